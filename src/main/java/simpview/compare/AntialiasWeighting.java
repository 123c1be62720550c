package simpview.compare;

import java.util.Arrays;
import java.util.Locale;
import simpview.geometry.Vertex;
import simpview.pages.A1Lines;
import simpview.raster.AntialiasedLineRenderer;

/**
 * A first-assignment antialiased panel of white lines whose levels follow another weighting than the handout's:
 * measured where one line alone reaches a pixel, on the line (distance 0 from it: simpview's coverage 0.818,
 * level 209) and one pixel beside it (distance 1: 0.091, level 23). The picture's levels there are told beside
 * simpview's, and what they look like: the coverage put through sRGB's gamma (a blend in linear light, about 234 and
 * 85), or a full pixel on the line (a disc of radius 1/2, or a weight of 1 - d: 255 and 0).
 *
 * @param theirsOn the picture's median level on the line, 0 to 255
 * @param oursOn simpview's there
 * @param theirsBeside the picture's median level one pixel beside it
 * @param oursBeside simpview's there
 * @param pixels how many pixels were measured
 */
public record AntialiasWeighting(int theirsOn, int oursOn, int theirsBeside, int oursBeside, int pixels)
        implements PanelHint {

    /** At least this many pixels of each kind are measured. */
    static final int LEAST = 20;
    /** A level on the line at least this is a full pixel there. */
    static final int FULL = 240;
    /** How far from distance 0 (on the line) and 1 (beside it) a measured pixel may be. */
    static final double NARROW = 0.1;
    /** Levels this close to the gamma's are taken for it. */
    static final int NEAR = 6;

    /**
     * The hint for an antialiased panel of n x n pixels (ours and theirs row by row from the top) drawing
     * {@code lines}, or null when a line is not white, too few pixels are reached by one line alone, or the
     * picture's levels there are simpview's (within {@code tolerance}).
     */
    public static AntialiasWeighting find(int[] ours, int[] theirs, int n, int tolerance, A1Lines lines) {
        int[] reached = new int[n * n];
        double[] distance = new double[n * n];
        for (int i = 0; i < lines.count(); i++) {
            Vertex p = lines.start(i);
            Vertex q = lines.end(i);
            if (p.r() != 1 || p.g() != 1 || p.b() != 1 || q.r() != 1 || q.g() != 1 || q.b() != 1) {
                return null; // a level is a coverage only of white over black
            }
            reach(Math.floor(p.x() + 0.5), Math.floor(p.y() + 0.5), Math.floor(q.x() + 0.5), Math.floor(q.y() + 0.5),
                    n, reached, distance);
        }
        int[] on = new int[n * n];
        int[] onOurs = new int[n * n];
        int[] beside = new int[n * n];
        int[] besideOurs = new int[n * n];
        int ons = 0;
        int besides = 0;
        for (int i = 0; i < n * n; i++) {
            if (reached[i] != 1) {
                continue;
            }
            if (distance[i] <= NARROW) {
                on[ons] = theirs[i] & 0xFF;
                onOurs[ons++] = ours[i] & 0xFF;
            } else if (Math.abs(distance[i] - 1) <= NARROW) {
                beside[besides] = theirs[i] & 0xFF;
                besideOurs[besides++] = ours[i] & 0xFF;
            }
        }
        if (ons < LEAST || besides < LEAST) {
            return null;
        }
        AntialiasWeighting found = new AntialiasWeighting(median(on, ons), median(onOurs, ons), median(beside, besides),
                median(besideOurs, besides), ons + besides);
        return Math.abs(found.theirsOn - found.oursOn) <= tolerance
                && Math.abs(found.theirsBeside - found.oursBeside) <= tolerance ? null : found;
    }

    /**
     * Counts, for each pixel the antialiased drawer would take for the line between the rounded ends (a, b), that
     * it does so, and keeps the pixel's distance from the line (SPEC Part 3: along the segment and half a pixel
     * past each end, within half the slab and the disc's radius of the line).
     */
    private static void reach(double ax, double ay, double bx, double by, int n, int[] reached, double[] distance) {
        double length = Math.hypot(bx - ax, by - ay);
        if (length == 0) {
            return;
        }
        double reach = AntialiasedLineRenderer.HALF_WIDTH + AntialiasedLineRenderer.RADIUS;
        int x0 = (int) Math.max(0, Math.min(ax, bx) - 2);
        int x1 = (int) Math.min(n - 1, Math.max(ax, bx) + 2);
        int y0 = (int) Math.max(0, Math.min(ay, by) - 2);
        int y1 = (int) Math.min(n - 1, Math.max(ay, by) + 2);
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                double along = ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / length;
                if (along < -AntialiasedLineRenderer.PAST_END || along > length + AntialiasedLineRenderer.PAST_END) {
                    continue;
                }
                double d = AntialiasedLineRenderer.distance(x, y, ax, ay, bx, by);
                if (d < reach) {
                    int i = (n - 1 - y) * n + x;
                    reached[i]++;
                    distance[i] = d;
                }
            }
        }
    }

    private static int median(int[] values, int count) {
        int[] sorted = Arrays.copyOf(values, count);
        Arrays.sort(sorted);
        return sorted[count / 2];
    }

    /** The level {@code c} of white gives through sRGB's gamma: a blend made in linear light. */
    private static int throughGamma(double c) {
        double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
        return (int) Math.floor(255 * encoded + 0.5);
    }

    /** What the levels look like, or "" when none of the known weightings. */
    private String looksLike() {
        double on = oursOn / 255.0;
        double beside = oursBeside / 255.0;
        if (Math.abs(theirsOn - throughGamma(on)) <= NEAR && Math.abs(theirsBeside - throughGamma(beside)) <= NEAR) {
            return "the coverage put through sRGB's gamma (" + throughGamma(on) + " and " + throughGamma(beside)
                    + "), as a blend in linear light gives: SPEC blends the levels as they are, c * colour + (1 - c) "
                    + "* old, no gamma";
        }
        if (theirsOn >= FULL && oursOn < FULL) {
            return "a full pixel on the line, as a disc of radius 1/2 (it fits inside the slab) or a weight of "
                    + "1 - d gives: SPEC's disc has radius sqrt(2)/2, the one that holds the pixel's square, so a pixel "
                    + "on the line is only 0.818 covered";
        }
        return "";
    }

    @Override
    public String brief() {
        return "antialiased with another weighting (" + theirsOn + " on a line, " + theirsBeside + " beside it; "
                + "simpview's " + oursOn + " and " + oursBeside + ")";
    }

    @Override
    public String hint(int n) {
        String like = looksLike();
        return String.format(Locale.ROOT, "where one line alone reaches a pixel, your antialiased levels are %d on the "
                + "line and %d one pixel beside it, simpview's %d and %d (the share of a disc of radius sqrt(2)/2 "
                + "inside the slab of width 1, 0.818 at distance 0 and 0.091 at 1; medians of %,d pixels within %s of "
                + "those distances)%s.", theirsOn, theirsBeside, oursOn, oursBeside, pixels, NARROW,
                like.isEmpty() ? "" : "; yours look like " + like);
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}
