package simpview.scene.text;

import java.nio.charset.Charset;

/**
 * What a file that is not lines of UTF-8 text is, for a reader's message:
 * UTF-16 text (what Windows Notepad saves as "Unicode") or UTF-32, text in
 * another encoding (Latin-1), or no text at all (a picture or a program
 * renamed), named by its first byte that no UTF-8 text holds and, when its
 * bytes say so, by what it looks like. The SIMP and .obj readers both meet
 * that byte as {@link LineSource} reads the lines, so a scene and a model
 * are checked alike, every line of them, comments included.
 *
 * @param line the line the problem is on (1 for UTF-16 and UTF-32: the whole file)
 * @param column the column of the byte on its line, 1-based (1 for UTF-16 and UTF-32: the file's start)
 * @param problem the words: what the file is, and what was expected
 */
public record NotText(int line, int column, String problem) {

    /** The first bytes of a kind of file that is not text, and what such a file is. */
    private record Look(int[] start, String what) {
    }

    /** What a file of text in another encoding is told to do. */
    private static final String SAVE_AS_UTF8 = "; %s is read as UTF-8: save it as UTF-8 (in Notepad: Save As,"
            + " Encoding UTF-8)";

    private static final Look[] LOOKS = {
        new Look(new int[] {0x89, 'P', 'N', 'G'}, "a PNG picture"),
        new Look(new int[] {0xFF, 0xD8, 0xFF}, "a JPEG picture"),
        new Look(new int[] {'G', 'I', 'F', '8'}, "a GIF picture"),
        new Look(new int[] {'P', 'K', 3, 4}, "a ZIP archive (a .zip, .docx or .jar file)"),
        new Look(new int[] {'%', 'P', 'D', 'F'}, "a PDF document"),
        new Look(new int[] {0x7F, 'E', 'L', 'F'}, "a program (ELF)"),
        new Look(new int[] {'M', 'Z'}, "a Windows program"),
        new Look(new int[] {0xCA, 0xFE, 0xBA, 0xBE}, "a Java class file"),
    };

    /**
     * The problem with a file whose byte at {@code offset}, on line
     * {@code line} and in its column {@code column}, is {@code value}, the first that no UTF-8 text holds
     * ({@link LineSource} finds it as it reads): UTF-16 or UTF-32 text, when
     * the file's first bytes ({@code head}) show it; else that byte, and what
     * the file looks like: a known kind of file by its first bytes, or text
     * saved in Latin-1 or Windows-1252 when the byte is a letter there and
     * the byte after it ({@code next}, -1 when none) does not continue it as
     * UTF-8 would: a byte that starts a character followed by one that
     * continues it is malformed UTF-8 (a character cut short, an overlong
     * form, a surrogate, a code point beyond U+10FFFF), which Latin-1 text
     * hardly ever holds.
     *
     * @param kind what the file should be, "a SIMP file" or "an .obj file"
     */
    public static NotText of(byte[] head, long offset, int line, int column, int value, int next, String kind) {
        String utf32 = utf32(head, 0, head.length);
        String utf16 = utf32 == null ? utf16(head, 0, head.length) : null;
        if (utf32 != null || utf16 != null) {
            return new NotText(1, 1, (utf32 != null ? "UTF-32 text, not UTF-8: " + utf32
                    : "UTF-16 text, not UTF-8: " + utf16) + SAVE_AS_UTF8.formatted(kind));
        }
        String byteAt = String.format("byte 0x%02X at offset %d (line %d)", value, offset, line);
        String looks = looksLike(head, 0, head.length);
        if (looks != null || value < 0x80) {
            return new NotText(line, column, "not a text file: " + byteAt + (looks == null ? "" : "; it looks like " + looks)
                    + "; " + kind + " is lines of text");
        }
        if (value >= 0xC0 && next >= 0x80 && next <= 0xBF) {
            // ED A0 80, C0 AF, F4 90 ...: bytes made as UTF-8 is made, by a program that made it wrongly
            return new NotText(line, column, "not UTF-8 text: " + byteAt + String.format(" and the byte 0x%02X after it are"
                    + " malformed UTF-8 (a character cut short, an overlong form, a surrogate or one beyond"
                    + " U+10FFFF), not text in another encoding", next) + SAVE_AS_UTF8.formatted(kind));
        }
        String latin = latin1(value);
        return new NotText(line, column, "not UTF-8 text: " + byteAt + " starts or continues no UTF-8 character"
                + (latin == null ? "" : "; it looks like text saved as Latin-1 or Windows-1252, where that byte is '"
                + latin + "'") + SAVE_AS_UTF8.formatted(kind));
    }

    /** The character byte {@code value} (0x80 up) is in Windows-1252 (Latin-1's superset), when it is a letter or sign; else null. */
    private static String latin1(int value) {
        String c = new String(new byte[] {(byte) value}, Charset.forName("windows-1252"));
        return c.length() == 1 && c.charAt(0) != '\uFFFD' && !Character.isISOControl(c.charAt(0))
                && !Character.isSpaceChar(c.charAt(0)) ? c : null;
    }

    /**
     * How b[from, to), a file's first bytes, show UTF-32 text (four bytes a character); null when they do not.
     * Asked before UTF-16: little-endian UTF-32's mark, FF FE 00 00, starts as UTF-16's does.
     */
    private static String utf32(byte[] b, int from, int to) {
        if (startsWith(b, from, to, 0xFF, 0xFE, 0, 0)) {
            return "it starts with the bytes FF FE 00 00";
        }
        if (startsWith(b, from, to, 0, 0, 0xFE, 0xFF)) {
            return "it starts with the bytes 00 00 FE FF";
        }
        return asciiInUnits(b, from, to, 4, 16) ? "three of every four of its first bytes are 0" : null;
    }

    /** How b[from, to), a file's first bytes, show UTF-16 text; null when they do not. */
    private static String utf16(byte[] b, int from, int to) {
        if (startsWith(b, from, to, 0xFF, 0xFE)) {
            return "it starts with the bytes FF FE, as Windows Notepad saves \"Unicode\"";
        }
        if (startsWith(b, from, to, 0xFE, 0xFF)) {
            return "it starts with the bytes FE FF";
        }
        return asciiInUnits(b, from, to, 2, 32) ? "every second one of its first bytes is 0" : null;
    }

    /**
     * Whether the first characters of b[from, to) (at least two, at most {@code most}), each {@code unit} bytes,
     * are all plain text in little- or big-endian order: one byte not 0 at the character's low end, the others 0.
     */
    private static boolean asciiInUnits(byte[] b, int from, int to, int unit, int most) {
        int characters = Math.min(most, (to - from) / unit);
        if (characters < 2) {
            return false;
        }
        boolean little = true;
        boolean big = true;
        for (int k = 0; k < characters; k++) {
            int at = from + unit * k;
            boolean middleZero = true;
            for (int i = 1; i < unit - 1; i++) {
                middleZero &= b[at + i] == 0;
            }
            little &= middleZero && b[at] != 0 && b[at + unit - 1] == 0;
            big &= middleZero && b[at] == 0 && b[at + unit - 1] != 0;
        }
        return little || big;
    }

    /** Whether b[from, to) starts with the bytes {@code start}. */
    private static boolean startsWith(byte[] b, int from, int to, int... start) {
        boolean same = to - from >= start.length;
        for (int k = 0; same && k < start.length; k++) {
            same = (b[from + k] & 0xFF) == start[k];
        }
        return same;
    }

    /** What a file starting with b[from, to) is, when its first bytes are those of a known kind; else null. */
    private static String looksLike(byte[] b, int from, int to) {
        for (Look look : LOOKS) {
            if (startsWith(b, from, to, look.start())) {
                return look.what();
            }
        }
        return null;
    }
}
