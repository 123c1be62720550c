package simpview.cli;

import simpview.window.SimpviewWindow;
import simpview.window.WindowOptions;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;
import javax.swing.SwingUtilities;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.Spec;
import simpview.pages.PageContext;
import simpview.pages.SceneList;
import simpview.scene.Nearest;

/** {@code simpview [--seed S] [--simp-dir D] [SCENE]}: opens the window. */
@Command(name = "simpview",
        mixinStandardHelpOptions = true,
        version = ExitCode.VERSION,
        subcommands = {RenderCommand.class, CompareCommand.class, CheckCommand.class, InspectCommand.class},
        description = {
            "Shows the course's pages in a window, the second assignment's eight first;",
            "click or press Right for the next page, Alt+1 to Alt+4 for each assignment's",
            "pages, F1 for every key.",
            "Use 'simpview render' to write pages as PNG files without a window,",
            "'simpview compare' to see how close a picture is to simpview's,",
            "and 'simpview check DIR' to check a folder of your pages before handing them in."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:scene error, or an output file that cannot be written", "2:usage error"})
public final class SimpviewCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Mixin
    private ThreadsOption threads;

    @Mixin
    private A1RuleOption a1Rule;

    @Option(names = "--seed", paramLabel = "S", description = PageDrawing.SEED_HELP + " (default: ${DEFAULT-VALUE})")
    private long seed = PageContext.DEFAULT_SEED;

    @Option(names = "--simp-dir", paramLabel = "D", description = "folder holding the course's page6.simp to page8.simp (default: the scene folder below)")
    private Path simpDir;

    @Parameters(arity = "0..*", paramLabel = "SCENE",
            description = "a .simp scene to open at start, outside the pages' cycle (Right goes on to page 2, as "
                    + "from page 1, and no page key comes back to it); several scenes, or a folder of them, become the "
                    + "window's first pages, in the order given (a folder: natural name order)")
    private List<Path> scenes = new ArrayList<>();

    private final BooleanSupplier displayMissing;
    /** Where the project's own scenes are, as the entry point found them ({@link OwnScenes}). */
    private final Path ownScenes;
    private boolean openedWindow;

    /** Run from the repository's folder: the project's scenes in simp/. */
    SimpviewCommand(BooleanSupplier displayMissing) {
        this(displayMissing, PageContext.PROJECT_SCENES);
    }

    SimpviewCommand(BooleanSupplier displayMissing, Path ownScenes) {
        this.displayMissing = displayMissing;
        this.ownScenes = ownScenes;
    }

    /** Where the project's own scenes are: what the subcommands' pages read too. */
    Path ownScenes() {
        return ownScenes;
    }

    /** No display, or one that cannot be reached (a DISPLAY whose X server is gone). */
    static boolean displayMissing() {
        if (GraphicsEnvironment.isHeadless()) {
            return true;
        }
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getDefaultScreenDevice();
            return false;
        } catch (AWTError e) {
            return true;
        }
    }

    /** One scene file named alone: the window opens on it as an extra view, as before. */
    private Optional<Path> openAtStart() {
        return scenes.size() == 1 && !Files.isDirectory(scenes.get(0)) ? Optional.of(scenes.get(0)) : Optional.empty();
    }

    /** Several scenes or a folder: the window's first pages; a usage error when one names no scene. */
    private List<Path> sceneList() {
        if (openAtStart().isPresent() || scenes.isEmpty()) {
            return List.of();
        }
        try {
            return SceneList.of(scenes);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    /** True once the window was asked to open: then the program lives until it closes. */
    boolean openedWindow() {
        return openedWindow;
    }

    /**
     * Refuses the window's options given before a command ({@code simpview --seed 5 render ...}): they are the
     * window's, the command reads its own, and it would draw with its defaults without a word (seed 361, page 6
     * away from the --simp-dir given). Says where each goes: after the command, or nowhere when the command has
     * no such option. Help and version are the window's to give wherever they stand.
     *
     * @throws ParameterException of the command, so that its --help is the one pointed to
     */
    static void refuseOptionsBeforeCommand(ParseResult parsed) {
        ParseResult command = parsed.subcommand();
        if (command == null) {
            return;
        }
        List<OptionSpec> before = parsed.matchedOptions().stream()
                .filter(option -> !option.usageHelp() && !option.versionHelp()).toList();
        if (before.isEmpty()) {
            return;
        }
        String name = command.commandSpec().name();
        List<String> names = before.stream().map(OptionSpec::longestName).toList();
        List<String> itsOwn = names.stream().filter(option -> command.commandSpec().findOption(option) != null)
                .toList();
        List<String> notItsOwn = names.stream().filter(option -> !itsOwn.contains(option)).toList();
        boolean one = names.size() == 1;
        String words = UsageWords.joined(names, "and") + (one ? " is" : " are") + " given before '" + name
                + "', where " + (one ? "it is the window's option" : "they are the window's options") + " and "
                + name + " does not read " + (one ? "it" : "them") + ": ";
        List<String> where = new ArrayList<>();
        if (!itsOwn.isEmpty()) {
            where.add("give " + UsageWords.joined(itsOwn, "and") + " after '" + name + "' (simpview " + name + " "
                    + String.join(" ... ", itsOwn) + " ...)");
        }
        if (!notItsOwn.isEmpty()) {
            where.add(name + " has no " + UsageWords.joined(notItsOwn, "or"));
        }
        throw new ParameterException(command.commandSpec().commandLine(), words + String.join("; ", where));
    }

    /**
     * The command {@code word} is a slip for ("comapre": "compare"), when it
     * names no file or folder (with .simp or without) and is near one.
     */
    static Optional<String> mistypedCommand(String word, Collection<String> commands) {
        return bareWordNamingNothing(word) ? Nearest.to(word, commands) : Optional.empty();
    }

    /**
     * True for a word with no folder, extension or option dash in it that
     * names no file or folder, with .simp or without: a command's name
     * (mistyped or guessed, "window"), not a scene.
     */
    static boolean bareWordNamingNothing(String word) {
        if (word.startsWith("-") || word.contains("/") || word.contains(File.separator) || word.contains(".")) {
            return false;
        }
        try {
            return !Files.exists(Path.of(word)) && !Files.exists(Path.of(word + ".simp"));
        } catch (InvalidPathException e) {
            return false;
        }
    }

    @Override
    public Integer call() {
        if (!scenes.isEmpty()) {
            String first = scenes.get(0).toString();
            if (mistypedCommand(first, spec.commandLine().getSubcommands().keySet()).isPresent()) {
                // Main's report of the usage error says which command was meant
                throw new ParameterException(spec.commandLine(), "no command or scene file '" + first + "'");
            }
            if (bareWordNamingNothing(first)) {
                throw new ParameterException(spec.commandLine(), "no command or scene file '" + first + "' (nor "
                        + first + ".simp): the commands are " + UsageWords.joined(List.copyOf(spec.commandLine()
                        .getSubcommands().keySet()), "and")
                        + "; with no command, simpview opens its window, on the scenes named");
            }
        }
        if (displayMissing.getAsBoolean()) {
            spec.commandLine().getErr().println(
                    "simpview: no display to open a window on; write PNG files with 'simpview render --all --out-dir DIR' "
                    + "(see 'simpview render --help')");
            return ExitCode.USAGE_ERROR;
        }
        WindowOptions options = new WindowOptions(seed, simpDir == null ? ownScenes : simpDir, openAtStart(),
                sceneList(), ownScenes, threads.count(), a1Rule.rule());
        SwingUtilities.invokeLater(() -> SimpviewWindow.open(options).checkFoldersWith(CheckCommand::checkFolder));
        openedWindow = true;
        return ExitCode.OK;
    }
}
