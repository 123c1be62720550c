package simpview.surface;

import java.util.Arrays;

/**
 * One depth per pixel (world space for depth-cued scenes, camera space for lit
 * ones); larger z is nearer. Reset to the farthest depth of the picture: the
 * far plane, z = -200, for depth-cued scenes; -infinity for lit ones.
 *
 * <p>Only a {@link ZBufferDrawable} writes the depths, and it says so
 * ({@link #written}) before it returns from a write. So the buffer knows when
 * every entry is still at the far plane, and a reset then costs nothing: the
 * pages that draw without depth (1 and 2) do not pay for filling 3.4 MB.
 */
public final class ZBuffer {

    private final int width;
    private final int height;
    final double[] depth;
    /** True only while every entry is {@link #resetTo}. */
    private boolean atFarPlane;
    private double resetTo = Double.NaN;

    public ZBuffer(int width, int height) {
        this.width = width;
        this.height = height;
        this.depth = new double[width * height];
        reset(-200);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Every entry back to {@code farthest}: -200 for depth-cued pictures, -infinity for lit ones. */
    public void reset(double farthest) {
        if (!atFarPlane || Double.doubleToLongBits(farthest) != Double.doubleToLongBits(resetTo)) {
            Arrays.fill(depth, farthest);
            resetTo = farthest;
            atFarPlane = true;
        }
    }

    /**
     * Every entry is to be {@code farthest}, set row by row by whoever draws
     * each row ({@link #resetRows}) before it tests any: the drawer of a band
     * of rows resets its own, on its own thread, where its drawing will find
     * them in cache.
     */
    public void resetByRows(double farthest) {
        resetTo = farthest;
        atFarPlane = false;
    }

    /** Rows from &lt;= y &lt; to back to the depth {@link #resetByRows} gave. */
    public void resetRows(int from, int to) {
        Arrays.fill(depth, from * width, to * width, resetTo);
    }

    /** The depth every entry had after the last reset. */
    public double farthest() {
        return resetTo;
    }

    /** Some entry may now differ from the far plane. */
    public void written() {
        // Read before written: threads drawing bands call this for every span, and a
        // store each time would pull the line holding it from core to core.
        if (atFarPlane) {
            atFarPlane = false;
        }
    }

    /** The raw depths, row by row from the bottom, for a stage that tests and writes them itself. */
    public double[] depths() {
        return depth;
    }

    /** True when no depth has been written since the last reset. */
    boolean atFarPlane() {
        return atFarPlane;
    }

    /** A copy of every depth, row by row (row y at y * width). */
    public double[] copyDepths() {
        return depth.clone();
    }

    public double depthAt(int x, int y) {
        return depth[y * width + x];
    }
}
