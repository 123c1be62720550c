package simpview.scene.simp;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.stage.CuedRenderers;
import simpview.stage.Painter;
import simpview.stage.PrimitiveSink;
import simpview.stage.PrimitiveTrace;
import simpview.surface.Drawable;

/**
 * What the commands of a scene act on: the CTM, the matrix stack, the stack
 * of files being read and the polygon style, which are the same under both
 * rules; lines, polygons and the lit commands go on to the scene's
 * {@link RuleSet}. One client draws one scene, from a fresh state: identity
 * CTM, empty stacks, style filled.
 *
 * <p>Which rules: a scene starts depth-cued and is lit from its first
 * command of the lit rules on (SPEC Part 2: a scene is lit when any file it
 * reads holds one), decided while reading, so no file is read twice to find
 * out. When that command comes before any primitive, as the camera must,
 * the client simply goes on by the lit rules; after one, the scene is drawn
 * again, lit, from the start ({@link SceneTurnsLit}).
 */
public final class SimpClient {

    /** How polygons are drawn; global, not saved by '{' '}', kept across files. */
    public enum Style { FILLED, WIRE }

    /** What a command of the lit rules does in a scene being drawn depth-cued. */
    enum OnLit {
        /** SPEC Part 2: the scene is lit; go on by the lit rules (or start again by them). */
        TURN_LIT,
        /** The eight pages are depth-cued whatever their files hold: the command is ignored, with a warning. */
        IGNORE,
        /** Depth-cue colours were asked for: stop there and say which command made the scene lit. */
        STOP
    }

    private final MatrixStack matrices = new MatrixStack();
    private final FileStack files;
    private final OnLit onLit;
    /** Makes the lit rules, when the scene turns out to be lit. */
    private final Supplier<LitRules> litRules;
    private RuleSet rules;
    private Matrix4 ctm = Matrix4.identity();
    private Style style = Style.FILLED;
    private boolean drew;
    /** Where the first colour outside [0, 1] was clamped ("file:line"), or null. */
    private String firstClamped;
    /** The largest channel of a colour clamped on that line, as written, or NaN. */
    private double firstClampedMost = Double.NaN;
    /** Where the first line or polygon with its vertices' own colours stands, or null. */
    private String firstOwnColours;
    /** A lit command met and ignored ({@link OnLit#IGNORE}): where the first stood, or null. */
    private String firstIgnored;
    /**
     * Where each '{' on the matrix stack was read, at the same index: the
     * reader of its file (one per time a file is read, so two readings of one
     * file are told apart) and its line.
     */
    private SimpReader[] openedIn = new SimpReader[16];
    private int[] openedAt = new int[16];
    /** The first '}' that closed a '{' of another file, said once the scene is drawn; null while none did. */
    private String firstClosedAcross;
    /** Where the command that made the scene lit stands, "pageA.simp:3 camera", or null. */
    private String litBecause;

    SimpClient(FileStack files, RuleSet rules, OnLit onLit, Supplier<LitRules> litRules) {
        this.files = files;
        this.rules = rules;
        this.onLit = onLit;
        this.litRules = litRules;
    }

    /** A depth-cued client on a panel-coordinate drawable with the project's renderers; lit commands are ignored. */
    SimpClient(Drawable panel) {
        this(CuedRenderers.make().painter(panel), new FileStack());
    }

    /** The same with other renderers (tests give renderers that record). */
    SimpClient(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire) {
        this(panel, lines, filled, wire, new FileStack());
    }

    SimpClient(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire, FileStack files) {
        this(new Painter(panel, lines, filled, wire), files);
    }

    private SimpClient(Painter painter, FileStack files) {
        this(files, new DepthCuedRules(painter, files, null, null), OnLit.IGNORE, SimpClient::neverLit);
    }

    static LitRules neverLit() {
        throw new IllegalStateException("this client is lit from the start, or ignores lit commands");
    }

    /** A depth-cued client with the project's renderers whose primitives {@code trace} follows; lit commands are ignored. */
    static SimpClient depthCued(Drawable panel, PrimitiveTrace trace) {
        FileStack files = new FileStack();
        return new SimpClient(files, new DepthCuedRules(panel, files, trace, null), OnLit.IGNORE, SimpClient::neverLit);
    }

    /** A client that draws by the lit rules from its first command: fragments through {@code fragments}. */
    public static SimpClient lit(FragmentStage fragments, ObjLibrary models, PrimitiveTrace trace) {
        FileStack files = new FileStack();
        return new SimpClient(files, new LitRules(fragments, models, files, SceneMonitor.NONE, trace, null), OnLit.TURN_LIT,
                SimpClient::neverLit);
    }

    /**
     * Carries out one command read from the top of {@link #files()}; true
     * when it drew a primitive. Every kind of {@link Command.Kind} is named
     * here, so a new command is a compile error until it has its action.
     */
    public boolean execute(Command c) throws SceneException {
        return switch (c.kind) {
            case PUSH -> {
                int d = matrices.depth();
                if (d == openedIn.length) {
                    openedIn = Arrays.copyOf(openedIn, 2 * d);
                    openedAt = Arrays.copyOf(openedAt, 2 * d);
                }
                openedIn[d] = files.current();
                openedAt[d] = files.current().lineNumber();
                matrices.push(ctm);
                yield false;
            }
            case POP -> pop(c);
            case SCALE -> transform(c, Matrix4.scaling(c.numbers[0], c.numbers[1], c.numbers[2]));
            case TRANSLATE -> transform(c, Matrix4.translation(c.numbers[0], c.numbers[1], c.numbers[2]));
            case ROTATE -> transform(c, Matrix4.rotation(c.axis, c.angle));
            case LINE -> {
                rules.line(ctm, c.xyz, colours(c));
                yield drew = true;
            }
            case POLYGON -> {
                rules.polygon(ctm, c.xyz, colours(c), style == Style.WIRE);
                yield drew = true;
            }
            case FILE -> {
                files.include(c);
                yield false;
            }
            case WIRE -> style(Style.WIRE);
            case FILLED -> style(Style.FILLED);
            // The commands of the lit rules: this switch is the one place
            // that says which they are. Each goes to the lit rules once lit()
            // has turned the scene lit (or said to ignore it).
            case CAMERA -> lit(c) && litRules().camera(c, ctm);
            case OBJ -> lit(c) && obj(c);
            case AMBIENT -> lit(c) && litRules().ambient(c);
            case SURFACE -> lit(c) && litRules().surface(c);
            case DEPTH -> lit(c) && litRules().depth(c);
            case LIGHT -> lit(c) && litRules().light(c, ctm);
            case FLAT -> lit(c) && litRules().shading(LitState.ShadingMode.FLAT);
            case GOURAUD -> lit(c) && litRules().shading(LitState.ShadingMode.GOURAUD);
            case PHONG -> lit(c) && litRules().shading(LitState.ShadingMode.PHONG);
        };
    }

    /**
     * Before a command of the lit rules: turns the scene lit first if need
     * be; false when the command is to be ignored (the eight pages).
     */
    private boolean lit(Command c) throws SceneException {
        if (rules instanceof LitRules) {
            return true;
        }
        String here = files.place() + " " + c.kind.spelling;
        switch (onLit) {
            case IGNORE -> {
                if (firstIgnored == null) {
                    firstIgnored = here;
                }
                return false;
            }
            case STOP -> throw new SceneTurnsLit(here);
            case TURN_LIT -> {
                if (drew) {
                    throw new SceneTurnsLit(here);
                }
                litBecause = here;
                rules = litRules.get();
            }
        }
        return true;
    }

    /** The rules of a scene {@link #lit} has turned lit. */
    private LitRules litRules() {
        return (LitRules) rules;
    }

    /** An obj: the one command of the lit rules that draws; its model's colours may be clamped. */
    private boolean obj(Command c) throws SceneException {
        litRules().obj(c, ctm, style);
        drew = true;
        if (firstClamped == null) {
            firstClamped = rules.firstClampedColour(); // the model's, read by this command
            firstClampedMost = rules.firstClampedChannel();
        }
        return true;
    }

    /**
     * CTM = CTM * m. A CTM that overflows the doubles (a scale of 1e200 twice,
     * a translate of 1e308 twice) is an error at this command: every point
     * transformed by it would come out Infinity or NaN and draw nothing, and
     * SPEC makes an infinite number an error. One check per transform
     * command, none per vertex.
     */
    private boolean transform(Command c, Matrix4 m) throws SceneException {
        Matrix4 product = ctm.times(m);
        if (!product.isFinite()) {
            double bad = product.firstNonFinite();
            throw files.current().error(c.commandIndex, "the transform overflows: after this " + c.kind.spelling
                    + " the matrix holds " + bad + (Double.isNaN(bad) ? " (Infinity minus Infinity)" : "")
                    + ", beyond the largest number a double holds (about 1.8e308), so every point it transformed"
                    + " would be lost: make its scales and translations smaller");
        }
        ctm = product;
        return false;
    }

    private boolean style(Style s) {
        style = s;
        return false;
    }

    private boolean pop(Command c) throws SceneException {
        if (matrices.isEmpty()) {
            throw files.current().error(c.commandIndex, "'}' has no '{' to match: the matrix stack is empty"
                    + (firstClosedAcross == null ? "" : " (" + firstClosedAcross + ")"));
        }
        int d = matrices.depth() - 1;
        SimpReader here = files.current();
        if (openedIn[d] != here && firstClosedAcross == null) {
            firstClosedAcross = closedAcross(openedIn[d], openedAt[d], here);
        }
        openedIn[d] = null;
        ctm = matrices.pop();
        return false;
    }

    /**
     * What to say of a '}' in {@code here} that closes the '{' read at line
     * {@code at} of {@code opened}, another file: each file should close the
     * '{' it opens. Either the '{' file has ended (an included file left it
     * open: its '}' is missing, and the including file's '}' closes it), or
     * it is still being read (an included file closes the including file's
     * '{': one '}' too many there).
     */
    private String closedAcross(SimpReader opened, int at, SimpReader here) {
        String openedName = files.shown(opened.file());
        String hereName = files.shown(here.file());
        String open = openedName + ":" + at;
        String close = hereName + ":" + here.lineNumber();
        if (!files.reading(opened)) {
            return open + ": this '{' is still open at the end of " + openedName + ", so the '}' at " + close
                    + " closes it, not the '{' it was written for: each file closes the '{' it opens;"
                    + " is a '}' missing at the end of " + openedName + "?";
        }
        return close + ": this '}' closes the '{' at " + open + ", opened before " + hereName + " was included,"
                + " so the '}' written for that '{' closes another, or none: each file closes the '{' it opens;"
                + " is this '}' one too many?";
    }

    /** The command's own colours, or null; notes the first line whose colours were clamped. */
    private double[] colours(Command c) {
        if (c.clamped && firstClamped == null) {
            firstClamped = files.place();
            firstClampedMost = c.largestColourChannel();
        }
        if (c.colored && firstOwnColours == null) {
            firstOwnColours = files.place();
        }
        return c.colored ? c.rgb : null;
    }

    /** Draws what the rules still hold recorded (several drawing threads); see {@link RuleSet#flush}. */
    void flush() {
        rules.flush();
    }

    /** The lit state as the commands so far left it, or null while depth-cued: read, never to be changed. */
    public LitState litState() {
        return rules instanceof LitRules lit ? lit.state() : null;
    }

    /** True for a lit scene whose lit polygons all came out black, nothing lighting them. */
    boolean everyLitPolygonBlack() {
        return rules instanceof LitRules lit && lit.everyLitPolygonBlack();
    }

    /** For a lit scene whose every primitive drawn lies wholly beyond its fog's far plane: the first one's fog; else null. */
    Fog everyPrimitiveFoggedWhole() {
        return rules instanceof LitRules lit ? lit.everyPrimitiveFoggedWhole() : null;
    }

    /** True for a lit scene whose lights all stood behind every lit polygon, polygons that face opposite ways. */
    boolean lightsInsideThePolygons() {
        return rules instanceof LitRules lit && lit.lightsInsideThePolygons();
    }

    /** True for a lit scene whose lights, while on, all stood behind every lit polygon. */
    boolean noLightReachedAPolygon() {
        return rules instanceof LitRules lit && lit.noLightReachedAPolygon();
    }

    /** True once the scene is drawn by the lit rules. */
    boolean isLit() {
        return rules instanceof LitRules;
    }

    /** Where the command that made the scene lit stands ("pageA.simp:3 camera"); null while depth-cued. */
    String litBecause() {
        return litBecause;
    }

    /** True once a primitive was drawn (or, reading ahead, handed on to be drawn). */
    boolean drew() {
        return drew;
    }

    /** The depth-cued rules, for a reader that sends their primitives to another thread. */
    DepthCuedRules depthCued() {
        return (DepthCuedRules) rules;
    }

    /** From now on primitives go to {@code to} instead of being drawn at once (depth-cued scenes only). */
    void sendTo(PrimitiveSink to) {
        depthCued().sendTo(to);
    }

    Painter painter() {
        return depthCued().painter();
    }

    /** For a lit scene that was followed: the centre of what its view showed, in camera space; else null. */
    double[] shownCentre() {
        return rules instanceof LitRules lit ? lit.shownCentre() : null;
    }

    FileStack files() {
        return files;
    }

    public Matrix4 ctm() {
        return ctm;
    }

    public Style style() {
        return style;
    }

    /**
     * What the scene should be told once it is drawn: what its models warned
     * of (before the clamp that a decimal comma may explain), clamped colours,
     * primitives not drawn for a vertex beyond the doubles, ignored lit
     * commands, '{' left open.
     */
    public List<String> warnings() {
        List<String> w = new ArrayList<>(rules.modelWarnings());
        if (rules instanceof LitRules lit && lit.colourAboveOne() != null) {
            w.add(lit.colourAboveOne());
        }
        if (rules instanceof LitRules lit && lit.fogUnseen() != null) {
            w.add(lit.fogUnseen());
        }
        if (firstClamped != null) {
            String of255 = LitRules.notOf255(firstClampedMost); // "" unless the channel looks like a byte
            w.add(firstClamped + ": colour channels outside 0 to 1 were clamped (this is the first such line)"
                    + (of255.isEmpty() ? "" : ": a colour runs from 0 to 1" + of255));
        }
        String nonFinite = rules.firstNonFinite();
        if (nonFinite != null) {
            long more = rules.nonFiniteCount() - 1;
            w.add(nonFinite + ": " + rules.nonFiniteWhy() + ", so this primitive was not drawn"
                    + (more > 0 ? ", nor " + more + " more like it" : ""));
        }
        if (firstIgnored != null) {
            w.add(firstIgnored + ": commands of lit scenes were ignored in this depth-cued drawing (the first of them)");
        }
        if (firstClosedAcross != null) {
            w.add(firstClosedAcross);
        }
        int open = matrices.depth();
        if (open > 0) {
            w.add(files.shown(openedIn[0].file()) + ":" + openedAt[0]
                    + ": '{' never closed by the end of the scene" + (open > 1 ? ", nor the " + (open - 1)
                    + " opened after it" : ""));
        }
        return w;
    }

    /** Primitives skipped because they lie wholly outside one plane of the view volume. */
    public long culledCount() {
        return rules.culledCount();
    }

    /** The planes every culled primitive lies wholly outside of, bits 1 &lt;&lt; Camera.HITHER ...; 0 when none. */
    int culledOutside() {
        return rules.culledOutside();
    }

    /** Primitives not culled that the clipper cut away whole (Part 1: that lie so, none of their pixels shown). */
    long clippedAwayCount() {
        return rules.clippedAwayCount();
    }

    /** The sides of the view every one of those reaches beyond, bits 1 &lt;&lt; Camera.HITHER ...; 0 when none. */
    int clippedAwayOutside() {
        return rules.clippedAwayOutside();
    }

    /** The view the primitives were culled and clipped by: the camera's, or the parallel box. */
    Camera view() {
        return rules instanceof LitRules lit ? lit.state().camera() : Camera.PARALLEL;
    }

    /** Where the first line or polygon with its vertices' own colours stands ("house.simp:3"), or null. */
    String firstOwnColours() {
        return firstOwnColours;
    }

    /** Primitives taken, culled or not. */
    long primitiveCount() {
        return rules.primitiveCount();
    }
}
