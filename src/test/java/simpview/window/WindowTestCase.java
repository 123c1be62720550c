package simpview.window;

import org.junit.jupiter.api.parallel.Isolated;

import java.awt.Point;
import java.awt.event.InputEvent;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SceneDrawer;
import simpview.surface.PageCanvas;
import simpview.testing.Images;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * What every test of the real window starts from: a display (skipped, or
 * under CI=true failed, without one), a folder of its own for files it
 * writes, and its window closed after it.
 */
@Isolated
public abstract class WindowTestCase {

    @TempDir
    Path dir;

    /** The window the test opened, if it opened one. */
    WindowDriver driver;

    @BeforeEach
    void needsADisplay() {
        Displays.assumeUsable();
    }

    /**
     * Opens the window (seed 361, this test's folder for its scenes), gives
     * it the keyboard on page 2, then opens {@code scene} in it and waits
     * until that is shown.
     */
    SimpviewWindow openWindowOn(Path scene) throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), SceneDrawer.SIMP);
        SimpviewWindow window = driver.window();
        driver.focusByClicking(new View.OfPage(2));
        driver.onEdt(() -> window.openScene(scene));
        driver.awaitShown(new View.OfScene(scene));
        return window;
    }

    /** A lit square in front of the camera, written to this test's folder: a scene that turns under a right-drag. */
    Path litSquare() throws IOException {
        return Files.writeString(dir.resolve("lit.simp"), String.join("\n", "ambient 0.3 0.3 0.3",
                "camera -1 -1 1 1 -1 -100", "light 1 1 1 1 0", "surface 0.9 0.5 0.1",
                "polygon (-30, -30, -40) (30, -30, -40) (30, 30, -40)",
                "polygon (-30, -30, -40) (30, 30, -40) (-30, 30, -40)", ""));
    }

    /** What a test does while the right button is held, given the drag's first frame on screen. */
    interface WhileHeld {
        void run(RenderedView firstFrame) throws Exception;
    }

    /**
     * Presses the right button at the page's centre and drags a little, waits for a frame of the drag (untraced,
     * turned away from {@code unturned}), runs {@code whileHeld}, and lets go, also when it fails.
     */
    void dragTurning(RenderedView unturned, WhileHeld whileHeld) throws Exception {
        SimpviewWindow window = driver.window();
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.robot().mouseMove(centre.x, centre.y);
        driver.robot().mousePress(InputEvent.BUTTON3_DOWN_MASK);
        try {
            for (int k = 1; k <= 4; k++) {
                driver.robot().mouseMove(centre.x + 10 * k, centre.y + 2 * k);
            }
            driver.awaitEdt(() -> !window.busy() && window.shown().facts().owners() == null
                    && Images.differingPixels(unturned.image(), window.shown().image()) > 100, "a frame of the drag");
            whileHeld.run(driver.onEdt(() -> window.shown()));
        } finally {
            driver.robot().mouseRelease(InputEvent.BUTTON3_DOWN_MASK);
        }
    }

    /** While {@link #dragTurning}: drags on, and returns the next frame once it is on screen in place of {@code last}. */
    RenderedView nextDragFrame(RenderedView last) throws Exception {
        SimpviewWindow window = driver.window();
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.robot().mouseMove(centre.x + 70, centre.y + 14);
        driver.awaitEdt(() -> !window.busy() && window.shown() != last, "another frame of the drag");
        return driver.onEdt(() -> window.shown());
    }

    @AfterEach
    void closeWindow() throws Exception {
        if (driver != null) {
            driver.close();
        }
    }
}
