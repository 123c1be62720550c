package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.SceneException;

/**
 * A file that is not UTF-8 text, saved or renamed .obj: an error that says
 * what it looks like and what is expected, on the line of its first byte
 * that no text holds (1 for UTF-16), and shows none of its bytes.
 */
class ObjNotTextTest {

    private static final String MODEL = "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n";
    private static final String SAVE_AS_UTF8 = "; an .obj file is read as UTF-8: save it as UTF-8 (in Notepad: Save As,"
            + " Encoding UTF-8)";

    @TempDir
    Path dir;

    /** The error streaming the file gives, the same as reading its bytes from memory gives. */
    private SceneException fails(byte[] bytes) throws IOException {
        Path file = Files.write(dir.resolve("model.obj"), bytes);
        SceneException fromFile = assertThrows(SceneException.class, () -> ObjReader.stream(file, face -> { }));
        SceneException inMemory = assertThrows(SceneException.class,
                () -> ObjReader.stream(file, bytes, face -> { }));
        assertEquals(fromFile.getMessage(), inMemory.getMessage());
        assertEquals("", fromFile.lineText(), "no byte of it is shown");
        assertTrue(fromFile.column() >= 1, "a column, for an editor to go to: " + fromFile.getMessage());
        assertTrue(fromFile.getMessage().startsWith(file + ":" + fromFile.line() + ":" + fromFile.column() + ": "),
                fromFile.getMessage());
        return fromFile;
    }

    private SceneException fails(String text, Charset charset) throws IOException {
        return fails(text.getBytes(charset));
    }

    @Test
    void notepadsUnicodeIsNamed() throws IOException {
        SceneException e = fails("\uFEFF" + MODEL, StandardCharsets.UTF_16LE);
        assertEquals("UTF-16 text, not UTF-8: it starts with the bytes FF FE, as Windows Notepad saves \"Unicode\""
                + SAVE_AS_UTF8, e.problem());
        assertEquals(1, e.line());
    }

    @Test
    void bigEndianUtf16IsNamed() throws IOException {
        assertEquals("UTF-16 text, not UTF-8: it starts with the bytes FE FF" + SAVE_AS_UTF8,
                fails(MODEL, StandardCharsets.UTF_16).problem());
    }

    @Test
    void utf16WithoutAByteOrderMarkIsNamed() throws IOException {
        assertEquals("UTF-16 text, not UTF-8: every second one of its first bytes is 0" + SAVE_AS_UTF8,
                fails(MODEL, StandardCharsets.UTF_16LE).problem());
        assertEquals("UTF-16 text, not UTF-8: every second one of its first bytes is 0" + SAVE_AS_UTF8,
                fails(MODEL, StandardCharsets.UTF_16BE).problem());
    }

    /** UTF-32 is named as itself, not as the UTF-16 its little-endian mark starts like. */
    @Test
    void utf32IsNamed() throws IOException {
        Charset le = Charset.forName("UTF-32LE");
        Charset be = Charset.forName("UTF-32BE");
        assertEquals("UTF-32 text, not UTF-8: it starts with the bytes FF FE 00 00" + SAVE_AS_UTF8,
                fails("\uFEFF" + MODEL, le).problem());
        assertEquals("UTF-32 text, not UTF-8: it starts with the bytes 00 00 FE FF" + SAVE_AS_UTF8,
                fails("\uFEFF" + MODEL, be).problem());
        assertEquals("UTF-32 text, not UTF-8: three of every four of its first bytes are 0" + SAVE_AS_UTF8,
                fails(MODEL, le).problem());
        assertEquals("UTF-32 text, not UTF-8: three of every four of its first bytes are 0" + SAVE_AS_UTF8,
                fails(MODEL, be).problem());
        assertEquals(1, fails(MODEL, be).line());
    }

    /** A picture renamed .obj: its first byte that no UTF-8 text holds, placed, and what its first bytes say it is. */
    @Test
    void aPictureRenamedObjIsNamed() throws IOException {
        byte[] png = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
        SceneException e = fails(png);
        assertEquals("not a text file: byte 0x89 at offset 0 (line 1); it looks like a PNG picture; an .obj file is"
                + " lines of text", e.problem());
        assertEquals(1, e.line());
        assertEquals("not a text file: byte 0x00 at offset 4 (line 1); an .obj file is lines of text",
                fails(new byte[] {'a', 'b', 'c', 'd', 0, 1, 2}).problem());
    }

    /**
     * The byte's column counts the characters before it on its line, a
     * character of two, three or four bytes as one, as every other error's
     * column counts; UTF-16 text, wrong from its first byte, is at 1:1.
     */
    @Test
    void theByteIsPlacedAtItsColumn() throws IOException {
        SceneException e = fails("v 0 0 0\n# \u00e9\u20ac\uD83D\uDE00\u0001\nf 1 2 3\n", StandardCharsets.UTF_8);
        assertEquals(2, e.line());
        assertEquals(6, e.column());
        SceneException utf16 = fails("\uFEFF" + MODEL, StandardCharsets.UTF_16LE);
        assertEquals(1, utf16.line());
        assertEquals(1, utf16.column());
    }

    /** A line of a v or f that fails, in a file that is not text, says that rather than what the line lacks. */
    @Test
    void aLineThatFailsInAFileThatIsNotTextSaysSo() throws IOException {
        assertEquals("not a text file: byte 0x01 at offset 10 (line 2); an .obj file is lines of text",
                fails("v 0 0 0\nv \u0001 1 0 0\n", StandardCharsets.US_ASCII).problem());
        byte[] elf = "\u007FELF\u0002\nf 1 2 3\n".getBytes(StandardCharsets.US_ASCII);
        assertEquals("not a text file: byte 0x7F at offset 0 (line 1); it looks like a program (ELF); an .obj file is"
                + " lines of text", fails(elf).problem());
    }

    /** Latin-1 in a comment of a model that draws is not UTF-8 text either (docs/simp.md), as in a scene. */
    @Test
    void latin1InACommentIsNotUtf8() throws IOException {
        SceneException e = fails(("v 0 0 0\nv 1 0 0\nv 0 1 0\n# caf\u00e9\nf 1 2 3\n").getBytes(StandardCharsets.ISO_8859_1));
        assertEquals("not UTF-8 text: byte 0xE9 at offset 29 (line 4) starts or continues no UTF-8 character; it looks"
                + " like text saved as Latin-1 or Windows-1252, where that byte is '\u00e9'" + SAVE_AS_UTF8, e.problem());
        assertEquals(4, e.line());
        assertEquals(6, e.column(), "after the five characters '# caf'");
        // a continuation byte alone, an overlong '/', a surrogate and a cut character are no UTF-8 either
        for (byte[] bad : new byte[][] {{'#', (byte) 0x80}, {'#', (byte) 0xC0, (byte) 0xAF}, {'#', (byte) 0xED,
                (byte) 0xA0, (byte) 0x80}, {'#', (byte) 0xE2, (byte) 0x88}}) {
            assertTrue(fails(bad).problem().startsWith("not UTF-8 text: byte 0x"), fails(bad).problem());
        }
    }

    /**
     * A byte that starts a character followed by one that continues it is
     * malformed UTF-8, not Latin-1: an overlong '/', a surrogate, a code
     * point beyond U+10FFFF and a character cut short are told so, not that
     * the byte is a Latin-1 letter ('í' for 0xED).
     */
    @Test
    void malformedUtf8IsNotTakenForLatin1() throws IOException {
        String malformed = " are malformed UTF-8 (a character cut short, an overlong form, a surrogate or one beyond"
                + " U+10FFFF), not text in another encoding" + SAVE_AS_UTF8;
        assertEquals("not UTF-8 text: byte 0xC0 at offset 1 (line 1) and the byte 0xAF after it" + malformed,
                fails(new byte[] {'#', (byte) 0xC0, (byte) 0xAF, '\n'}).problem());
        assertEquals("not UTF-8 text: byte 0xED at offset 1 (line 1) and the byte 0xA0 after it" + malformed,
                fails(new byte[] {'#', (byte) 0xED, (byte) 0xA0, (byte) 0x80, '\n'}).problem());
        assertEquals("not UTF-8 text: byte 0xF4 at offset 1 (line 1) and the byte 0x90 after it" + malformed,
                fails(new byte[] {'#', (byte) 0xF4, (byte) 0x90, (byte) 0x80, (byte) 0x80, '\n'}).problem());
        assertEquals("not UTF-8 text: byte 0xE2 at offset 1 (line 1) and the byte 0x88 after it" + malformed,
                fails(new byte[] {'#', (byte) 0xE2, (byte) 0x88, ' ', '\n'}).problem());
        // a Latin-1 letter before a space or a letter is still told it may be Latin-1
        assertTrue(fails(new byte[] {'#', 'p', (byte) 0xED, 'x', '\n'}).problem().contains("where that byte is"
                + " '\u00ed'"));
    }

    @Test
    void aTextModelWithAnErrorIsNotTakenForAnything() throws IOException {
        Path file = Files.writeString(dir.resolve("model.obj"), "# caf\u00e9\nv 0 0 0\nf 1 2 3\n");
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.stream(file, face -> { }));
        assertEquals("vertex index 2 names nothing: 1 vertex (v line) defined so far", e.problem());
    }
}
