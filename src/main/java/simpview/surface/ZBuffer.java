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
 *
 * <p>Beside the depths, a floor for each run of {@link #SEGMENT} pixels of a
 * row (its segment): a depth that no pixel of the segment is farther than.
 * Every writer only ever makes a depth nearer (the depth test lets nothing
 * else through), so a floor once true stays true until the reset, which sets
 * every floor to the far plane with the depths. {@link ZBufferDrawable} raises
 * a segment's floor when one run of winners covers the segment whole, and
 * skips the part of a span over a segment that its depths at both ends do not
 * rise above (the depth along a span is monotone in x): no pixel there could
 * win. Nothing else reads or writes the floors.
 */
public final class ZBuffer {

    /** Pixels per segment of a row: 1 << {@link #SEGMENT_SHIFT}. */
    static final int SEGMENT = 16;
    static final int SEGMENT_SHIFT = 4;

    private final int width;
    private final int height;
    final double[] depth;
    /** Segments per row: the last one may be short. */
    final int segments;
    /** The floor of segment s of row y at y * segments + s. */
    final double[] floor;
    /** True only while every entry is {@link #resetTo}. */
    private boolean atFarPlane;
    private double resetTo = Double.NaN;

    public ZBuffer(int width, int height) {
        this.width = width;
        this.height = height;
        this.depth = new double[width * height];
        this.segments = (width + SEGMENT - 1) >> SEGMENT_SHIFT;
        this.floor = new double[segments * height];
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
            Arrays.fill(floor, farthest);
            resetTo = farthest;
            atFarPlane = true;
        }
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
