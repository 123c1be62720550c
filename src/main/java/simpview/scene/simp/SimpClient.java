package simpview.scene.simp;

import simpview.geometry.Matrix4;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.scene.DepthCuedGeometry;
import simpview.scene.Painter;
import simpview.scene.PrimitiveSink;
import simpview.scene.SceneException;
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
    private final DepthCuedGeometry geometry;
    private final MatrixStack matrices = new MatrixStack();
    private final FileStack files;
    private Matrix4 ctm = Matrix4.identity();
    private Style style = Style.FILLED;
    /** Where the first colour outside [0, 1] was clamped ("file:line"), or null. */
    private String firstClamped;

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
        this.geometry = new DepthCuedGeometry(painter);
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
            case SCALE -> ctm = ctm.times(Matrix4.scaling(c.numbers[0], c.numbers[1], c.numbers[2]));
            case TRANSLATE -> ctm = ctm.times(Matrix4.translation(c.numbers[0], c.numbers[1], c.numbers[2]));
            case ROTATE -> ctm = ctm.times(Matrix4.rotation(c.axis, c.angle));
            case LINE -> geometry.line(ctm, c.xyz, colours(c));
            case POLYGON -> geometry.polygon(ctm, c.xyz, colours(c), style == Style.WIRE);
            case FILE -> files.include(c);
            case WIRE -> style = Style.WIRE;
            case FILLED -> style = Style.FILLED;
            default -> throw files.current().error(c.commandIndex, "'" + c.kind.spelling
                    + "' belongs to lit scenes, and this scene is drawn depth-cued");
        }
    }

    /** The command's own colours, or null; notes the first line whose colours were clamped. */
    private double[] colours(Command c) {
        if (c.clamped && firstClamped == null) {
            firstClamped = files.current().file().getFileName() + ":" + files.current().lineNumber();
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

    /** From now on primitives go to {@code to} instead of being drawn at once. */
    void sendTo(PrimitiveSink to) {
        geometry.sendTo(to);
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

    /** Where a vertex colour outside [0, 1] was first clamped, as "file:line"; null when none was. */
    public String firstClamped() {
        return firstClamped;
    }

    /** Primitives skipped because they lie wholly outside one plane of the view volume. */
    public long culledCount() {
        return geometry.culledCount();
    }
}
