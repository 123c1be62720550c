package simpview.scene.simp;

import simpview.geometry.Matrix4;
import simpview.geometry.Vertex;
import simpview.geometry.ViewVolume;
import simpview.scene.PrimitiveTrace;
import simpview.surface.Drawable;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.raster.WireframePolygonRenderer;

/**
 * What the commands of a scene act on: the CTM, the matrix stack, the stack
 * of files being read and the polygon style, and the renderers that draw on
 * the panel. One client draws one scene, from a fresh state: identity CTM,
 * empty stacks, style filled.
 */
public final class SimpClient {

    /** How polygons are drawn; global, not saved by '{' '}', kept across files. */
    public enum Style { FILLED, WIRE }

    private final Painter painter;
    /** Where primitives go: the painter, or a batch for the drawing thread. */
    private PrimitiveSink sink;
    private final MatrixStack matrices = new MatrixStack();
    private final FileStack files;
    private Matrix4 ctm = Matrix4.identity();
    private Style style = Style.FILLED;
    /** World-space vertices of the primitive at hand, reused. */
    private final double[] world = new double[3 * Command.MAX_VERTICES];
    /** The same in panel space with colours, as the painter takes them, reused. */
    private final double[] primitive = new double[Painter.STRIDE];
    private long culled;
    /** Who follows the primitives (the window's instruments), or null. */
    private PrimitiveTrace trace;
    private int traced;

    /** Draws on a panel-coordinate drawable with the project's renderers. */
    public SimpClient(Drawable panel) {
        this(panel, new DdaLineRenderer(), new FilledPolygonRenderer(),
                new WireframePolygonRenderer(new DdaLineRenderer()));
    }

    public SimpClient(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire) {
        this(panel, lines, filled, wire, new FileStack());
    }

    SimpClient(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire, FileStack files) {
        this.painter = new Painter(panel, lines, filled, wire);
        this.sink = painter;
        this.files = files;
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
            case SCALE -> ctm = ctm.times(Matrix4.scaling(c.xyz[0], c.xyz[1], c.xyz[2]));
            case TRANSLATE -> ctm = ctm.times(Matrix4.translation(c.xyz[0], c.xyz[1], c.xyz[2]));
            case ROTATE -> ctm = ctm.times(Matrix4.rotation(c.axis, c.angle));
            case LINE -> line(c);
            case POLYGON -> polygon(c);
            case FILE -> files.include(c);
            case WIRE -> style = Style.WIRE;
            case FILLED -> style = Style.FILLED;
            default -> throw new IllegalStateException(String.valueOf(c.kind));
        }
    }

    private void pop(Command c) throws SceneException {
        if (matrices.isEmpty()) {
            throw files.current().error(c.commandIndex, "'}' has no '{' to match: the matrix stack is empty");
        }
        ctm = matrices.pop();
    }

    private void line(Command c) {
        toWorld(c, 2);
        if (Culling.isCulled(world, 2)) {
            culled++;
            return;
        }
        toPanel(c, 2);
        emit(Painter.LINE);
    }

    private void polygon(Command c) {
        toWorld(c, 3);
        if (Culling.isCulled(world, 3)) {
            culled++;
            return;
        }
        toPanel(c, 3);
        emit(style == Style.FILLED ? Painter.FILLED : Painter.WIRE);
    }

    /** Hands the primitive on; a trace, if any, learns which line it came from. */
    private void emit(int kind) {
        if (trace != null) {
            trace.read(traced++, files.current().file(), files.current().lineNumber(), kind, primitive);
        }
        sink.add(kind, primitive);
    }

    /**
     * Has {@code follower} told of every primitive: where it came from as it
     * is read, and before it is drawn; null for nobody (the default, free).
     */
    public void follow(PrimitiveTrace follower) {
        trace = follower;
        painter.follow(follower);
    }

    /** Starts the CTM at {@code turn} (a turn of the whole world before the scene's own transforms); null: identity. */
    public void turnWorld(Matrix4 turn) {
        ctm = turn == null ? Matrix4.identity() : turn;
    }

    private void toWorld(Command c, int count) {
        Matrix4 m = ctm;
        double[] p = c.xyz;
        for (int k = 0; k < 3 * count; k += 3) {
            double x = p[k];
            double y = p[k + 1];
            double z = p[k + 2];
            world[k] = m.applyX(x, y, z);
            world[k + 1] = m.applyY(x, y, z);
            world[k + 2] = m.applyZ(x, y, z);
        }
    }

    /** The first count world vertices in panel space, each with its own colour or white. */
    private void toPanel(Command c, int count) {
        for (int k = 0; k < count; k++) {
            int i = 3 * k;
            int o = Vertex.NUMBERS * k;
            primitive[o + Vertex.X] = ViewVolume.toPanel(world[i]);
            primitive[o + Vertex.Y] = ViewVolume.toPanel(world[i + 1]);
            primitive[o + Vertex.Z] = world[i + 2];
            primitive[o + Vertex.R] = c.color(k, 0);
            primitive[o + Vertex.G] = c.color(k, 1);
            primitive[o + Vertex.B] = c.color(k, 2);
        }
    }

    Painter painter() {
        return painter;
    }

    /** From now on primitives go to {@code to} instead of being drawn at once. */
    void sendTo(PrimitiveSink to) {
        sink = to;
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

    /** Primitives skipped because they lie wholly outside one plane of the view volume. */
    public long culledCount() {
        return culled;
    }
}
