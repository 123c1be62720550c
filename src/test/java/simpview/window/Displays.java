package simpview.window;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.GraphicsEnvironment;

/** Whether the window tests can run here. */
public final class Displays {

    private Displays() {
    }

    /**
     * Skips the test, saying why, unless there is an X server to open windows
     * on; under CI=true, where the tests run under xvfb-run, fails instead.
     */
    static void assumeUsable() {
        if ("true".equalsIgnoreCase(System.getenv("CI")) && GraphicsEnvironment.isHeadless()) {
            fail("no display although CI=true: CI runs the tests under xvfb-run");
        }
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under xvfb-run");
        String failure = null;
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getDefaultScreenDevice();
        } catch (Error e) {
            failure = e.toString();
        }
        // A Gradle daemon keeps the environment of the session that started it,
        // so its tests may get a DISPLAY whose Xvfb is long gone.
        assumeTrue(failure == null, "DISPLAY=" + System.getenv("DISPLAY") + " cannot be reached (" + failure
                + "); if a Gradle daemon started in another session runs the tests, use gradle --no-daemon");
    }
}
