package simpview.cli;

import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicBoolean;
import picocli.CommandLine;
import simpview.pages.PageContext;
import simpview.scene.MemoryAdvice;
import simpview.scene.Nearest;

/**
 * Entry point: {@code simpview} opens the window, {@code simpview render ...}
 * writes PNG files. Exit codes: 0 success, 1 scene error (or an output that
 * cannot be written), 2 usage error ({@link ExitCode}).
 */
public final class Main {

    /** The whole argument line of {@code gradle run -PappArgs="..."}, split here as a shell would. */
    static final String APP_ARGS = "simpview.appArgs";

    private Main() {
    }

    /**
     * Runs the command line and exits the JVM with its exit code, unless it opened the window, which keeps the
     * program until it is closed. For use from Java, {@link #run} returns the code instead.
     */
    public static void main(String[] args) {
        PrintWriter out = new PrintWriter(System.out, true, StandardCharsets.UTF_8);
        PrintWriter err = new PrintWriter(System.err, true, StandardCharsets.UTF_8);
        Path ownScenes = OwnScenes.folder();
        String[] line;
        try {
            line = withAppArgs(System.getProperty(APP_ARGS), args);
        } catch (IllegalArgumentException e) {
            err.println("simpview: -PappArgs: " + e.getMessage());
            System.exit(ExitCode.USAGE_ERROR);
            return;
        }
        SimpviewCommand command = new SimpviewCommand(SimpviewCommand::displayMissing, ownScenes);
        int code = execute(command, line, out, err);
        // An open window keeps the program alive; it ends when the window closes.
        if (!command.openedWindow()) {
            System.exit(code);
        }
    }

    /**
     * Runs one command line in-process and returns its exit code ({@link ExitCode}); never exits the JVM.
     * Its output and messages go to {@code out} and {@code err}. A line that opens the window (no command, or
     * scenes alone) returns once it is open, and the window keeps the JVM running until it is closed; without
     * a display that is a message on {@code err} and exit code 2.
     */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return execute(new SimpviewCommand(SimpviewCommand::displayMissing), args, out, err);
    }

    /**
     * The arguments simpview runs with: those of -Dsimpview.appArgs (one line,
     * split as a shell would, so quoted paths stay whole), then the program's own.
     *
     * @throws IllegalArgumentException when a quote of the line is never closed
     */
    static String[] withAppArgs(String appArgs, String[] args) {
        if (appArgs == null) {
            return args;
        }
        List<String> all = new ArrayList<>(ArgumentLine.split(appArgs));
        all.addAll(List.of(args));
        return all.toArray(String[]::new);
    }

    static int execute(SimpviewCommand command, String[] args, PrintWriter out, PrintWriter err) {
        // Whether the line was parsed and its command run: a usage error before that never reached the command,
        // which releases its outputs itself once it runs.
        AtomicBoolean ran = new AtomicBoolean();
        CommandLine commandLine = new CommandLine(command)
                .setOut(out)
                .setErr(err)
                .setExecutionStrategy(parsed -> {
                    SimpviewCommand.refuseOptionsBeforeCommand(parsed);
                    ran.set(true);
                    return new CommandLine.RunLast().execute(parsed);
                })
                .setExecutionExceptionHandler(Main::reportUnexpected)
                .setParameterExceptionHandler((e, words) -> {
                    if (!ran.get()) {
                        // a FIFO named as an output would leave its reader waiting for ever
                        NamedOutputs.release(e.getCommandLine(), NamedOutputs.expanded(e.getCommandLine(), words));
                    }
                    return reportUsageError(e, words);
                });
        sayWhereTheScenesAre(commandLine, command.ownScenes());
        // Every subcommand SimpviewCommand lists (a set: an alias would name one twice).
        for (CommandLine sub : new LinkedHashSet<>(commandLine.getSubcommands().values())) {
            sayWhereTheScenesAre(sub, command.ownScenes());
        }
        // picocli's own exit code for invalid input is already ExitCode.USAGE_ERROR (2).
        int code;
        try {
            code = commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            // A scene or model ran out where it is read or drawn, and said where; this is anything else.
            err.println("simpview: " + MemoryAdvice.outOfMemory("running this command"));
            code = ExitCode.SCENE_ERROR;
        }
        out.flush();
        err.flush();
        return code;
    }

    /** A usage error: the problem, a suggestion when a word was mistyped, and one line pointing at --help. */
    private static int reportUsageError(CommandLine.ParameterException e, String[] args) {
        CommandLine commandLine = e.getCommandLine();
        PrintWriter err = commandLine.getErr();
        err.println("simpview: " + UsageWords.of(e, commandLine.getCommandSpec().qualifiedName()));
        if (commandLine.getParent() == null && args != null) {
            // a slip in the command's name: its options were read as the window's
            for (String word : args) {
                Optional<String> meant = SimpviewCommand.mistypedCommand(word, commandLine.getSubcommands().keySet());
                if (meant.isPresent()) {
                    err.println("Did you mean 'simpview " + meant.get() + "' for '" + word + "'?");
                    break;
                }
            }
        }
        if (e instanceof CommandLine.UnmatchedArgumentException unmatched) {
            for (String word : unmatched.getUnmatched()) {
                Set<String> known = new TreeSet<>(commandLine.getCommandSpec().optionsMap().keySet());
                known.addAll(commandLine.getSubcommands().keySet());
                Nearest.to(word, known).ifPresent(near -> err.println("Did you mean '" + near + "' for '" + word + "'?"));
            }
        }
        err.println("See '" + commandLine.getCommandSpec().qualifiedName() + " --help' for how to use it.");
        err.flush();
        return ExitCode.USAGE_ERROR;
    }

    /** Ends --help with the scene folder the defaults really read, as an absolute path. */
    private static void sayWhereTheScenesAre(CommandLine commandLine, Path ownScenes) {
        String folder = ownScenes.toAbsolutePath().normalize().toString().replace("%", "%%");
        List<String> footer = new ArrayList<>(List.of(commandLine.getCommandSpec().usageMessage().footer()));
        footer.add("");
        footer.add("Scene folder: " + folder);
        footer.add("  pages 4 and 5 come from there; pages 6 to 8 too, unless --simp-dir D");
        footer.add("  names the folder of the course's page6.simp to page8.simp.");
        commandLine.getCommandSpec().usageMessage().footer(footer.toArray(String[]::new));
    }

    /**
     * User errors are caught where they happen and reported in one message
     * (a {@link UsageProblem} as a usage error); anything else reaching here
     * is a bug, so the trace is worth showing.
     */
    private static int reportUnexpected(Exception e, CommandLine commandLine, CommandLine.ParseResult parsed) {
        if (e instanceof UsageProblem problem) {
            return reportUsageError(new CommandLine.ParameterException(commandLine, problem.getMessage()), null);
        }
        PrintWriter err = commandLine.getErr();
        err.println("simpview: internal error: " + e);
        e.printStackTrace(err);
        return ExitCode.SCENE_ERROR;
    }
}
