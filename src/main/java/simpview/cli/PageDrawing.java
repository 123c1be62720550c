package simpview.cli;

import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.ScenePipeline;

import java.io.PrintWriter;
import java.nio.file.Path;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.Setting;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * The one way the command line draws a picture, a page or any scene as a
 * page: {@code render} and {@code compare} both draw through here, on one
 * canvas that is reused (the canvas returned is overwritten by the next call).
 */
public final class PageDrawing {

    /** What --seed is, in every command's help: the pages it changes, of both assignments. */
    static final String SEED_HELP = "seed of the random pages: 1 to 3 of the eight, 3 to 5 of the first assignment's";

    private final PageRenderer renderer;
    private final SceneMonitor monitor;
    /** The files of this run's scenes: each .simp or .obj file read once however many scenes draw it. */
    private final SceneLibrary library = new SceneLibrary();

    /** Draws with {@code threads}, which the caller owns and closes. */
    PageDrawing(SceneMonitor monitor, DrawingThreads threads) {
        this.monitor = monitor;
        this.renderer = new PageRenderer(threads);
    }

    /** Page n; on a scene error the canvas keeps what was drawn before it and the error is thrown on. */
    PageCanvas page(int number, PageContext context) throws SceneException {
        return renderer.render(number, context.withMonitor(monitor).withLibrary(library));
    }

    /**
     * A scene as a whole page: lit by its own rules, or depth-cued from near
     * (default white) to far (default black), or with {@code ownColours} in
     * the vertices' own colours without the cue. Given depth-cue colours or
     * own colours, both of depth-cued scenes only, a lit scene is not drawn
     * ({@link ScenePipeline.Drawn#drawn} false: see {@link #cueColoursProblem}).
     * The picture is on {@link #canvas()}.
     */
    ScenePipeline.Drawn scene(Path file, Rgb near, Rgb far, boolean ownColours) throws SceneException {
        boolean cueGiven = near != null || far != null || ownColours;
        ScenePipeline.Options options = ScenePipeline.Options.byCommands(library)
                .withCue(near == null ? Rgb.WHITE : near, far == null ? Rgb.BLACK : far)
                .withOwnColours(ownColours)
                .withRules(cueGiven ? ScenePipeline.Rules.DEPTH_CUED_OR_NOTHING : ScenePipeline.Rules.BY_COMMANDS);
        return renderer.renderScene(file, options, monitor);
    }

    /** The canvas the last page or scene was drawn on (overwritten by the next). */
    PageCanvas canvas() {
        return renderer.canvas();
    }

    /**
     * Why {@code file}, which drew nothing, could not take the depth-cue
     * colours or, with {@code ownColours}, the own colours given: it is lit,
     * {@code litBecause} ("pageA.simp:3 camera").
     */
    static String cueColoursProblem(Path file, String litBecause, boolean ownColours) {
        return (ownColours ? "--own-colors is" : "--near-color and --far-color are") + " for depth-cued scenes, and "
                + file.getFileName() + " is lit (" + litBecause + ")";
    }

    /** The pages' context from the command line's options (null where not given), warnings to {@code monitor}. */
    static PageContext context(Path ownScenes, Long seed, Path simpDir, SceneMonitor monitor) {
        PageContext context = PageContext.of(ownScenes).withMonitor(monitor);
        if (seed != null) {
            context = context.withSeed(seed);
        }
        return simpDir == null ? context : context.withSimpDir(simpDir);
    }

    /** A monitor that prints each warning as a "warning: ..." line on {@code err}, naming settings by option. */
    static SceneMonitor warningsTo(PrintWriter err) {
        return new SceneMonitor() {
            @Override
            public void warning(String message) {
                err.println("warning: " + message);
            }

            @Override
            public String nameOf(Setting setting) {
                return setting.option();
            }
        };
    }
}
