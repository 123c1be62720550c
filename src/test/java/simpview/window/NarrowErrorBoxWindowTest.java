package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.FontMetrics;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import simpview.scene.simp.SceneDrawer;

/**
 * The scene-error box in a window as narrow as it goes (320 pixels): its heading, "Scene error — the page shows
 * what was drawn before it (E hides this):", is broken into lines that each fit the box, every word of it shown,
 * not cut at the window's right edge.
 */
public class NarrowErrorBoxWindowTest extends WindowTestCase {

    @Test
    void atThreeHundredTwentyPixelsTheErrorBoxsHeadingWrapsWhole() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), SceneDrawer.SIMP);
        SimpviewWindow window = driver.window();
        PageView view = window.pageView();
        driver.onEdt(() -> {
            window.frame().setSize(320, 600);
            window.frame().validate();
        });
        driver.awaitEdt(() -> view.getWidth() > 0 && view.getWidth() <= 320, "the page laid out at the window's width");

        Path scene = dir.resolve("typo.simp");
        Files.writeString(scene, "polygon (-60, -60, -50) (60, -60, -50) (0, 60, -50)\npolygonx 1 2\n");
        driver.onEdt(() -> window.openScene(scene));
        driver.awaitEdt(() -> !window.busy() && view.error() != null, "the typo's error shown");
        driver.settle();
        driver.onEdt(() -> {
            List<String> lines = view.errorHeadingLines();
            FontMetrics metrics = view.getFontMetrics(ErrorOverlay.FONT);
            // the box is 10 pixels in from each side of the view, its text 10 pixels in from the box's
            int room = view.getWidth() - 40;
            assertTrue(lines.size() > 1, "the heading broken at " + view.getWidth() + " pixels: " + lines);
            for (String line : lines) {
                assertTrue(metrics.stringWidth(line) <= room, "'" + line + "' is " + metrics.stringWidth(line)
                        + " pixels wide in a box with " + room + " pixels for text: " + lines);
            }
            assertEquals(ErrorOverlay.HEADING, String.join(" ", lines), "the heading whole, line by line");
            return null;
        });
    }
}
