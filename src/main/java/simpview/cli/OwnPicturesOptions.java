package simpview.cli;

import java.nio.file.Path;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import simpview.pages.PageContext;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.DrawingThreads;
import simpview.surface.Rgb;

/**
 * The options of the commands that compare pictures with simpview's own
 * ({@code compare}, {@code check}): the seed and the course's folder the
 * pages are drawn with (and the first assignment's rule), the depth cue a scene is drawn with (or its own
 * colours), and which of them go together.
 */
final class OwnPicturesOptions {

    @Spec(Spec.Target.MIXEE)
    private CommandSpec spec;

    @Option(names = "--seed", paramLabel = "S", description = PageDrawing.SEED_HELP + " (default: 361)")
    private Long seed;

    @Option(names = "--simp-dir", paramLabel = "D", description = "folder holding the course's page6.simp to page8.simp (default: the scene folder below)")
    private Path simpDir;

    @Mixin
    private A1RuleOption a1Rule;

    @Option(names = "--near-color", paramLabel = "r,g,b", converter = RgbConverter.class,
            description = "colour at z = 0 for --scene, channels 0 to 1 (default: 1,1,1)")
    private Rgb near;

    @Option(names = "--far-color", paramLabel = "r,g,b", converter = RgbConverter.class,
            description = "colour at z = -200 for --scene (default: 0,0,0)")
    private Rgb far;

    @Option(names = {"--own-colors", "--own-colours"},
            description = "--scene: draw the vertices' own colours (white where none) without the depth cue, as "
                    + "render --own-colors does")
    private boolean ownColours;

    /** Usage errors for options that do not go with what is compared: a scene, or the pages when {@code scene} is null. */
    void check(Path scene) {
        if (scene == null && (near != null || far != null)) {
            throw new ParameterException(spec.commandLine(), "--near-color and --far-color go with --scene only");
        }
        if (scene == null && ownColours) {
            throw new ParameterException(spec.commandLine(), "--own-colors goes with --scene only");
        }
        if (ownColours && (near != null || far != null)) {
            throw new ParameterException(spec.commandLine(), "--own-colors draws without the depth cue: it does not"
                    + " go with --near-color or --far-color");
        }
        if (scene != null && (seed != null || simpDir != null)) {
            throw new ParameterException(spec.commandLine(), "--seed and --simp-dir go with the pages, not with --scene");
        }
        if (scene != null && a1Rule.given()) {
            throw new ParameterException(spec.commandLine(), "--a1-rule goes with the first assignment's pages, not with --scene");
        }
        a1Rule.check();
    }

    /** Usage errors for options that do nothing to the first assignment's pages alone (--assignment 1). */
    void checkFirstAssignment() {
        if (simpDir != null) {
            throw new ParameterException(spec.commandLine(), "--simp-dir goes with assignment 2's pages: the first "
                    + "assignment's read no files");
        }
    }

    /** " --seed S" when --seed was given, else "": for a command these options suggest. */
    String seedOption() {
        return seed == null ? "" : " --seed " + seed;
    }

    /**
     * The options given that change what a scene page or scene draws, as typed: " --simp-dir course/ --seed 7",
     * " --near-color 1,0,0 --own-colors"; "" when none was. For a command these options suggest ({@code inspect},
     * which takes them all).
     */
    String drawingOptions() {
        String typed = typedOptions("--simp-dir", "--seed", "--near-color", "--far-color");
        return ownColours ? typed + " --own-colors" : typed;
    }

    /** The options of {@code names} given to the command, each with its value as typed: " --min 99.5". */
    String typedOptions(String... names) {
        StringBuilder out = new StringBuilder();
        for (String name : names) {
            OptionSpec given = spec.commandLine().getParseResult().matchedOption(name);
            if (given != null) {
                out.append(' ').append(name).append(' ').append(ArgumentLine.shellWord(given.stringValues().get(0)));
            }
        }
        return out.toString();
    }

    /** Whether --a1-rule was given. */
    boolean a1RuleGiven() {
        return a1Rule.given();
    }

    /** The pages' context these options ask for, the project's own scenes in {@code ownScenes}. */
    PageContext context(Path ownScenes, SceneMonitor monitor) {
        return a1Rule.applyTo(PageDrawing.context(ownScenes, seed, simpDir, monitor));
    }

    /** simpview's pictures to compare with, drawn as these options ask, by {@code drawing}. */
    OwnPictures ownPictures(Path ownScenes, SceneMonitor monitor, DrawingThreads drawing) {
        return new OwnPictures(context(ownScenes, monitor), near, far, ownColours, monitor, drawing);
    }
}
