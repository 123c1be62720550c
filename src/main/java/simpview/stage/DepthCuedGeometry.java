package simpview.stage;

import simpview.geometry.Camera;
import simpview.geometry.Clipper;
import simpview.geometry.Matrix4;
import simpview.geometry.Vertex;

/**
 * The geometry stage of a depth-cued scene (SPEC Part 1), top to bottom:
 * object space -> world space by the CTM (world space is camera space: Part 1
 * has no camera) -> culled when wholly outside one plane of the parallel view
 * -> projected onto the panel -> handed to the sink. Nothing is clipped here:
 * the scissor in the drawable chain drops what lies outside, pixel by pixel.
 *
 * <p>Reuses its scratch arrays: nothing is allocated per primitive.
 */
public final class DepthCuedGeometry implements GeometryStage {

    private static final Camera VIEW = Camera.PARALLEL;

    private PrimitiveSink sink;
    /** Camera-space (= world-space) positions of the primitive at hand, x, y, z each. */
    private final double[] camera = new double[3 * 3];
    /** The same in panel space with colours, as the painter takes them. */
    private final double[] panel = new double[Painter.STRIDE];
    private long culled;
    /** The planes every culled primitive lies wholly outside of (see {@link #culledOutside}). */
    private int culledOutside;
    private long primitives;
    /**
     * Primitives not culled that lie wholly outside the view round one of its corners, a pixel or more from
     * it: drawn, and every pixel of theirs dropped by the scissor. Told, never clipped: the clipper only looks.
     */
    private long roundACorner;
    /** The sides every one of those reaches beyond (see {@link #clippedAwayOutside}). */
    private int roundACornerOutside;
    /**
     * Whether a primitive has been found that reaches the view: then the scene cannot have drawn nothing, the
     * only case in which {@link #roundACorner} is told, and no more primitives are looked at for it.
     */
    private boolean someReachTheView;
    private final Clipper looker = new Clipper(3);
    /** Primitives not drawn because a vertex of theirs is not finite in camera space, or on the panel. */
    private long nonFinite;
    /** Whether the first of those was finite in camera space and overflowed on its way to the panel. */
    private boolean firstBeyondPanel;
    /** Told of the primitives culled (the inspector), or null. */
    private PrimitiveTrace trace;

    public DepthCuedGeometry(PrimitiveSink sink) {
        this.sink = sink;
    }

    @Override
    public void line(Matrix4 ctm, double[] xyz, double[] rgb) {
        draw(Painter.LINE, ctm, xyz, rgb, 2);
    }

    @Override
    public void polygon(Matrix4 ctm, double[] xyz, double[] rgb, boolean wire) {
        draw(wire ? Painter.WIRE : Painter.FILLED, ctm, xyz, rgb, 3);
    }

    /**
     * Object -> world (= camera) -> cull -> project -> sink; a vertex without
     * a colour is white. A primitive with a vertex the CTM takes beyond the
     * doubles (finite numbers and a finite CTM can still overflow) is not
     * drawn, and counted: the scene warns of it.
     */
    private void draw(int kind, Matrix4 ctm, double[] xyz, double[] rgb, int count) {
        primitives++;
        if (!toCamera(ctm, xyz, count)) {
            nonFinite++;
            return;
        }
        int outside = VIEW.outsideEvery(camera, 3, count);
        if (outside != 0) {
            culledOutside = culled++ == 0 ? outside : culledOutside & outside;
            if (trace != null) {
                trace.skipped(null, 0, kind, true, camera, 0, 3, count);
            }
            return;
        }
        noteRoundACorner(count);
        project(rgb, count);
        if (!onPanel(kind, count)) {
            firstBeyondPanel |= nonFinite++ == 0;
            return;
        }
        sink.add(kind, panel);
    }

    /**
     * Counts the primitive at hand, not culled, when it misses the view
     * grown by a pixel ({@link Camera#PARALLEL_AND_A_PIXEL}): a polygon whose
     * box overlaps a corner of the panel but whose edge passes outside it
     * writes no pixel there, as a culled one does not. Only one with a vertex
     * outside the view is clipped to see: most have none.
     */
    private void noteRoundACorner(int count) {
        if (someReachTheView) {
            return;
        }
        int reaches = VIEW.outsideAny(camera, 3, count);
        if (reaches == 0) {
            someReachTheView = true;
            return;
        }
        Camera grown = Camera.PARALLEL_AND_A_PIXEL;
        boolean missed = count == 2 ? !looker.clipLine(grown, camera, 0, 3)
                : looker.clipPolygon(grown, camera, 0, 3) < 3;
        if (missed) {
            roundACornerOutside = roundACorner++ == 0 ? reaches : roundACornerOutside & reaches;
        } else {
            someReachTheView = true;
        }
    }

    /**
     * Whether the rasterizers can take the primitive just projected: its
     * panel x and y finite (a vertex beyond about 2.7e305 overflows the
     * panel's scale) and, filled, twice its area there too (the fill rule's
     * test, whose products overflow for a triangle some 1e154 across), so
     * that what they would drop without a word is counted instead.
     */
    private boolean onPanel(int kind, int count) {
        int n = Vertex.NUMBERS;
        double sum = 0;
        for (int k = 0; k < count; k++) {
            sum += panel[n * k + Vertex.X] + panel[n * k + Vertex.Y];
        }
        if (!Double.isFinite(sum) && !GeometryStage.allFinite(panel, n, count)) {
            return false;
        }
        if (kind != Painter.FILLED) {
            return true;
        }
        double x1 = panel[Vertex.X];
        double y1 = panel[Vertex.Y];
        double doubleArea = (panel[n + Vertex.X] - x1) * (panel[2 * n + Vertex.Y] - y1)
                - (panel[n + Vertex.Y] - y1) * (panel[2 * n + Vertex.X] - x1);
        return Double.isFinite(doubleArea);
    }

    /** The vertices to camera space; false when one of them is not finite there. */
    private boolean toCamera(Matrix4 ctm, double[] p, int count) {
        double sum = 0;
        for (int k = 0; k < 3 * count; k += 3) {
            double x = p[k];
            double y = p[k + 1];
            double z = p[k + 2];
            double cx = ctm.applyX(x, y, z);
            double cy = ctm.applyY(x, y, z);
            double cz = ctm.applyZ(x, y, z);
            camera[k] = cx;
            camera[k + 1] = cy;
            camera[k + 2] = cz;
            sum += cx + cy + cz;
        }
        return Double.isFinite(sum) || GeometryStage.allFinite(camera, 3, count);
    }

    /** Panel x and y, depth kept, each vertex with its own colour or white. */
    private void project(double[] rgb, int count) {
        for (int k = 0; k < count; k++) {
            int i = 3 * k;
            int o = Vertex.NUMBERS * k;
            double z = camera[i + 2];
            panel[o + Vertex.X] = VIEW.panelX(camera[i], z);
            panel[o + Vertex.Y] = VIEW.panelY(camera[i + 1], z);
            panel[o + Vertex.Z] = z;
            panel[o + Vertex.R] = rgb == null ? 1 : rgb[i];
            panel[o + Vertex.G] = rgb == null ? 1 : rgb[i + 1];
            panel[o + Vertex.B] = rgb == null ? 1 : rgb[i + 2];
        }
    }

    /** From now on tells {@code follower} of every primitive culled (null: nobody). */
    public void follow(PrimitiveTrace follower) {
        trace = follower;
    }

    /** From now on primitives go to {@code to}. */
    public void sendTo(PrimitiveSink to) {
        sink = to;
    }

    @Override
    public long culledCount() {
        return culled;
    }

    @Override
    public int culledOutside() {
        return culledOutside;
    }

    /**
     * Primitives not culled that lie round a corner of the view, a pixel or more outside it: none of them shows.
     * Counted only until a primitive is found that reaches the view, when the count can no longer be told.
     */
    @Override
    public long clippedAwayCount() {
        return roundACorner;
    }

    @Override
    public int clippedAwayOutside() {
        return roundACornerOutside;
    }

    @Override
    public long nonFiniteCount() {
        return nonFinite;
    }

    /**
     * Whether the first primitive {@link #nonFiniteCount} counted was finite
     * after the transforms and overflowed only on its way to the panel.
     */
    public boolean firstBeyondPanel() {
        return firstBeyondPanel;
    }

    @Override
    public long primitiveCount() {
        return primitives;
    }
}
