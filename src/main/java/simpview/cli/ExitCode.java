package simpview.cli;

/**
 * The exit codes of every simpview command, and its version line. The
 * commands return these; only {@link Main} ends the JVM with them.
 */
public final class ExitCode {

    /** Everything asked for was done (for compare and check: every picture passed). */
    public static final int OK = 0;
    /** A scene had an error, an output could not be written, or a comparison failed. */
    public static final int SCENE_ERROR = 1;
    /** The command line itself was wrong: an unknown option, a missing value, a bad pixel. */
    public static final int USAGE_ERROR = 2;
    /** What {@code --version} prints. */
    public static final String VERSION = "simpview 1.0";

    private ExitCode() {
    }
}
