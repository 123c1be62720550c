package simpview.raster;

import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * Bresenham's line: the midpoint algorithm of the first octant, with the
 * any-octant transform for the rest (the major axis and the minor direction
 * swapped or mirrored into it), from the same start endpoint as the {@link
 * DdaWalk} (the smaller rounded major coordinate). Every end is rounded,
 * {@code floor(v + 0.5)}; the rounded major coordinates give the pixels'
 * count and the start pixel. Which line the decisions are taken on is the
 * walk's one choice:
 * <ul>
 * <li>{@link #integer()}, SPEC Part 3's words: the line through the rounded
 *     ends, the integer midpoint algorithm ({@code 2 dy - dx}, {@code +2 dy},
 *     {@code -2 dx}, integers held exactly in doubles); both end pixels are
 *     the rounded endpoints;</li>
 * <li>{@link #throughGivenMinor()}, as the course's own picture of its page 1
 *     panel 2 shows its program drawing: the line through the ends' minor
 *     coordinates <em>as given</em> (over the rounded major span). On integer
 *     endpoints the two are the same walk.</li>
 * </ul>
 * At each step the decision variable, in units of 1/(2 dx), says on which
 * side of the line the midpoint between the two candidate pixels lies: it
 * starts at {@code 2 dx f + 2 dy - dx}, f the start's minor offset from its
 * pixel (in the first octant's direction; 0 for the integer walk), adds
 * {@code 2 dy} per step and gives {@code 2 dx} back at a minor step. At an
 * exact tie (the midpoint on the line) the walk keeps the minor coordinate,
 * on the start's side, as the course's picture does at its five ties (on the
 * 60-degree spoke, whose end is x = 217.5: through the given minor
 * coordinates the end pixel is then (217, 267), not the rounded (218, 267)).
 *
 * <p>When the line starts off the surface, the hidden steps are taken too (so
 * a clipped line has the same pixels as the whole one), unless there are more
 * than {@value #MAX_STEPPED_SKIP}: then the walk jumps there by the closed
 * form, evaluated exactly on the same numbers, which is the stepping's result
 * whenever the stepping is exact (integer ends). Rounded endpoints must lie
 * within 2^50 of the origin, so that the integer case stays exact; a line
 * with an end beyond that draws nothing.
 */
public final class BresenhamWalk implements LineWalk {

    private static final double LIMIT = 0x1p50;
    /** Above this many hidden steps the walk jumps instead of stepping. */
    static final int MAX_STEPPED_SKIP = 1 << 20;

    private final boolean givenMinor;
    private boolean xMajor;
    private boolean reversed;
    private int minorLimit;
    private int major;
    private int remaining;
    private long minor;
    private long direction;
    /** The decision for the next step: 2 dx (the line's minor offset at the next column - the pixel's - 1/2). */
    private double decision;
    private double twiceRise;
    private double twiceSpan;
    private double halfStart;
    private double halfSteps;
    private boolean first;
    private int x;
    private int y;
    private double t;

    private BresenhamWalk(boolean givenMinor) {
        this.givenMinor = givenMinor;
    }

    /** SPEC Part 3's Bresenham: the integer midpoint algorithm on the rounded ends. */
    public static BresenhamWalk integer() {
        return new BresenhamWalk(false);
    }

    /** The course's program's Bresenham: decisions on the line through the ends' minor coordinates as given. */
    public static BresenhamWalk throughGivenMinor() {
        return new BresenhamWalk(true);
    }

    /** Whether the decisions are taken on the ends' given minor coordinates (else on the rounded ones). */
    public boolean givenMinor() {
        return givenMinor;
    }

    @Override
    public boolean start(double px, double py, double qx, double qy, int width, int height) {
        double x0 = Math.floor(px + 0.5);
        double y0 = Math.floor(py + 0.5);
        double x1 = Math.floor(qx + 0.5);
        double y1 = Math.floor(qy + 0.5);
        // Also false for NaN.
        if (!(Math.abs(x0) <= LIMIT && Math.abs(y0) <= LIMIT && Math.abs(x1) <= LIMIT && Math.abs(y1) <= LIMIT)) {
            return false;
        }
        xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        reversed = xMajor ? x1 < x0 : y1 < y0;
        long major0 = (long) (xMajor ? (reversed ? x1 : x0) : (reversed ? y1 : y0));
        long major1 = (long) (xMajor ? (reversed ? x0 : x1) : (reversed ? y0 : y1));
        double minorStart = givenMinor ? (xMajor ? (reversed ? qy : py) : (reversed ? qx : px))
                : (xMajor ? (reversed ? y1 : y0) : (reversed ? x1 : x0));
        double minorEnd = givenMinor ? (xMajor ? (reversed ? py : qy) : (reversed ? px : qx))
                : (xMajor ? (reversed ? y0 : y1) : (reversed ? x0 : x1));
        long minor0 = (long) (xMajor ? (reversed ? y1 : y0) : (reversed ? x1 : x0));
        int majorLimit = xMajor ? width : height;
        minorLimit = xMajor ? height : width;
        long lo = Math.max(major0, 0);
        long hi = Math.min(major1, majorLimit - 1L);
        if (lo > hi) {
            return false;
        }
        long span = major1 - major0;
        direction = minorEnd >= minorStart ? 1 : -1;
        double rise = Math.abs(minorEnd - minorStart);
        // In [-1/2, 1/2]; exact, the pixel being within a half of the coordinate.
        double offset = direction * (minorStart - minor0);
        twiceSpan = 2.0 * span;
        twiceRise = 2 * rise;
        decision = twiceSpan * offset + twiceRise - span;
        minor = minor0;
        long skip = lo - major0;
        if (skip <= MAX_STEPPED_SKIP) {
            for (long n = 0; n < skip; n++) {
                step();
            }
        } else {
            jump(skip, span, offset, rise);
        }
        halfStart = 0.5 * major0;
        halfSteps = 0.5 * major1 - halfStart;
        major = (int) lo;
        remaining = (int) (hi - lo) + 1;
        first = true;
        return true;
    }

    /** One major step's decision: a minor step when the midpoint lies strictly below the line. */
    private void step() {
        if (decision > 0) {
            minor += direction;
            decision -= twiceSpan;
        }
        decision += twiceRise;
    }

    /**
     * Where k steps take the walk, in closed form: the minor steps taken are
     * {@code max(0, ceil((2 dx f + 2 k dy - dx) / (2 dx)))} (the line's offset
     * rounded to the nearest integer, a tie kept), and the decision follows.
     */
    private void jump(long k, long span, double offset, double rise) {
        BigDecimal twiceDx = BigDecimal.valueOf(span).multiply(BigDecimal.valueOf(2));
        BigDecimal twiceDy = new BigDecimal(rise).multiply(BigDecimal.valueOf(2));
        BigDecimal before = twiceDx.multiply(new BigDecimal(offset)).add(twiceDy.multiply(BigDecimal.valueOf(k)))
                .subtract(BigDecimal.valueOf(span));
        long steps = Math.max(0, before.divide(twiceDx, 0, RoundingMode.CEILING).longValueExact());
        minor += direction * steps;
        decision = before.add(twiceDy).subtract(twiceDx.multiply(BigDecimal.valueOf(steps))).doubleValue();
    }

    @Override
    public boolean next() {
        while (remaining > 0) {
            if (first) {
                first = false;
            } else {
                major++;
                step();
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
