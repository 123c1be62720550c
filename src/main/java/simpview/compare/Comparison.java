package simpview.compare;

import java.util.Objects;

/**
 * Two 650x650 panels compared pixel by pixel. A pixel's distance is the
 * largest difference of one channel (0 to 255). Its distance with slack is
 * the smaller one found when either picture may take its colour from up to
 * {@code deviation} pixels away (dEQP's position deviation; 1 by default):
 * the larger of (ours against the nearest match among theirs' neighbours
 * within that distance, a square) and (theirs against ours' neighbours).
 * Both ways, so a line one pixel off passes and a line missing from either
 * side does not. Deviation 0 makes slack the same as no slack.
 *
 * <p>With the {@link Metric#BLUR} metric the distances are measured between
 * the two panels each blurred by {@link Blur}, so a different antialiasing of
 * the same edge counts as near; {@link #ours()} and {@link #theirs()} stay
 * the pictures as given, for showing.
 *
 * <p>With {@link Metric#FLIP} the shares are still the colour distances (with
 * slack) above, but whether a pixel matches is decided by its {@link Flip}
 * value: at most {@link #FLIP_THRESHOLD}. The verdict's share
 * ({@link #verdictShare}), the failing pixels and their regions then count
 * by FLIP, not by the tolerance.
 *
 * <p>Invariant: {@code slack[i] <= direct[i]}. The pixels are read, never kept
 * changed; the arrays here (and the blurred copies) are the only ones made.
 */
public final class Comparison {

    /** The side of a page's panel in pixels, 650: the panels {@link #of(int[], int[])} takes are N x N. */
    public static final int N = PanelPlace.SIZE;
    private static final int LEVELS = 256;

    /**
     * How distances are measured: on the pixels as they are, after a small blur of both panels, or
     * whether a pixel matches is decided by its perceptual difference (LDR-FLIP).
     */
    public enum Metric { EXACT, BLUR, FLIP }

    /**
     * The default FLIP value at or below which a pixel matches: just above the 0.128 FLIP gives inside a flat area
     * whose colour is the default tolerance, 8/255, off mid grey (0.100 on black, 0.117 near white;
     * {@link Flip#flat}). So where there is no edge FLIP forgives what the default tolerance forgives, and
     * along an edge what the eye does not see when the two pictures are flipped between.
     */
    public static final double FLIP_THRESHOLD = 0.13;
    private final double flipThreshold;

    /** Today's slack: one pixel. */
    public static final int DEFAULT_DEVIATION = 1;
    /**
     * The tolerance {@code simpview compare} and {@code check} judge by unless told otherwise
     * ({@code --tolerance}), per channel in 1/255 steps: what {@link #verdictShare} is usually asked for, and
     * {@link ComparisonReport}'s.
     */
    public static final int DEFAULT_TOLERANCE = 8;
    /** The largest position deviation offered. */
    public static final int MAX_DEVIATION = 2;

    private final int[] ours;
    private final int[] theirs;
    private final int size;
    private final int deviation;
    private final Metric metric;
    private final byte[] direct;
    private final byte[] slack;
    private final int[] directCount = new int[LEVELS];
    private final int[] slackCount = new int[LEVELS];
    private float[] flip;
    private int flipFailing;

    private Comparison(int[] ours, int[] theirs, int size, int deviation, Metric metric, double flipThreshold) {
        this.flipThreshold = flipThreshold;
        this.ours = ours;
        this.theirs = theirs;
        this.size = size;
        this.deviation = deviation;
        this.metric = metric;
        this.direct = new byte[size * size];
        this.slack = new byte[size * size];
    }

    /** Compares two panels of 650x650 0xRRGGBB pixels, row by row from the top, with one pixel of slack. */
    public static Comparison of(int[] ours, int[] theirs) {
        return of(ours, theirs, DEFAULT_DEVIATION, Metric.EXACT);
    }

    /** Compares with slack of {@code deviation} pixels (0 to 2), measuring by {@code metric}. */
    public static Comparison of(int[] ours, int[] theirs, int deviation, Metric metric) {
        requirePanels(ours, theirs);
        if (ours.length != N * N || theirs.length != N * N) {
            throw new IllegalArgumentException("panels are 650x650 pixels");
        }
        return of(ours, theirs, N, deviation, metric, FLIP_THRESHOLD);
    }

    /** The same, a pixel matching by FLIP at {@code flipThreshold} or less (with {@link Metric#FLIP}). */
    public static Comparison of(int[] ours, int[] theirs, int deviation, Metric metric, double flipThreshold) {
        return of(ours, theirs, N, deviation, metric, flipThreshold);
    }

    /**
     * Compares two square panels of {@code size} x {@code size} pixels (the first assignment's are 300x300);
     * with FLIP a pixel matches at {@code flipThreshold} or less (0 to 1).
     */
    public static Comparison of(int[] ours, int[] theirs, int size, int deviation, Metric metric, double flipThreshold) {
        Comparison c = unmeasured(ours, theirs, size, deviation, metric, flipThreshold);
        if (metric == Metric.BLUR) {
            c.measure(Blur.of(ours, size), Blur.of(theirs, size));
        } else {
            c.measure(ours, theirs);
        }
        if (metric == Metric.FLIP) {
            c.flip = Flip.of(ours, theirs, size, size);
            for (float v : c.flip) {
                c.flipFailing += v > flipThreshold ? 1 : 0;
            }
        }
        return c;
    }

    /** A comparison of these panels with nothing measured yet, its arguments checked. */
    private static Comparison unmeasured(int[] ours, int[] theirs, int size, int deviation, Metric metric,
            double flipThreshold) {
        requirePanels(ours, theirs);
        Objects.requireNonNull(metric, "metric must not be null");
        if (!(flipThreshold >= 0 && flipThreshold <= 1)) {
            throw new IllegalArgumentException("a FLIP threshold is 0 to 1, not " + flipThreshold);
        }
        if (size < 1 || ours.length != size * size || theirs.length != size * size) {
            throw new IllegalArgumentException("both panels must be " + size + "x" + size + " pixels");
        }
        if (deviation < 0 || deviation > MAX_DEVIATION) {
            throw new IllegalArgumentException("position deviation is 0 to " + MAX_DEVIATION + " pixels, not " + deviation);
        }
        return new Comparison(ours, theirs, size, deviation, metric, flipThreshold);
    }

    /** Refuses a null panel where the caller hands it in, naming which. */
    private static void requirePanels(int[] ours, int[] theirs) {
        Objects.requireNonNull(ours, "ours must not be null");
        Objects.requireNonNull(theirs, "theirs must not be null");
    }

    private void measure(int[] ours, int[] theirs) {
        for (int y = 0; y < size; y++) {
            measureRow(ours, theirs, y, LEVELS);
        }
    }

    /**
     * Row y's distances, without and with slack, measured and counted; how many of its pixels are beyond
     * {@code tolerance} with slack.
     */
    private int measureRow(int[] ours, int[] theirs, int y, int tolerance) {
        int r = deviation;
        int n = size;
        int beyond = 0;
        for (int x = 0; x < n; x++) {
            int i = y * n + x;
            int d = Rasters.distance(ours[i], theirs[i]);
            int s = d;
            if (d != 0 && r != 0) {
                int one = nearest(ours[i], theirs, n, x, y, r, d, 0);
                // The other way only matters where it is larger than the first: it may stop at that.
                s = one == d ? d : nearest(theirs[i], ours, n, x, y, r, d, one);
            }
            direct[i] = (byte) d;
            slack[i] = (byte) s;
            directCount[d]++;
            slackCount[s]++;
            beyond += s > tolerance ? 1 : 0;
        }
        return beyond;
    }

    /**
     * The comparison {@link #of(int[], int[], int, int, Metric, double)} makes, unless at least {@code enough}
     * pixels fail by {@code tolerance} (beyond it even with slack): then null, as soon as that many are found.
     * The rows are measured every {@link #ROW_STRIDE}-th first, then those between, so that pixels failing
     * anywhere in the panel are found early. Each pixel's distances are its own, whatever order the rows are
     * measured in, so a comparison returned is the one {@code of} makes; and null means that comparison would
     * have at least {@code enough} failing pixels ({@link #failing}), for those found are among them. With
     * {@link Metric#FLIP}, whose failing pixels are FLIP's, the comparison is always made.
     */
    static Comparison unlessFailing(int[] ours, int[] theirs, int size, int deviation, Metric metric,
            double flipThreshold, int tolerance, long enough) {
        if (metric == Metric.FLIP || enough > (long) size * size) {
            return of(ours, theirs, size, deviation, metric, flipThreshold);
        }
        Comparison c = unmeasured(ours, theirs, size, deviation, metric, flipThreshold);
        int[] measuredOurs = metric == Metric.BLUR ? Blur.of(ours, size) : ours;
        int[] measuredTheirs = metric == Metric.BLUR ? Blur.of(theirs, size) : theirs;
        long failing = 0;
        for (int phase = 0; phase < ROW_STRIDE; phase++) {
            for (int y = phase; y < size; y += ROW_STRIDE) {
                failing += c.measureRow(measuredOurs, measuredTheirs, y, tolerance);
                if (failing >= enough) {
                    return null;
                }
            }
        }
        return c;
    }

    /** Rows apart that {@link #unlessFailing} measures first. */
    static final int ROW_STRIDE = 16;

    /**
     * The smallest distance from {@code colour} to a pixel of {@code other} within r pixels of (x, y)
     * (a square), at most {@code bound}; or, as soon as one is found at or below {@code floor}, the
     * floor (the caller takes the larger of this and the floor, so nothing smaller changes it).
     */
    private static int nearest(int colour, int[] other, int n, int x, int y, int r, int bound, int floor) {
        int best = bound;
        for (int ny = Math.max(0, y - r); ny <= Math.min(n - 1, y + r); ny++) {
            for (int nx = Math.max(0, x - r); nx <= Math.min(n - 1, x + r); nx++) {
                best = Math.min(best, Rasters.distance(colour, other[ny * n + nx]));
                if (best <= floor) {
                    return floor;
                }
            }
        }
        return best;
    }

    /** The share of panel pixels within {@code tolerance} (0 to 255) in every channel, with or without slack. */
    public double share(int tolerance, boolean withSlack) {
        int[] counts = withSlack ? slackCount : directCount;
        long within = 0;
        for (int level = 0; level <= Math.min(tolerance, LEVELS - 1); level++) {
            within += counts[level];
        }
        return (double) within / (size * size);
    }

    /**
     * The share the verdict is on: within {@code tolerance} with slack; with FLIP, the share of pixels
     * whose FLIP value is at most the threshold.
     */
    public double verdictShare(int tolerance) {
        return metric == Metric.FLIP ? 1 - (double) flipFailing / (size * size) : share(tolerance, true);
    }

    /** Whether pixel i fails: beyond {@code tolerance} even with slack; with FLIP, above the threshold. */
    public boolean fails(int i, int tolerance) {
        return metric == Metric.FLIP ? flip[i] > flipThreshold : (slack[i] & 0xFF) > tolerance;
    }

    /** Pixel i's FLIP value, 0 to 1; NaN unless the metric is FLIP. */
    public double flip(int i) {
        return flip == null ? Double.NaN : flip[i];
    }

    /** How many panel pixels fail: differ by more than {@code tolerance} even with slack, or with FLIP above its threshold. */
    public int failing(int tolerance) {
        if (metric == Metric.FLIP) {
            return flipFailing;
        }
        int failing = 0;
        for (int level = Math.max(0, tolerance + 1); level < LEVELS; level++) {
            failing += slackCount[level];
        }
        return failing;
    }

    /** With FLIP, the value at or below which a pixel matches. */
    public double flipThreshold() {
        return flipThreshold;
    }

    /** The panels' side in pixels: 650 for a page's panel. */
    public int size() {
        return size;
    }

    /** The slack in pixels: the position deviation. */
    public int deviation() {
        return deviation;
    }

    /** How the distances were measured, and whether a pixel matches by its tolerance or by FLIP. */
    public Metric metric() {
        return metric;
    }

    /**
     * The shares of the panel identical, within 1/255 and within 8/255, pixel for pixel, without slack
     * (on the blurred panels with {@link Metric#BLUR}).
     */
    public Shares exact() {
        return new Shares(share(0, false), share(1, false), share(8, false));
    }

    /** The same shares with {@link #deviation()} pixels of slack: what {@code compare}'s verdict counts. */
    public Shares withSlack() {
        return new Shares(share(0, true), share(1, true), share(8, true));
    }

    /** Pixel i's distance, 0 to 255, without slack. i = row from the top * 650 + column. */
    public int distance(int i) {
        return direct[i] & 0xFF;
    }

    /** Pixel i's distance with slack ({@link #deviation()} pixels). */
    public int distanceWithSlack(int i) {
        return slack[i] & 0xFF;
    }

    /** Simpview's panel as given, 0xRRGGBB row by row from the top (not a copy: do not change it). */
    public int[] ours() {
        return ours;
    }

    /** The other panel as given, 0xRRGGBB row by row from the top (not a copy: do not change it). */
    public int[] theirs() {
        return theirs;
    }
}
