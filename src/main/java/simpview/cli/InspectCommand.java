package simpview.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import simpview.inspect.A1Inspector;
import simpview.inspect.A1Report;
import simpview.inspect.HistoryEntry;
import simpview.inspect.InspectedScene;
import simpview.inspect.PixelInspector;
import simpview.inspect.PixelPair;
import simpview.inspect.PixelReport;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/** {@code simpview inspect ...}: why a pixel is the colour it is, as text or JSON. */
@Command(name = "inspect",
        mixinStandardHelpOptions = true,
        version = ExitCode.VERSION,
        description = {"Explains one pixel of a page or scene: every write attempted at it in drawing order "
                + "(primitive, include chain, depth, colour, what became of it), how its colour was made, "
                + "and the vertices of the primitive that drew it through every space.",
            "X,Y are panel coordinates: x right, y up from the panel's bottom-left pixel, 0 to 649; "
                + "with --assignment 1, page coordinates: x right, y up from the page's bottom-left pixel, 0 to 749 "
                + "(the report names the panel)."},
        footer = {"", "Examples:",
            "  simpview inspect --page 7 --simp-dir course/ --at 325,325",
            "  simpview inspect --scene course-a4/page-d.simp --at 455,330 --explain",
            "  simpview inspect --scene pageI.simp --at 320,300 --history --json",
            "  simpview inspect --assignment 1 --page 1 --at 540,200 --json"},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:scene error", "2:usage error (a pixel outside the panel, too)"})
final class InspectCommand implements Callable<Integer> {

    static final class What {
        @Option(names = "--page", paramLabel = "N", required = true,
                description = "page 4 to 8 (the scene pages); with --assignment 1, page 1 to 5")
        Integer page;

        @Option(names = "--scene", paramLabel = "F.simp", required = true,
                description = "any scene, drawn as render --scene draws it: lit by its own rules, or depth-cued")
        Path scene;
    }

    @Spec
    private CommandSpec spec;

    @picocli.CommandLine.ParentCommand
    private SimpviewCommand parent;

    @ArgGroup(exclusive = true, multiplicity = "1")
    private What what;

    @Option(names = "--assignment", paramLabel = "A",
            description = "whose pages --page means: 1 (the first assignment's five pages, --at in page coordinates) "
                    + "or 2 (the eight pages; default)")
    private Integer assignment;

    @Option(names = "--at", paramLabel = "X,Y", required = true,
            description = "the pixel, in panel coordinates (--assignment 1: page coordinates): X,Y, X Y or "
                    + "(X, Y) as the report writes a pixel, as the window's Go to pixel (Shift+G) takes it")
    private String at;

    @Option(names = "--history", description = "every write attempted at the pixel, in drawing order")
    private boolean history;

    @Option(names = "--explain", description = "how the pixel's colour was made, term by term")
    private boolean explain;

    @Option(names = "--vertices", description = "the vertices of the primitive that drew the pixel, through every space; for a filled one, whether it covers the pixel's centre and why")
    private boolean vertices;

    @Option(names = "--primitive", paramLabel = "N", description = "with --vertices or --explain: primitive N (1, 2, ... in drawing order, as the window steps) instead of the pixel's owner: why it did or did not cover the pixel (outside it, or on a shared edge the top-left rule gave to its neighbour); how the colour of its write here was made, one that lost the depth test or was covered later too")
    private Integer primitive;

    @Option(names = "--json", description = "one JSON object instead of text")
    private boolean json;

    @Mixin
    private A1RuleOption a1Rule;

    @Option(names = "--seed", paramLabel = "S", description = PageDrawing.SEED_HELP + " (default: 361)")
    private Long seed;

    @Option(names = "--simp-dir", paramLabel = "D", description = "folder holding the course's page6.simp to page8.simp (default: the scene folder below)")
    private Path simpDir;

    @Option(names = "--near-color", paramLabel = "r,g,b", converter = RgbConverter.class,
            description = "--scene, depth-cued: colour at z = 0 (default 1,1,1)")
    private Rgb near;

    @Option(names = "--far-color", paramLabel = "r,g,b", converter = RgbConverter.class,
            description = "--scene, depth-cued: colour at z = -200 (default 0,0,0)")
    private Rgb far;

    @Option(names = {"--own-colors", "--own-colours"},
            description = "--scene, depth-cued: the vertices' own colours (white where none) without the depth cue, "
                    + "as render --own-colors draws them")
    private boolean ownColours;

    @Override
    public Integer call() {
        usage(assignment == null || assignment == 1 || assignment == 2,
                "--assignment must be 1 or 2 (the later assignments' pages are scenes: use --scene), not " + assignment);
        usage(assignment == null || what.page != null, "--assignment goes with --page");
        if (assignment != null && assignment == 1) {
            return firstAssignment();
        }
        int[] xy = pixel(PageCanvas.PANEL - 1, "panel");
        usage(!a1Rule.given(), "--a1-rule goes with --assignment 1");
        usage(primitive == null || vertices || explain, "--primitive goes with --vertices or --explain");
        usage(what.scene != null || near == null && far == null, "--near-color and --far-color go with --scene only");
        usage(what.scene != null || !ownColours, "--own-colors goes with --scene only");
        usage(!ownColours || near == null && far == null,
                "--own-colors draws without the depth cue: it does not go with --near-color or --far-color");
        usage(what.page != null || seed == null && simpDir == null, "--seed and --simp-dir go with --page only");
        boolean all = !history && !explain && !vertices;
        try {
            InspectedScene scene;
            if (what.page != null) {
                usage(what.page >= 1 && what.page <= Assignment2.COUNT, "--page must be 4 to " + Assignment2.COUNT
                        + " (the pages drawn from scene files), not " + what.page);
                try {
                    scene = InspectedScene.page(what.page, PageDrawing.context(parent.ownScenes(), seed, simpDir,
                            PageDrawing.warningsTo(err())));
                } catch (IllegalArgumentException e) {
                    throw new ParameterException(spec.commandLine(), e.getMessage());
                }
            } else {
                scene = ownColours ? InspectedScene.cued(what.scene, Rgb.WHITE, Rgb.BLACK).withOwnColours(true)
                        : near == null && far == null ? InspectedScene.of(what.scene)
                        : InspectedScene.cued(what.scene, near == null ? Rgb.WHITE : near, far == null ? Rgb.BLACK : far);
            }
            PixelInspector inspector = new PixelInspector(new SceneLibrary(),
                    PageDrawing.warningsTo(err()));
            usage(primitive == null || primitive >= 1, "--primitive counts from 1, as the window's stepping does");
            int wanted = primitive == null ? HistoryEntry.NO_NUMBER : primitive - 1;
            PixelReport report = inspector.inspect(scene, xy[0], xy[1], wanted);
            if (!report.drawn()) {
                throw new UsageProblem(PageDrawing.cueColoursProblem(what.scene, report.litBecause(), ownColours));
            }
            if (primitive != null && report.vertices(wanted) == null && report.error() != null) {
                // not a usage problem: the scene stops before the primitive asked for
                err().println("--primitive " + primitive + ": the scene stops at an error before its primitive "
                        + primitive + ":");
                err().println(report.error().getMessage());
                return ExitCode.SCENE_ERROR;
            }
            if (primitive != null && report.vertices(wanted) == null) {
                throw new UsageProblem("--primitive " + primitive + ": the scene has no primitive " + primitive
                        + " (they count from 1 in drawing order, as the window steps)");
            }
            int table = HistoryEntry.NO_NUMBER;
            if (vertices || all) {
                HistoryEntry owner = report.lastWritten();
                table = primitive != null ? wanted : owner == null ? HistoryEntry.NO_NUMBER : owner.primitive();
            }
            int explained = primitive != null && explain ? wanted : HistoryEntry.NO_NUMBER;
            PrintWriter out = spec.commandLine().getOut();
            if (json) {
                out.println(report.json(history || all, explain || all, table, explained));
            } else {
                out.print(report.text(history || all, explain || all, table, explained));
            }
            out.flush();
            if (report.error() == null) {
                return ExitCode.OK;
            }
            // the report went as far as the error and names it; JSON's reader may not show it to a person
            if (json) {
                err().println(report.error().getMessage());
            }
            return ExitCode.SCENE_ERROR;
        } catch (SceneException e) {
            err().println(e.getMessage());
            return ExitCode.SCENE_ERROR;
        }
    }

    /** {@code --assignment 1 --page N}: the history of a page pixel, blends and all. */
    private Integer firstAssignment() {
        int[] xy = pixel(PageCanvas.SIZE - 1, "page");
        usage(what.page >= 1 && what.page <= Assignment1.COUNT,
                "--page must be 1 to " + Assignment1.COUNT + " for the first assignment, not " + what.page);
        usage(!vertices && primitive == null, "--vertices and --primitive are for scenes: the first assignment's "
                + "pages are drawn in panel coordinates, and the history names each line's or triangle's vertices");
        usage(simpDir == null, "--simp-dir goes with assignment 2's pages: the first assignment's read no files");
        usage(near == null && far == null, "--near-color and --far-color go with --scene only");
        usage(!ownColours, "--own-colors goes with --scene only");
        long chosen = PageDrawing.context(parent.ownScenes(), seed, null, PageDrawing.warningsTo(err())).seed();
        A1Report report = A1Inspector.inspect(what.page, chosen, a1Rule.rule(), xy[0], xy[1]);
        PrintWriter out = spec.commandLine().getOut();
        boolean all = !history && !explain;
        if (json) {
            out.println(report.json(history || all, explain || all));
        } else {
            out.print(report.text(history || all, explain || all));
        }
        out.flush();
        return ExitCode.OK;
    }

    /** X,Y from --at, inside the panel (or the page), read as the window's Go to pixel reads it. */
    private int[] pixel(int last, String where) {
        try {
            PixelPair pixel = PixelPair.read(at, where, last);
            return new int[] {pixel.x(), pixel.y()};
        } catch (PixelPair.NotAPixel e) {
            throw new ParameterException(spec.commandLine(), "--at " + e.getMessage());
        }
    }

    private void usage(boolean fine, String message) {
        if (!fine) {
            throw new ParameterException(spec.commandLine(), message);
        }
    }

    private PrintWriter err() {
        return spec.commandLine().getErr();
    }
}
