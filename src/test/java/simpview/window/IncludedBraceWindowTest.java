package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * Under Xvfb: a student's included part, in a folder of its own, ends with its last '}' forgotten. The window's
 * status names that part's '{' and the '}' that closed it instead; the student adds the '}' to the part and
 * saves, and the window draws again with the warning gone.
 */
public class IncludedBraceWindowTest extends WindowTestCase {

    @Test
    void aBraceLeftOpenInAnIncludedPartIsNamedUntilThePartIsMended() throws Exception {
        Path parts = Files.createDirectory(dir.resolve("parts"));
        String part = "{\n  translate 30 0 0\n  polygon (-10, -10, 0) (10, -10, 0) (0, 10, 0)\n";
        Path open = Files.writeString(parts.resolve("open.simp"), part);
        Path scene = Files.writeString(dir.resolve("scene.simp"),
                "{\n  translate 0 0 -50\n  file \"parts/open\"\n}\npolygon (-60, -60, -20) (-40, -60, -20) (-50, -40, -20)\n");
        SimpviewWindow window = openWindowOn(scene);
        String named = "parts/open.simp:1: this '{' is still open at the end of parts/open.simp, so the '}' at"
                + " scene.simp:4 closes it";
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().contains(named),
                "the status to name the part's '{': " + driver.onEdt(() -> window.status().messageText()));
        assertEquals(2, driver.onEdt(() -> window.shown()).warnings().size(), "and the scene's '{' left open");

        Files.writeString(open, part + "}\n");
        driver.awaitEdt(() -> !window.busy() && !window.status().messageText().contains("'{'"),
                "the warning to go once the part is mended: " + driver.onEdt(() -> window.status().messageText()));
        assertTrue(driver.onEdt(() -> window.shown()).error() == null);
        assertEquals(0, driver.onEdt(() -> window.shown()).warnings().size());
    }
}
