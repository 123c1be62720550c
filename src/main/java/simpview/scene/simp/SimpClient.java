package simpview.scene.simp;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.geometry.Vertex;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.stage.DepthCuedGeometry;
import simpview.stage.GeometryStage;
import simpview.stage.LitGeometry;
import simpview.stage.Painter;
import simpview.stage.PrimitiveSink;
import simpview.stage.PrimitiveTrace;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.surface.Drawable;

/**
 * What the commands of a scene act on: the CTM, the matrix stack, the stack
 * of files being read and the polygon style; lines and polygons go on to the
 * scene's geometry stage. One client draws one scene, from a fresh state:
 * identity CTM, empty stacks, style filled.
 */
public final class SimpClient {

    /** How polygons are drawn; global, not saved by '{' '}', kept across files. */
    public enum Style { FILLED, WIRE }

    private final Painter painter;
    /** The depth-cued stage; null for a lit scene. */
    private final DepthCuedGeometry cued;
    /** The lit stage and its state; null for a depth-cued scene. */
    private final LitGeometry lit;
    private final LitState state;
    private final ObjLibrary models;
    private final GeometryStage geometry;
    private final MatrixStack matrices = new MatrixStack();
    private final FileStack files;
    private Matrix4 ctm = Matrix4.identity();
    private Style style = Style.FILLED;
    /** Where the first colour outside [0, 1] was clamped ("file:line"), or null. */
    private String firstClamped;
    /** Where the camera command stands, and where the first primitive did ("file:line"), or null. */
    private String cameraAt;
    private String firstPrimitiveAt;
    /** A lit command met in a scene drawn depth-cued on request: where the first stood, or null. */
    private String firstIgnored;
    /** Who follows the primitives (the window's instruments), or null: nobody, and nothing is spent on it. */
    private PrimitiveTrace trace;
    private int traced;

    /** Draws a depth-cued scene on a panel-coordinate drawable with the project's renderers. */
    public SimpClient(Drawable panel) {
        this(panel, new DdaLineRenderer(), new FilledPolygonRenderer(),
                new WireframePolygonRenderer(new DdaLineRenderer()));
    }

    public SimpClient(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire) {
        this(panel, lines, filled, wire, new FileStack());
    }

    SimpClient(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire, FileStack files) {
        this.painter = new Painter(panel, lines, filled, wire);
        this.cued = new DepthCuedGeometry(painter);
        this.geometry = cued;
        this.lit = null;
        this.state = null;
        this.models = null;
        this.files = files;
    }

    private SimpClient(FragmentStage fragments, ObjLibrary models, FileStack files) {
        this.painter = null;
        this.cued = null;
        this.state = new LitState();
        this.lit = new LitGeometry(state, fragments);
        this.geometry = lit;
        this.models = models;
        this.files = files;
    }

    /** A client for a lit scene: its fragments go through {@code fragments}; .obj models come from {@code models}. */
    public static SimpClient lit(FragmentStage fragments, ObjLibrary models) {
        return new SimpClient(fragments, models, new FileStack());
    }

    /** True for a client that draws by the lit rules. */
    public boolean isLit() {
        return lit != null;
    }

    /**
     * Carries out one command read from the top of {@link #files()}. Lines and
     * polygons are drawn at once, unless the interpreter has the client send
     * them to the drawing thread.
     */
    public void execute(Command c) throws SceneException {
        switch (c.kind) {
            case PUSH -> matrices.push(ctm);
            case POP -> pop(c);
            case SCALE -> ctm = ctm.times(Matrix4.scaling(c.numbers[0], c.numbers[1], c.numbers[2]));
            case TRANSLATE -> ctm = ctm.times(Matrix4.translation(c.numbers[0], c.numbers[1], c.numbers[2]));
            case ROTATE -> ctm = ctm.times(Matrix4.rotation(c.axis, c.angle));
            case LINE -> {
                primitive();
                geometry.line(ctm, c.xyz, colours(c));
            }
            case POLYGON -> {
                primitive();
                geometry.polygon(ctm, c.xyz, colours(c), style == Style.WIRE);
            }
            case FILE -> files.include(c);
            case WIRE -> style = Style.WIRE;
            case FILLED -> style = Style.FILLED;
            default -> litCommand(c);
        }
    }

    /** The commands of the lit rules (SPEC Part 2); each checks its numbers first. */
    private void litCommand(Command c) throws SceneException {
        if (lit == null) {
            if (firstIgnored == null) {
                firstIgnored = place() + " " + c.kind.spelling;
            }
            return;
        }
        switch (c.kind) {
            case CAMERA -> camera(c);
            case OBJ -> obj(c);
            case AMBIENT -> {
                notNegative(c, 0, 3, "ambient light");
                state.setAmbient(c.numbers[0], c.numbers[1], c.numbers[2]);
            }
            case SURFACE -> surface(c);
            case DEPTH -> depth(c);
            case LIGHT -> light(c);
            case FLAT -> state.setShading(LitState.Shading.FLAT);
            case GOURAUD -> state.setShading(LitState.Shading.GOURAUD);
            case PHONG -> state.setShading(LitState.Shading.PHONG);
            default -> throw new IllegalStateException(String.valueOf(c.kind));
        }
    }

    private void camera(Command c) throws SceneException {
        if (cameraAt != null) {
            throw error(c, c.commandIndex, "a second camera: a scene has one, and the first is at " + cameraAt);
        }
        if (firstPrimitiveAt != null) {
            throw error(c, c.commandIndex, "the camera must come before every line, polygon and obj; "
                    + firstPrimitiveAt + " drew one before it");
        }
        double[] n = c.numbers;
        String problem = Camera.problem(n[0], n[1], n[2], n[3], n[4], n[5]);
        if (problem != null) {
            throw error(c, c.argumentIndex, problem);
        }
        Matrix4 w = ctm.inverse();
        if (w == null) {
            throw error(c, c.commandIndex, "the CTM at the camera cannot be inverted (a scale of 0?): "
                    + "there is no way from the world to the camera");
        }
        cameraAt = place();
        state.setCamera(Camera.perspective(n[0], n[1], n[2], n[3], n[4], n[5]), w);
    }

    private void obj(Command c) throws SceneException {
        primitive();
        Path file = FileStack.locate(c.fileName, ".obj", files.current(), c);
        lit.beginObj(ctm, style == Style.WIRE, file);
        models.draw(file, lit::face);
    }

    private void surface(Command c) throws SceneException {
        notNegative(c, 0, c.count, c.count == 3 ? "surface colour" : "surface colour, ks and p");
        double[] n = c.numbers;
        if (c.count == 3) {
            state.setSurface(n[0], n[1], n[2]);
        } else {
            state.setSurface(n[0], n[1], n[2], n[3], n[4]);
        }
    }

    private void depth(Command c) throws SceneException {
        double[] n = c.numbers;
        if (!(n[0] > n[1])) {
            throw error(c, c.argumentIndex, "fog needs near > far (camera-space z, far more negative), found near "
                    + n[0] + " and far " + n[1]);
        }
        notNegative(c, 2, 5, "fog colour");
        state.setFog(new Fog(n[0], n[1], n[2], n[3], n[4]));
    }

    private void light(Command c) throws SceneException {
        notNegative(c, 0, 5, "light intensity and attenuation");
        double[] n = c.numbers;
        if (n[3] == 0 && n[4] == 0) {
            throw error(c, c.argumentIndex, "attenuation A and B are both 0: the light would be infinitely bright");
        }
        state.addLight(ctm.get(0, 3), ctm.get(1, 3), ctm.get(2, 3), n[0], n[1], n[2], n[3], n[4]);
    }

    private void notNegative(Command c, int from, int to, String what) throws SceneException {
        for (int i = from; i < to; i++) {
            if (c.numbers[i] < 0) {
                throw error(c, c.argumentIndex, what + " may not be negative, found " + c.numbers[i]);
            }
        }
    }

    private SceneException error(Command c, int at, String problem) {
        return files.current().error(at, problem);
    }

    /** "file:line" of the command being carried out. */
    private String place() {
        SimpReader r = files.current();
        return r.file().getFileName() + ":" + r.lineNumber();
    }

    /** Notes the first primitive, which no camera may follow; tells a followed lit stage where it stands. */
    private void primitive() {
        if (lit == null) {
            return;
        }
        if (firstPrimitiveAt == null) {
            firstPrimitiveAt = place();
        }
        if (trace != null) {
            lit.from(files.current().file(), files.current().lineNumber());
        }
    }

    /** The command's own colours, or null; notes the first line whose colours were clamped. */
    private double[] colours(Command c) {
        if (c.clamped && firstClamped == null) {
            firstClamped = place();
        }
        return c.colored ? c.rgb : null;
    }

    private void pop(Command c) throws SceneException {
        if (matrices.isEmpty()) {
            throw files.current().error(c.commandIndex, "'}' has no '{' to match: the matrix stack is empty");
        }
        ctm = matrices.pop();
    }

    Painter painter() {
        return painter;
    }

    /**
     * The window's instruments' hook, one place on each side: {@code follower}
     * learns each primitive's file and line as the geometry hands it on (the
     * reading thread), and is asked before the painter draws it (the drawing
     * thread). Null for nobody, the default. A lit scene is read and drawn
     * on one thread, and its stage tells the trace itself. Call before the
     * scene is read.
     */
    public void follow(PrimitiveTrace follower) {
        trace = follower;
        if (lit != null) {
            lit.follow(follower);
            return;
        }
        painter.follow(follower);
        cued.sendTo(follower == null ? painter : new Traced(painter));
    }

    /**
     * Turns the view by {@code turn}, in camera space (see
     * {@link SceneMonitor#viewTurn}); null: not turned. A depth-cued scene
     * starts its CTM at it; a lit one puts it after W. Call before the scene
     * is read.
     */
    public void turnView(Matrix4 turn) {
        if (state != null) {
            state.turnView(turn);
        } else {
            ctm = turn == null ? Matrix4.identity() : turn;
        }
    }

    /** For a lit scene that was followed: the centre of what its view showed, in camera space; else null. */
    public double[] shownCentre() {
        return lit == null ? null : lit.shownCentre();
    }

    /** A sink that tells the trace where each primitive came from, then hands it on. */
    private final class Traced implements PrimitiveSink {
        private final PrimitiveSink next;

        Traced(PrimitiveSink next) {
            this.next = next;
        }

        @Override
        public void add(int kind, double[] p) {
            trace.read(traced++, files.current().file(), files.current().lineNumber(), kind, p, 0, Vertex.NUMBERS,
                    kind == Painter.LINE ? 2 : 3);
            next.add(kind, p);
        }
    }

    /** From now on primitives go to {@code to} instead of being drawn at once (depth-cued scenes only). */
    void sendTo(PrimitiveSink to) {
        cued.sendTo(trace == null ? to : new Traced(to));
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

    /** Depth of the matrix stack: '{' not yet closed. */
    public int openBraces() {
        return matrices.depth();
    }

    /** What the scene should be told once it is drawn: clamped colours, ignored lit commands. */
    public List<String> warnings() {
        List<String> w = new ArrayList<>();
        if (firstClamped != null) {
            w.add(firstClamped + ": colour channels outside 0 to 1 were clamped (this is the first such line)");
        }
        if (firstIgnored != null) {
            w.add(firstIgnored + ": commands of lit scenes were ignored in this depth-cued drawing (the first of them)");
        }
        return w;
    }

    /** Primitives skipped because they lie wholly outside one plane of the view volume. */
    public long culledCount() {
        return geometry.culledCount();
    }
}
