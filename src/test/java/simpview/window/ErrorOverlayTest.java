package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

public class ErrorOverlayTest {

    @Test
    void aLongSourceLineWrapsWithTheCaretUnderTheRightCharacter() {
        String source = "polygon (1, 2, 3) (4, 5, 6) ".repeat(6) + "(7, 8, x)";
        int column = source.indexOf('x') + 1;
        String message = "scene.simp:4:" + column + ": expected a number, found 'x'\n    " + source + "\n    "
                + " ".repeat(column - 1) + "^";
        List<String> lines = ErrorOverlay.wrap(message, 60);
        int caretLine = -1;
        for (int i = 0; i < lines.size(); i++) {
            assertTrue(lines.get(i).length() <= 60, "line " + i + " too long: " + lines.get(i));
            if (lines.get(i).trim().equals("^")) {
                caretLine = i;
            }
        }
        assertTrue(caretLine > 0, "a caret line: " + lines);
        String above = lines.get(caretLine - 1);
        assertEquals('x', above.charAt(lines.get(caretLine).indexOf('^')), "caret under the x: " + lines);
        assertEquals(source, String.join("", lines.subList(1, lines.size()).stream()
                .filter(l -> !l.trim().equals("^")).map(l -> l.substring(4)).toList()), "the source line whole");
    }

    @Test
    void aShortMessageStaysAsItIs() {
        String message = "a.simp:1:1: unknown command\n    frob\n    ^";
        assertEquals(List.of("a.simp:1:1: unknown command", "    frob", "    ^"), ErrorOverlay.wrap(message, 60));
    }
}
