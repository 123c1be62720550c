package simpview.raster;

/**
 * The pixels of one line, one at a time, without allocating: {@link #start}
 * a line between two panel-space points, then {@link #next} until it says
 * false, reading each pixel's place and its parameter along the line.
 *
 * <p>Both walks round each endpoint to the nearest pixel, {@code floor(v +
 * 0.5)}, and go from the end with the smaller x (an x-major line, |dx| >=
 * |dy|) or the smaller y (a y-major one), one pixel per step along the major
 * axis, both end pixels included; they differ only in how they choose the
 * minor coordinate. Only the pixels on the {@code width x height} surface are
 * visited, so a line a billion pixels long costs no more than one across it.
 * A walk keeps its state between calls: one walk serves one thread.
 */
public interface LineWalk {

    /**
     * Begins the line from (px, py) to (qx, qy) on a width x height surface;
     * false when none of its pixels lies on it (or a coordinate is not finite).
     */
    boolean start(double px, double py, double qx, double qy, int width, int height);

    /** Moves to the next pixel on the surface; false when the line is done. */
    boolean next();

    /** The current pixel's column. */
    int x();

    /** The current pixel's row. */
    int y();

    /**
     * The current pixel's parameter from the walk's start (0) to its end (1):
     * steps taken / steps in all; 0 for a one-pixel line.
     */
    double t();

    /** True when the walk starts at the line's second point (q) and ends at its first (p). */
    boolean reversed();
}
