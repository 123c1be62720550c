package simpview.compare;

import java.util.Locale;
import simpview.pages.A1Lines;
import simpview.surface.PageCanvas;

/**
 * A first-assignment line panel (DDA, Bresenham or alternating) whose lines are one pixel short or one pixel
 * long: most of the pixels that differ are the lines' end pixels, lit in simpview's panel and black in the
 * picture, or the pixels one step past them along the line, lit in the picture and black in simpview's. SPEC
 * draws both rounded ends and nothing past them; a loop that stops at {@code x < x1}, or runs to
 * {@code x <= x1 + 1}, does otherwise. Such a panel often passes (90 end pixels are 0.1 % of a panel), so the
 * student would not learn of it from the shares alone.
 *
 * @param shortEnds how many of the pixels that differ are ends that the picture leaves black
 * @param longEnds how many are one step past an end, lit in the picture only
 * @param differing how many pixels of the panel differ beyond the tolerance
 * @param example one such pixel and its line, in words: "line 1's end (285, 150)"
 */
public record LineEnds(int shortEnds, int longEnds, int differing, String example) implements PanelHint {

    /** At least this many such pixels, and at least half of those that differ. */
    static final int LEAST = 3;

    /**
     * The hint for a line panel of n x n pixels (ours and theirs row by row from the top) drawing {@code lines},
     * or null when fewer than half of its differing pixels (or fewer than {@value #LEAST}) are ends or one past
     * them.
     */
    public static LineEnds find(int[] ours, int[] theirs, int n, int tolerance, A1Lines lines) {
        int differing = 0;
        for (int i = 0; i < n * n; i++) {
            differing += Rasters.distance(ours[i], theirs[i]) > tolerance ? 1 : 0;
        }
        if (differing < LEAST) {
            return null;
        }
        boolean[] counted = new boolean[n * n];
        int shortEnds = 0;
        int longEnds = 0;
        String shortExample = null;
        String longExample = null;
        for (int i = 0; i < lines.count(); i++) {
            long ax = Math.round(Math.floor(lines.start(i).x() + 0.5));
            long ay = Math.round(Math.floor(lines.start(i).y() + 0.5));
            long bx = Math.round(Math.floor(lines.end(i).x() + 0.5));
            long by = Math.round(Math.floor(lines.end(i).y() + 0.5));
            long[][] ends = {{ax, ay, bx, by}, {bx, by, ax, ay}};
            for (long[] e : ends) {
                // the end e[0], e[1] of the line from e[2], e[3]; one step past it along the major axis
                int at = index(e[0], e[1], n);
                if (at >= 0 && !counted[at] && differs(ours[at], theirs[at], tolerance) && lit(ours[at])
                        && !lit(theirs[at])) {
                    counted[at] = true;
                    shortEnds++;
                    shortExample = shortExample != null ? shortExample : "line " + (i + 1) + "'s end " + point(e);
                }
                long dx = e[0] - e[2];
                long dy = e[1] - e[3];
                if (dx == 0 && dy == 0) {
                    continue;
                }
                boolean xMajor = Math.abs(dx) >= Math.abs(dy);
                long px = xMajor ? e[0] + Long.signum(dx)
                        : Math.round(Math.floor(e[0] + (double) dx / Math.abs(dy) + 0.5));
                long py = xMajor ? Math.round(Math.floor(e[1] + (double) dy / Math.abs(dx) + 0.5))
                        : e[1] + Long.signum(dy);
                int past = index(px, py, n);
                if (past >= 0 && !counted[past] && differs(ours[past], theirs[past], tolerance) && !lit(ours[past])
                        && lit(theirs[past])) {
                    counted[past] = true;
                    longEnds++;
                    longExample = longExample != null ? longExample
                            : "(" + px + ", " + py + ") past line " + (i + 1) + "'s end " + point(e);
                }
            }
        }
        int ends = shortEnds + longEnds;
        if (ends < LEAST || 2 * ends < differing) {
            return null;
        }
        return new LineEnds(shortEnds, longEnds, differing, shortEnds >= longEnds ? shortExample : longExample);
    }

    /** The index of panel pixel (x, y), y up, in a panel row by row from the top; -1 outside it. */
    private static int index(long x, long y, int n) {
        return x < 0 || y < 0 || x >= n || y >= n ? -1 : (int) ((n - 1 - y) * n + x);
    }

    private static boolean differs(int a, int b, int tolerance) {
        return Rasters.distance(a, b) > tolerance;
    }

    private static boolean lit(int rgb) {
        return (rgb & 0xFFFFFF) != (PageCanvas.BACKGROUND & 0xFFFFFF);
    }

    private static String point(long[] e) {
        return "(" + e[0] + ", " + e[1] + ")";
    }

    @Override
    public String brief() {
        return shortEnds >= longEnds ? "to stop a pixel short of its lines' ends"
                : "to run a pixel past its lines' ends";
    }

    @Override
    public String hint(int n) {
        if (shortEnds >= longEnds) {
            return String.format(Locale.ROOT, "your lines stop a pixel short: %,d of the %s that differ are ends of "
                    + "simpview's lines that yours leaves black (%s). SPEC draws both rounded ends: a loop from the "
                    + "first end's x (or y) to the second's, both included (x <= x1, not x < x1).",
                    shortEnds, Count.of(differing, "pixel"), example);
        }
        return String.format(Locale.ROOT, "your lines run a pixel long: %,d of the %s that differ are one step past "
                + "the end of a line of simpview's, lit in yours and black in simpview's (%s). SPEC stops at the "
                + "rounded end: a loop to the second end's x (or y), included, and no further.",
                longEnds, Count.of(differing, "pixel"), example);
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}
