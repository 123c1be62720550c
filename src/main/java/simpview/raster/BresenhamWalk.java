package simpview.raster;

import java.math.BigInteger;

/**
 * Bresenham's line: the integer midpoint algorithm of the first octant, with
 * the any-octant transform for the rest (the major axis and the minor
 * direction swapped or mirrored into it), from the same start endpoint as the
 * {@link DdaWalk}. At each step a decision variable says on which side of the
 * line the midpoint between the two candidate pixels lies; at an exact tie
 * (the midpoint on the line) it steps the minor coordinate when
 * {@code stepAtTie}, else keeps it.
 *
 * <p>Rounded endpoints must lie within 2^60 of the origin; a line with an end
 * beyond that draws nothing.
 */
public final class BresenhamWalk implements LineWalk {

    private static final double LIMIT = 0x1p60;

    private final boolean stepAtTie;
    private boolean xMajor;
    private boolean reversed;
    private int minorLimit;
    private int major;
    private int remaining;
    private long minor;
    private long direction;
    private long decision;
    private long twiceMinorSpan;
    private long twiceMajorSpan;
    private double halfStart;
    private double halfSteps;
    private boolean first;
    private int x;
    private int y;
    private double t;

    /** A walk that, at an exact tie, steps the minor coordinate (true) or keeps it (false). */
    public BresenhamWalk(boolean stepAtTie) {
        this.stepAtTie = stepAtTie;
    }

    @Override
    public boolean start(double px, double py, double qx, double qy, int width, int height) {
        double x0 = Math.floor(px + 0.5);
        double y0 = Math.floor(py + 0.5);
        double x1 = Math.floor(qx + 0.5);
        double y1 = Math.floor(qy + 0.5);
        if (!(Math.abs(x0) <= LIMIT && Math.abs(y0) <= LIMIT && Math.abs(x1) <= LIMIT && Math.abs(y1) <= LIMIT)) {
            return false;
        }
        xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        reversed = xMajor ? x1 < x0 : y1 < y0;
        long major0 = (long) (xMajor ? (reversed ? x1 : x0) : (reversed ? y1 : y0));
        long major1 = (long) (xMajor ? (reversed ? x0 : x1) : (reversed ? y0 : y1));
        long minor0 = (long) (xMajor ? (reversed ? y1 : y0) : (reversed ? x1 : x0));
        long minor1 = (long) (xMajor ? (reversed ? y0 : y1) : (reversed ? x0 : x1));
        int majorLimit = xMajor ? width : height;
        minorLimit = xMajor ? height : width;
        long lo = Math.max(major0, 0);
        long hi = Math.min(major1, majorLimit - 1L);
        if (lo > hi) {
            return false;
        }
        long span = major1 - major0;
        long minorSpan = Math.abs(minor1 - minor0);
        direction = minor1 >= minor0 ? 1 : -1;
        twiceMajorSpan = 2 * span;
        twiceMinorSpan = 2 * minorSpan;
        long skip = lo - major0;
        long steps = span == 0 ? 0 : offsetAt(skip, span, minorSpan);
        minor = minor0 + direction * steps;
        // The decision for the step after this one: 2 (k + 1) dy - 2 dx m - dx, wrapping
        // arithmetic giving the exact value, which is small (|d| <= 2 dx + 2 dy).
        decision = (skip + 1) * twiceMinorSpan - steps * twiceMajorSpan - span;
        halfStart = 0.5 * major0;
        halfSteps = 0.5 * major1 - halfStart;
        major = (int) lo;
        remaining = (int) (hi - lo) + 1;
        first = true;
        return true;
    }

    /**
     * How many minor steps the midpoint walk has taken after k major steps:
     * k dy / dx rounded to the nearest integer, ties as {@code stepAtTie} says,
     * {@code floor((2 k dy + dx - (stepAtTie ? 0 : 1)) / (2 dx))}.
     */
    private long offsetAt(long k, long dx, long dy) {
        long tie = stepAtTie ? 0 : 1;
        long high = Math.multiplyHigh(2 * k, dy);
        long low = 2 * k * dy;
        if (high == 0 && low >= 0 && low <= Long.MAX_VALUE - dx) {
            return Math.floorDiv(low + dx - tie, 2 * dx);
        }
        BigInteger n = BigInteger.valueOf(k).multiply(BigInteger.valueOf(2 * dy))
                .add(BigInteger.valueOf(dx - tie));
        return n.divide(BigInteger.valueOf(2 * dx)).longValueExact();
    }

    @Override
    public boolean next() {
        while (remaining > 0) {
            if (first) {
                first = false;
            } else {
                major++;
                if (decision > 0 || decision == 0 && stepAtTie) {
                    minor += direction;
                    decision -= twiceMajorSpan;
                }
                decision += twiceMinorSpan;
            }
            remaining--;
            if (minor >= 0 && minor < minorLimit) {
                x = xMajor ? major : (int) minor;
                y = xMajor ? (int) minor : major;
                t = halfSteps == 0 ? 0 : (0.5 * major - halfStart) / halfSteps;
                return true;
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
