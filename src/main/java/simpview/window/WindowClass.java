package simpview.window;


import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.Toolkit;
import java.lang.reflect.Field;

/**
 * The class name of simpview's windows on X11 (their WM_CLASS property), by
 * which docks and taskbars group windows and name them: "simpview". The
 * JDK's X toolkit takes it from its static field {@code awtAppClassName},
 * which it fills with the name of the class at the bottom of the stack that
 * made the toolkit ("simpview-cli-Main", or a test runner's), and reads it
 * again for each window it makes. So it is set once the toolkit exists and
 * before the first window; {@code --add-opens
 * java.desktop/sun.awt.X11=ALL-UNNAMED} (given by the start scripts, the
 * jar's manifest, {@code gradle run} and the packaged program) lets it be
 * set. On another toolkit, or without that opening, nothing happens.
 */
public final class WindowClass {

    static final String NAME = "simpview";
    static final String X_TOOLKIT = "sun.awt.X11.XToolkit";
    private static final String FIELD = "awtAppClassName";

    private WindowClass() {
    }

    /**
     * Names the windows made from now on "simpview", when the toolkit is
     * X11's and lets itself be changed.
     *
     * @return true when set; false when not X11, headless, or the access refused
     */
    static boolean apply() {
        if (GraphicsEnvironment.isHeadless()) {
            return false;
        }
        Class<?> toolkit;
        try {
            toolkit = Toolkit.getDefaultToolkit().getClass();
        } catch (AWTError e) {
            return false;
        }
        if (!toolkit.getName().equals(X_TOOLKIT)) {
            return false;
        }
        try {
            Field field = toolkit.getDeclaredField(FIELD);
            field.setAccessible(true);
            field.set(null, NAME);
            return true;
        } catch (ReflectiveOperationException | RuntimeException e) {
            // Not opened to us (InaccessibleObjectException), or a JDK without the field: the name stays.
            return false;
        }
    }
}
