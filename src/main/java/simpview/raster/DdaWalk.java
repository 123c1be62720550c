package simpview.raster;

/**
 * The course's DDA (SPEC Part 1, "Lines"): the minor coordinate starts at the
 * start pixel's, adds the slope once per step and is rounded half up,
 * {@code floor(v + 0.5)}, at each pixel.
 *
 * <p>When the line starts off the surface, the steps before the first visible
 * one are added up too (so a clipped line has the same pixels as the whole
 * one), unless there are more than {@value #MAX_ADDED_SKIP} of them: then the
 * minor coordinate jumps there by one multiplication, which may differ from
 * the sum in the last bit.
 *
 * <p>A walk may be kept to a window of rows ({@link #rows}, a band drawn by
 * one thread): it then visits exactly the pixels of the whole walk that lie
 * on those rows. A line along y starts at the window's first row, the steps
 * before it added one by one after the jump above (if any), so its minor
 * coordinate there has the same bits; a line along x stops once its rounded
 * y, which only ever moves one way, has left the window.
 */
public final class DdaWalk implements LineWalk {

    /** Above this many hidden steps the walk jumps instead of adding. */
    static final int MAX_ADDED_SKIP = 1 << 20;

    /** The rows visited: rowFrom &lt;= y &lt; rowTo. */
    private int rowFrom;
    private int rowTo = Integer.MAX_VALUE;
    /** The minor coordinates visited: minorFrom &lt;= m &lt; minorTo. */
    private int minorFrom;
    private int minorTo;
    private boolean xMajor;
    private boolean reversed;
    private int minorLimit;
    private int major;
    private int remaining;
    private double minor;
    private double slope;
    /** The start's major coordinate and the number of steps in all, halved (so they stay finite). */
    private double halfStart;
    private double halfSteps;
    private boolean first;
    private int x;
    private int y;
    private double t;

    /** From now on only rows from &lt;= y &lt; to are visited (a band's); all rows by default. */
    public void rows(int from, int to) {
        rowFrom = from;
        rowTo = to;
    }

    @Override
    public boolean start(double px, double py, double qx, double qy, int width, int height) {
        if (!Double.isFinite(px) || !Double.isFinite(py) || !Double.isFinite(qx) || !Double.isFinite(qy)) {
            return false;
        }
        // Pixel indices as doubles: endpoints may lie far beyond int range.
        double x0 = Math.floor(px + 0.5);
        double y0 = Math.floor(py + 0.5);
        double x1 = Math.floor(qx + 0.5);
        double y1 = Math.floor(qy + 0.5);
        xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        reversed = xMajor ? x1 < x0 : y1 < y0;
        double major0 = xMajor ? (reversed ? x1 : x0) : (reversed ? y1 : y0);
        double major1 = xMajor ? (reversed ? x0 : x1) : (reversed ? y0 : y1);
        double minor0 = xMajor ? (reversed ? y1 : y0) : (reversed ? x1 : x0);
        double minor1 = xMajor ? (reversed ? y0 : y1) : (reversed ? x0 : x1);
        int majorLimit = xMajor ? width : height;
        minorLimit = xMajor ? height : width;
        double lo = Math.max(major0, 0);
        double hi = Math.min(major1, majorLimit - 1);
        // Along y, the window's rows clip the major axis; the steps up to its first row are added below.
        double windowLo = xMajor ? lo : Math.max(lo, rowFrom);
        if (!xMajor) {
            hi = Math.min(hi, (double) rowTo - 1);
        }
        if (windowLo > hi) {
            return false;
        }
        minorFrom = xMajor ? Math.max(rowFrom, 0) : 0;
        minorTo = xMajor ? Math.min(rowTo, minorLimit) : minorLimit;
        // Halves keep the differences finite for any finite ends; scaling by a
        // power of two is exact, so the quotients are the same bits as unhalved.
        halfStart = 0.5 * major0;
        halfSteps = 0.5 * major1 - halfStart;
        slope = halfSteps == 0 ? 0 : (0.5 * minor1 - 0.5 * minor0) / halfSteps;
        double skip = lo - major0;
        minor = minor0;
        if (skip <= MAX_ADDED_SKIP) {
            for (int n = 0; n < skip; n++) {
                minor += slope;
            }
        } else {
            minor = minor0 + slope * skip;
        }
        for (double n = lo; n < windowLo; n++) {
            minor += slope;
        }
        major = (int) windowLo;
        remaining = (int) (hi - windowLo) + 1;
        first = true;
        return true;
    }

    @Override
    public boolean next() {
        while (remaining > 0) {
            if (first) {
                first = false;
            } else {
                major++;
                minor += slope;
            }
            remaining--;
            double m = Math.floor(minor + 0.5);
            if (m >= minorFrom && m < minorTo) {
                x = xMajor ? major : (int) m;
                y = xMajor ? (int) m : major;
                t = halfSteps == 0 ? 0 : (0.5 * major - halfStart) / halfSteps;
                return true;
            }
            if (xMajor && (slope >= 0 && m >= minorTo || slope <= 0 && m < minorFrom)) {
                remaining = 0; // y has left the window for good
            }
        }
        return false;
    }

    @Override
    public int x() {
        return x;
    }

    @Override
    public int y() {
        return y;
    }

    @Override
    public double t() {
        return t;
    }

    @Override
    public boolean reversed() {
        return reversed;
    }
}
