package simpview.geometry;

/**
 * The view: which camera-space points are seen, and where on the 650x650
 * panel each lands. Two kinds:
 * <ul>
 * <li>{@link #PARALLEL}, Part 1's view volume: -100 &lt;= x, y &lt;= 100,
 *     -200 &lt;= z &lt;= 0, x and y mapped linearly onto the panel, z kept for
 *     depth only;</li>
 * <li>{@link #perspective}: the SIMP {@code camera} command. The eye at the
 *     origin looks down -z; the window [xlow, xhigh] x [ylow, yhigh] lies on
 *     the plane z = -1; the near plane is z = hither, the far plane z = yon.
 *     A point lands on the window at (x / -z, y / -z).</li>
 * </ul>
 * Both map window coordinates to panel pixels with one rule: the window
 * becomes a rectangle of its own aspect, as large as fits, centred:
 * {@code px = offsetX + (x' - xlow) * 650 / extent}, extent the larger side.
 * For the parallel view the offset is 0 and the expression is Part 1's
 * {@code (x + 100) * 650 / 200} to the bit.
 *
 * <p>The six planes, each with a signed distance that is {@code >= 0} inside,
 * are numbered in clipping order: {@link #HITHER}, {@link #YON}, {@link #LEFT},
 * {@link #RIGHT}, {@link #BOTTOM}, {@link #TOP}.
 */
public final class Camera {

    public static final int PANEL_SIZE = 650;
    public static final int HITHER = 0;
    public static final int YON = 1;
    public static final int LEFT = 2;
    public static final int RIGHT = 3;
    public static final int BOTTOM = 4;
    public static final int TOP = 5;
    public static final int PLANES = 6;

    /** Part 1's view: the box -100..100 x -100..100 x -200..0, parallel projection. */
    public static final Camera PARALLEL = new Camera(false, -100, -100, 100, 100, 0, -200);

    /**
     * Part 1's view grown by one pixel of the panel (200 / 650) on each of its four sides: a depth-cued
     * primitive that misses this box writes no pixel of the panel, as a line's rounded ends and DDA steps stray
     * less than a pixel from it. For telling whether something can show, never for projecting.
     */
    public static final Camera PARALLEL_AND_A_PIXEL = new Camera(false, -100 - 200.0 / PANEL_SIZE,
            -100 - 200.0 / PANEL_SIZE, 100 + 200.0 / PANEL_SIZE, 100 + 200.0 / PANEL_SIZE, 0, -200);

    private final boolean perspective;
    private final double xlow;
    private final double ylow;
    private final double xhigh;
    private final double yhigh;
    private final double hither;
    private final double yon;
    private final double extent;
    private final double offsetX;
    private final double offsetY;

    private Camera(boolean perspective, double xlow, double ylow, double xhigh, double yhigh,
            double hither, double yon) {
        this.perspective = perspective;
        this.xlow = xlow;
        this.ylow = ylow;
        this.xhigh = xhigh;
        this.yhigh = yhigh;
        this.hither = hither;
        this.yon = yon;
        double width = xhigh - xlow;
        double height = yhigh - ylow;
        extent = Math.max(width, height);
        double s = PANEL_SIZE / extent;
        offsetX = (PANEL_SIZE - s * width) / 2;
        offsetY = (PANEL_SIZE - s * height) / 2;
    }

    /**
     * The camera of a {@code camera xlow ylow xhigh yhigh hither yon} command.
     *
     * @throws IllegalArgumentException unless xlow &lt; xhigh, ylow &lt; yhigh and 0 &gt; hither &gt; yon
     */
    public static Camera perspective(double xlow, double ylow, double xhigh, double yhigh,
            double hither, double yon) {
        Problem problem = problem(xlow, ylow, xhigh, yhigh, hither, yon);
        if (problem != null) {
            throw new IllegalArgumentException(problem.words());
        }
        return new Camera(true, xlow, ylow, xhigh, yhigh, hither, yon);
    }

    /**
     * What is wrong with a camera's numbers.
     *
     * @param number the first number at fault, from 0 (xlow, ylow, xhigh, yhigh, hither, yon)
     */
    public record Problem(int number, String words) {
    }

    /** What is wrong with these camera numbers, or null when they make a camera. */
    public static Problem problem(double xlow, double ylow, double xhigh, double yhigh, double hither,
            double yon) {
        if (!(xlow < xhigh)) {
            return new Problem(0, "the window needs xlow < xhigh, found " + xlow + " and " + xhigh);
        }
        if (!(ylow < yhigh)) {
            return new Problem(1, "the window needs ylow < yhigh, found " + ylow + " and " + yhigh);
        }
        if (!(0 > hither && hither > yon)) {
            return new Problem(0 > hither ? 5 : 4,
                    "the planes need 0 > hither > yon, found hither " + hither + " and yon " + yon
                            + planesHint(hither, yon));
        }
        if (!Double.isFinite(PANEL_SIZE / Math.max(xhigh - xlow, yhigh - ylow))) {
            return new Problem(0, "the window is too small or too large to map onto the panel");
        }
        return null;
    }

    /**
     * What a hither and yon that are not 0 &gt; hither &gt; yon most likely
     * meant: distances in front of the eye, as OpenGL's near and far are
     * given (both above 0); the two planes swapped; a near plane at the eye.
     */
    private static String planesHint(double hither, double yon) {
        if (hither > 0 && yon > hither) {
            return ": they are z values, and the camera looks down its -z axis, so what it sees has z below 0;"
                    + " as distances in front of it they are hither " + written(-hither) + " and yon " + written(-yon);
        }
        if (yon > hither && hither < 0) {
            return ": hither is the near plane and yon the far one, further below 0: swap them";
        }
        if (hither == 0 && yon < 0) {
            return ": hither 0 is the eye itself, where nothing can be projected; give it a small number below 0,"
                    + " such as -0.1";
        }
        return "";
    }

    /** A number as a scene file writes it, for messages: -100, not -100.0. */
    public static String written(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    public boolean isPerspective() {
        return perspective;
    }

    /** The near plane's z: nothing nearer (greater z) is seen. */
    public double hither() {
        return hither;
    }

    /** The far plane's z: nothing farther (smaller z) is seen. */
    public double yon() {
        return yon;
    }

    /** Panel x of the camera-space point (x, ?, z); z matters only in perspective. */
    public double panelX(double x, double z) {
        double onWindow = perspective ? x / -z : x;
        return offsetX + (onWindow - xlow) * PANEL_SIZE / extent;
    }

    /** Panel y of the camera-space point (?, y, z). */
    public double panelY(double y, double z) {
        double onWindow = perspective ? y / -z : y;
        return offsetY + (onWindow - ylow) * PANEL_SIZE / extent;
    }

    /**
     * The window x that panel x stands for, panelX's map undone: in
     * perspective the x / -z of every camera-space point that lands there, in
     * the parallel view x itself.
     */
    public double windowX(double panelX) {
        return xlow + (panelX - offsetX) * extent / PANEL_SIZE;
    }

    /** The window y that panel y stands for (see {@link #windowX}). */
    public double windowY(double panelY) {
        return ylow + (panelY - offsetY) * extent / PANEL_SIZE;
    }

    /**
     * Where the window lies on the panel: its left, bottom, right and top
     * edges in panel coordinates (the whole panel along its longer side,
     * centred along the other). Pixels whose centres lie outside it show
     * nothing of the scene.
     */
    public double[] windowOnPanel() {
        double s = PANEL_SIZE / extent;
        return new double[] {offsetX, offsetY, offsetX + s * (xhigh - xlow), offsetY + s * (yhigh - ylow)};
    }

    /**
     * 1/w of a camera-space depth: the quantity that is affine in screen space,
     * 1 / -z in perspective and 1 in the parallel view. Attributes are
     * interpolated as a * q and divided by q at each pixel.
     */
    public double q(double z) {
        return perspective ? 1 / -z : 1;
    }

    /**
     * True when (x, y, z) is inside every plane: each {@link #distance}, the
     * same expressions, {@code >= 0} (so NaN is never inside). One call for
     * the clipper's common case, a vertex in view.
     */
    public boolean inside(double x, double y, double z) {
        double w = perspective ? -z : 1;
        return hither - z >= 0 && z - yon >= 0 && x - xlow * w >= 0 && xhigh * w - x >= 0
                && y - ylow * w >= 0 && yhigh * w - y >= 0;
    }

    /** The signed distance of (x, y, z) to plane {@code plane}: {@code >= 0} inside the view. */
    public double distance(int plane, double x, double y, double z) {
        double w = perspective ? -z : 1;
        return switch (plane) {
            case HITHER -> hither - z;
            case YON -> z - yon;
            case LEFT -> x - xlow * w;
            case RIGHT -> xhigh * w - x;
            case BOTTOM -> y - ylow * w;
            case TOP -> yhigh * w - y;
            default -> throw new IllegalArgumentException("plane " + plane);
        };
    }

    /**
     * The planes (x, y, z) is outside of, one bit per plane ({@code 1 << plane});
     * NaN is outside none. For the parallel view these are Part 1's tests.
     * A point behind the eye (z &gt; 0) in perspective can be outside both
     * side planes of a pair, left and right (or bottom and top): each plane
     * passes through the eye, and behind it their inside half-spaces cross,
     * so (0.02, 0, 1) under the window [-1, 1] is outside all four. Each
     * plane is tested on its own, as {@link #distance} measures it.
     */
    public int outcode(double x, double y, double z) {
        double w = perspective ? -z : 1;
        int code = 0;
        if (z > hither) {
            code |= 1 << HITHER;
        } else if (z < yon) {
            code |= 1 << YON;
        }
        if (x < xlow * w) {
            code |= 1 << LEFT;
        }
        if (x > xhigh * w) {
            code |= 1 << RIGHT;
        }
        if (y < ylow * w) {
            code |= 1 << BOTTOM;
        }
        if (y > yhigh * w) {
            code |= 1 << TOP;
        }
        return code;
    }

    /**
     * Culling: true when the first {@code count} vertices of {@code p} (camera
     * space, {@code stride} numbers each, x, y, z first) are all outside one and
     * the same plane, so that the primitive cannot touch the view.
     */
    public boolean culls(double[] p, int stride, int count) {
        return outsideEvery(p, stride, count) != 0;
    }

    /**
     * The planes (bits 1 &lt;&lt; {@link #HITHER} ...) that every one of the
     * first {@code count} vertices of {@code p} is outside of; 0 when there is
     * none, and the primitive is not culled.
     */
    public int outsideEvery(double[] p, int stride, int count) {
        int common = ~0;
        for (int k = 0; k < count && common != 0; k++) {
            int o = k * stride;
            common &= outcode(p[o], p[o + 1], p[o + 2]);
        }
        return common;
    }

    /**
     * The planes (bits 1 &lt;&lt; {@link #HITHER} ...) that one or more of the
     * first {@code count} vertices of {@code p} is outside of; 0 when every
     * vertex is in view. Of a primitive not culled, these are the sides of
     * the view it reaches beyond: the corner it lies round, when the clipper
     * leaves nothing of it. In perspective a vertex nearer than the near
     * plane counts for that plane alone: behind the eye the side planes'
     * outside half-spaces cross (see {@link #outcode}), so its side bits say
     * nothing of where it is.
     */
    public int outsideAny(double[] p, int stride, int count) {
        int any = 0;
        for (int k = 0; k < count; k++) {
            int o = k * stride;
            int code = outcode(p[o], p[o + 1], p[o + 2]);
            any |= perspective && (code & 1 << HITHER) != 0 ? 1 << HITHER : code;
        }
        return any;
    }

    /** The depth cue's weight of the near colour: 0 at the far plane, 1 at the near plane. */
    public double nearness(double z) {
        return (z - yon) / (hither - yon);
    }

    @Override
    public String toString() {
        return (perspective ? "perspective" : "parallel") + " camera [" + xlow + ", " + xhigh + "] x ["
                + ylow + ", " + yhigh + "], z from " + hither + " to " + yon;
    }
}
