package simpview.window;

import org.junit.jupiter.api.parallel.Isolated;

import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SceneDrawer;
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

    @AfterEach
    void closeWindow() throws Exception {
        if (driver != null) {
            driver.close();
        }
    }
}
