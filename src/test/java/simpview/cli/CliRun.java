package simpview.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;

/** One in-process run of the command line: exit code and what it printed. */
public record CliRun(int exitCode, String out, String err) {

    static CliRun of(String... args) {
        return with(() -> false, args);
    }

    /** Runs with a display, or without one when {@code displayMissing} says so. */
    static CliRun with(BooleanSupplier displayMissing, String... args) {
        return run(new SimpviewCommand(displayMissing), args);
    }

    /** Runs with simpview's own scenes looked for in {@code ownScenes}, as a start from another folder would. */
    static CliRun withOwnScenes(Path ownScenes, String... args) {
        return run(new SimpviewCommand(() -> false, ownScenes), args);
    }

    private static CliRun run(SimpviewCommand command, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Main.execute(command, args, new PrintWriter(out), new PrintWriter(err));
        return new CliRun(code, out.toString(), err.toString());
    }

    /** A user error never shows a Java stack trace. */
    boolean showsStackTrace() {
        return err.contains("\tat ") || err.contains("Exception in thread") || out.contains("\tat ");
    }
}
