package simpview.app;

import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import picocli.CommandLine;

/**
 * Entry point: {@code simpview} opens the window, {@code simpview render ...}
 * writes PNG files. Exit codes: 0 success, 1 scene error (or an output that
 * cannot be written), 2 usage error.
 */
public final class Main {

    public static final int OK = 0;
    public static final int SCENE_ERROR = 1;
    public static final int USAGE_ERROR = 2;
    static final String VERSION = "simpview 1.0";

    private Main() {
    }

    public static void main(String[] args) {
        PrintWriter out = new PrintWriter(System.out, true, StandardCharsets.UTF_8);
        PrintWriter err = new PrintWriter(System.err, true, StandardCharsets.UTF_8);
        SimpviewCommand command = new SimpviewCommand(SimpviewCommand::displayMissing);
        int code = execute(command, args, out, err);
        // An open window keeps the program alive; it ends when the window closes.
        if (!command.openedWindow()) {
            System.exit(code);
        }
    }

    /** Runs one command line in-process and returns its exit code (never exits the JVM). */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return execute(new SimpviewCommand(SimpviewCommand::displayMissing), args, out, err);
    }

    static int execute(SimpviewCommand command, String[] args, PrintWriter out, PrintWriter err) {
        CommandLine commandLine = new CommandLine(command)
                .setOut(out)
                .setErr(err)
                .setExecutionExceptionHandler(Main::reportUnexpected)
                .setParameterExceptionHandler(Main::reportUsageError);
        // picocli's own exit code for invalid input is already USAGE_ERROR (2).
        int code = commandLine.execute(args);
        out.flush();
        err.flush();
        return code;
    }

    /** A usage error: the problem, a suggestion when a word was mistyped, and one line pointing at --help. */
    private static int reportUsageError(CommandLine.ParameterException e, String[] args) {
        CommandLine commandLine = e.getCommandLine();
        PrintWriter err = commandLine.getErr();
        err.println("simpview: " + e.getMessage());
        if (e instanceof CommandLine.UnmatchedArgumentException unmatched) {
            for (String word : unmatched.getUnmatched()) {
                java.util.Set<String> known = new java.util.TreeSet<>(commandLine.getCommandSpec().optionsMap().keySet());
                known.addAll(commandLine.getSubcommands().keySet());
                simpview.scene.Nearest.to(word, known).ifPresent(near -> err.println("Did you mean '" + near + "' for '" + word + "'?"));
            }
        }
        err.println("See '" + commandLine.getCommandSpec().qualifiedName() + " --help' for how to use it.");
        err.flush();
        return USAGE_ERROR;
    }

    /**
     * User errors are caught where they happen and reported in one message;
     * anything reaching here is a bug, so the trace is worth showing.
     */
    private static int reportUnexpected(Exception e, CommandLine commandLine, CommandLine.ParseResult parsed) {
        PrintWriter err = commandLine.getErr();
        err.println("simpview: internal error: " + e);
        e.printStackTrace(err);
        return SCENE_ERROR;
    }
}
