package simpview.window;

import org.junit.jupiter.api.parallel.Isolated;

import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

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

    @AfterEach
    void closeWindow() throws Exception {
        if (driver != null) {
            driver.close();
        }
    }
}
