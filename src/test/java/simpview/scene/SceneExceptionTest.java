package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** How an error shows its line: whole, with the caret under the column; a long one around the caret. */
class SceneExceptionTest {

    private static final Path FILE = Path.of("s.simp");

    @Test
    void aShortLineIsShownWholeWithTheCaretUnderTheColumn() {
        SceneException e = new SceneException(FILE, 3, 7, "scale\t1 x 3", "expected a number, found 'x'");
        assertEquals("s.simp:3:7: expected a number, found 'x'\n    scale 1 x 3\n          ^", e.getMessage());
    }

    /** A line of 100,000 characters (a generated file) made a message of 200 KB: now 120 of them, cut ends marked. */
    @Test
    void aLongLineIsShownAroundTheCaret() {
        String line = "polygon " + "1 ".repeat(50_000) + "x";
        int column = line.length();
        String[] shown = new SceneException(FILE, 1, column, line, "expected a number, found 'x'").getMessage().split("\n");
        assertEquals(3, shown.length);
        assertEquals("    …" + line.substring(line.length() - 120), shown[1]);
        assertEquals(shown[1].length() - 1, shown[2].indexOf('^'), "the caret under the x");
        String start = new SceneException(FILE, 1, 1, line, "p").getMessage().split("\n")[1];
        assertEquals("    " + line.substring(0, 120) + "…", start);
        String middle = new SceneException(FILE, 1, 50_001, line, "p").getMessage();
        String[] parts = middle.split("\n");
        assertEquals(line.charAt(50_000), parts[1].charAt(parts[2].indexOf('^')), "the caret under its character");
        assertEquals(4 + 1 + 120 + 1, parts[1].length(), "both ends cut");
    }

    /** render --scenes . named its scenes ./bad.simp: the "." parts are left out, the file is the same. */
    @Test
    void theFileIsNamedWithoutItsDotParts() {
        Path file = Path.of(".").resolve("bad.simp");
        SceneException e = new SceneException(file, 1, 6, "line (0,0,-10", "expected a number");
        assertEquals("bad.simp:1:6: expected a number\n    line (0,0,-10\n         ^", e.getMessage());
        assertEquals(file, e.file(), "the file as it was read");
    }
}
