package simpview.scene.text;

/**
 * What a file that is not lines of UTF-8 text is, for a reader's message:
 * UTF-16 text (what Windows Notepad saves as "Unicode") or UTF-32, or no text at all
 * (a picture or a program renamed), named by its first byte that no text
 * holds and, when its first bytes say so, by what it looks like. A reader
 * asks only once a file failed to read or gave nothing, so a good file
 * costs nothing.
 *
 * @param line the line the problem is on (1 for UTF-16 and UTF-32: the whole file)
 * @param problem the words: what the file is, and what was expected
 */
public record NotText(int line, String problem) {

    /** The first bytes of a kind of file that is not text, and what such a file is. */
    private record Look(int[] start, String what) {
    }

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
     * The problem with the bytes b[from, to), which stand at {@code offset}
     * in the file and start on line {@code line}; null when they could be
     * lines of text. At offset 0 the first bytes are also looked at: UTF-16
     * or UTF-32 text, or the start of a known kind of file.
     *
     * @param kind what the file should be, "a SIMP file" or "an .obj file"
     */
    public static NotText find(byte[] b, int from, int to, long offset, int line, String kind) {
        if (offset == 0) {
            String utf32 = utf32(b, from, to);
            String utf16 = utf32 == null ? utf16(b, from, to) : null;
            if (utf32 != null || utf16 != null) {
                return new NotText(1, (utf32 != null ? "UTF-32 text, not UTF-8: " + utf32
                        : "UTF-16 text, not UTF-8: " + utf16) + "; " + kind
                        + " is read as UTF-8: save it as UTF-8 (in Notepad: Save As, Encoding UTF-8)");
            }
        }
        int at = line;
        for (int i = from; i < to; i++) {
            int v = b[i] & 0xFF;
            if (v == '\n') {
                at++;
            } else if (v < 0x20 && v != '\t' && v != '\r' && v != '\f' || v == 0x7F) {
                String looks = offset == 0 ? looksLike(b, from, to) : null;
                return new NotText(at, String.format("not a text file: byte 0x%02X at offset %d (line %d)", v,
                        offset + (i - from), at) + (looks == null ? "" : "; it looks like " + looks) + "; " + kind
                        + " is lines of text");
            }
        }
        return null;
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
