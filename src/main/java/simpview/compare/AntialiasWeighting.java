package simpview.compare;

import java.util.Arrays;
import java.util.Locale;
import simpview.geometry.Vertex;
import simpview.pages.A1Lines;
import simpview.raster.AntialiasedLineRenderer;
import simpview.surface.Colors;

/**
 * A first-assignment antialiased panel whose levels follow another weighting than the handout's, on any of the
 * line pages (SPEC Part 3: panel 4 of pages 1 to 3): measured on the line (distance 0 from it: simpview's coverage
 * 0.818, level 209 of white) and one pixel beside it (distance 1: 0.091, level 23). Where one line alone reaches
 * a pixel (the starburst, the random lines), the levels there are measured directly, a coloured line's as a share
 * of its brightest channel (out of 255, as white's); where the lines overlap everywhere (the parallelogram's, a
 * pixel apart), each distance's coverage is fitted over the pixels of white lines blended over black, one minus
 * the level being the product of one minus each line's coverage there. The picture's levels are told beside
 * simpview's, measured alike, and what they look like: the coverage put through sRGB's gamma (a blend in linear
 * light, about 234 and 85), or a full pixel on the line (a disc of radius 1/2, or a weight of 1 - d: 255 and 0).
 *
 * @param theirsOn the picture's level on the line, 0 to 255
 * @param oursOn simpview's there
 * @param theirsBeside the picture's level one pixel beside it
 * @param oursBeside simpview's there
 * @param pixels how many pixels were measured
 * @param fitted whether the levels were fitted over overlapping lines, not measured where one line alone reaches
 * @param coloured whether some line is not white: its levels are shares of its brightest channel
 * @param gammaOn the level on the line that simpview's coverage there gives blended in linear light (sRGB's gamma)
 * @param gammaBeside the same one pixel beside it
 * @param linearLight whether the picture's levels are simpview's coverages blended in linear light
 */
public record AntialiasWeighting(int theirsOn, int oursOn, int theirsBeside, int oursBeside, int pixels,
        boolean fitted, boolean coloured, int gammaOn, int gammaBeside, boolean linearLight) implements PanelHint {

    /** At least this many pixels of each kind are measured. */
    static final int LEAST = 20;
    /** A level on the line at least this is a full pixel there. */
    static final int FULL = 240;
    /** How far from distance 0 (on the line) and 1 (beside it) a measured pixel may be. */
    static final double NARROW = 0.1;
    /** Levels this close to the gamma's are taken for it. */
    static final int NEAR = 6;
    /** A coloured line is measured only when its brightest channel is at least this: a share of it is then fine. */
    static final int BRIGHT = 64;
    /** Where lines overlap, the distances of the pixels one line alone reaches are grouped by this much. */
    static final double BIN = 0.05;
    /** At most this many lines reaching one pixel are kept of it (the starburst's centre has more). */
    static final int MOST_LINES = 2;

    /**
     * The hint for an antialiased panel of n x n pixels (ours and theirs row by row from the top) drawing
     * {@code lines}, or null when a line changes colour along it, too few pixels are measured, or the picture's
     * levels there are simpview's (within {@code tolerance}).
     */
    public static AntialiasWeighting find(int[] ours, int[] theirs, int n, int tolerance, A1Lines lines) {
        int count = lines.count();
        int[] channel = new int[count]; // the shift of each line's brightest channel
        int[] level = new int[count]; // its byte
        boolean coloured = false;
        int[] reached = new int[n * n];
        double[] distance = new double[n * n];
        int[] line = new int[n * n];
        double[][] distances = new double[n * n][];
        for (int i = 0; i < count; i++) {
            Vertex p = lines.start(i);
            Vertex q = lines.end(i);
            if (p.r() != q.r() || p.g() != q.g() || p.b() != q.b()) {
                return null; // a level is a share of one colour
            }
            int[] bytes = {Colors.toByte(p.b()), Colors.toByte(p.g()), Colors.toByte(p.r())};
            for (int c = 0; c < 3; c++) {
                if (bytes[c] > level[i]) {
                    level[i] = bytes[c];
                    channel[i] = 8 * c;
                }
            }
            coloured |= bytes[0] != 255 || bytes[1] != 255 || bytes[2] != 255;
            reach(Math.floor(p.x() + 0.5), Math.floor(p.y() + 0.5), Math.floor(q.x() + 0.5), Math.floor(q.y() + 0.5),
                    n, i, reached, distance, line, distances);
        }
        int[] on = new int[n * n];
        int[] onOurs = new int[n * n];
        int[] onGamma = new int[n * n];
        int[] beside = new int[n * n];
        int[] besideOurs = new int[n * n];
        int[] besideGamma = new int[n * n];
        int ons = 0;
        int besides = 0;
        for (int i = 0; i < n * n; i++) {
            if (reached[i] != 1 || level[line[i]] < BRIGHT) {
                continue;
            }
            int shift = channel[line[i]];
            double colour = level[line[i]];
            int theirsLevel = Colors.level(255 * (theirs[i] >> shift & 0xFF) / colour);
            double c = (ours[i] >> shift & 0xFF) / colour; // simpview's coverage there
            int oursLevel = Colors.level(255 * c);
            int gammaLevel = Colors.level(255 * 255 * encode(c * decode(colour / 255)) / colour);
            if (distance[i] <= NARROW) {
                on[ons] = theirsLevel;
                onOurs[ons] = oursLevel;
                onGamma[ons++] = gammaLevel;
            } else if (Math.abs(distance[i] - 1) <= NARROW) {
                beside[besides] = theirsLevel;
                besideOurs[besides] = oursLevel;
                besideGamma[besides++] = gammaLevel;
            }
        }
        AntialiasWeighting found;
        if (ons >= LEAST && besides >= LEAST) {
            int theirsOn = median(on, ons);
            int theirsBeside = median(beside, besides);
            int gammaOn = median(onGamma, ons);
            int gammaBeside = median(besideGamma, besides);
            found = new AntialiasWeighting(theirsOn, median(onOurs, ons), theirsBeside, median(besideOurs, besides),
                    ons + besides, false, coloured, gammaOn, gammaBeside, Math.abs(theirsOn - gammaOn) <= NEAR
                            && Math.abs(theirsBeside - gammaBeside) <= NEAR);
        } else if (!coloured) {
            found = fitted(ours, theirs, n, distances);
        } else {
            return null;
        }
        // a picture dark where simpview's lines are has its lines elsewhere (its own random ones): not a weighting
        return found == null || 4 * found.theirsOn < found.oursOn || Math.abs(found.theirsOn - found.oursOn) <= tolerance
                && Math.abs(found.theirsBeside - found.oursBeside) <= tolerance ? null : found;
    }

    /**
     * The levels on and beside a line of white lines that overlap (the parallelogram's, a pixel apart), or null when
     * too few pixels are measured. One pixel beside a line is measured where one line alone reaches, at the edge of
     * the lines; on a line, where one other line reaches too, taken out: a pixel holds 1 - (1 - w1) (1 - w2) of
     * white, as each line blended over the last gives, and the other line's w2 is the level one line alone gives at
     * its distance (the median of such pixels, distances grouped by {@link #BIN}). The picture blended in linear
     * light is measured so too, its levels decoded first.
     */
    private static AntialiasWeighting fitted(int[] ours, int[] theirs, int n, double[][] distances) {
        int bins = (int) Math.ceil((AntialiasedLineRenderer.HALF_WIDTH + AntialiasedLineRenderer.RADIUS) / BIN) + 1;
        double[][] alone = new double[3][]; // by distance group, the median level one line alone gives: 0 to 1
        for (int kind = 0; kind < 3; kind++) {
            alone[kind] = aloneByDistance(kind == 1 ? ours : theirs, kind == 2, distances, bins);
        }
        double[][] on = new double[3][n * n];
        double[][] beside = new double[3][n * n];
        int ons = 0;
        int besides = 0;
        for (int i = 0; i < n * n; i++) {
            double[] d = distances[i];
            if (d == null || d.length > 2) {
                continue;
            }
            if (d.length == 1 && Math.abs(d[0] - 1) <= NARROW) {
                for (int kind = 0; kind < 3; kind++) {
                    beside[kind][besides] = level(kind == 1 ? ours[i] : theirs[i], kind == 2);
                }
                besides++;
            } else if (d.length == 2 && Math.min(d[0], d[1]) <= NARROW) {
                int other = (int) (Math.max(d[0], d[1]) / BIN);
                if (Double.isNaN(alone[0][other]) || Double.isNaN(alone[1][other]) || Double.isNaN(alone[2][other])) {
                    continue;
                }
                for (int kind = 0; kind < 3; kind++) {
                    double v = level(kind == 1 ? ours[i] : theirs[i], kind == 2);
                    on[kind][ons] = alone[kind][other] >= 1 ? v : 1 - (1 - v) / (1 - alone[kind][other]);
                }
                ons++;
            }
        }
        if (ons < LEAST || besides < LEAST) {
            return null;
        }
        int[] onLevel = new int[3];
        int[] besideLevel = new int[3];
        for (int kind = 0; kind < 3; kind++) {
            onLevel[kind] = Colors.level(255 * median(on[kind], ons));
            besideLevel[kind] = Colors.level(255 * median(beside[kind], besides));
        }
        boolean linear = Math.abs(onLevel[2] - onLevel[1]) <= NEAR && Math.abs(besideLevel[2] - besideLevel[1]) <= NEAR;
        return new AntialiasWeighting(onLevel[0], onLevel[1], besideLevel[0], besideLevel[1], ons + besides, true,
                false, throughGamma(onLevel[1] / 255.0), throughGamma(besideLevel[1] / 255.0), linear);
    }

    /**
     * By distance group, the median level (0 to 1; {@code decoded}: through sRGB first) of the pixels one line alone
     * reaches; NaN where fewer than three are.
     */
    private static double[] aloneByDistance(int[] rgb, boolean decoded, double[][] distances, int bins) {
        double[][] levels = new double[bins][rgb.length / bins + 16];
        int[] counts = new int[bins];
        for (int i = 0; i < rgb.length; i++) {
            if (distances[i] != null && distances[i].length == 1) {
                int b = (int) (distances[i][0] / BIN);
                if (counts[b] == levels[b].length) {
                    levels[b] = Arrays.copyOf(levels[b], 2 * counts[b]);
                }
                levels[b][counts[b]++] = level(rgb[i], decoded);
            }
        }
        double[] medians = new double[bins];
        for (int b = 0; b < bins; b++) {
            medians[b] = counts[b] < 3 ? Double.NaN : median(levels[b], counts[b]);
        }
        return medians;
    }

    /** A white line's level, its blue channel, 0 to 1; {@code decoded}: through sRGB first, linear light. */
    private static double level(int rgb, boolean decoded) {
        double v = (rgb & 0xFF) / 255.0;
        return decoded ? decode(v) : v;
    }

    private static double median(double[] values, int count) {
        double[] sorted = Arrays.copyOf(values, count);
        Arrays.sort(sorted);
        return sorted[count / 2];
    }

    /**
     * Counts, for each pixel the antialiased drawer would take for line i between the rounded ends (a, b), that it
     * does so, and keeps the pixel's distance from the line and the line, and adds the distance to the pixel's list
     * (SPEC Part 3: along the segment and half a pixel past each end, within half the slab and the disc's radius of
     * the line).
     */
    private static void reach(double ax, double ay, double bx, double by, int n, int i, int[] reached,
            double[] distance, int[] line, double[][] distances) {
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
                    int p = (n - 1 - y) * n + x;
                    reached[p]++;
                    distance[p] = d;
                    line[p] = i;
                    double[] list = distances[p];
                    if (list == null) {
                        distances[p] = new double[] {d};
                    } else if (list.length <= MOST_LINES) { // one more: "more than MOST_LINES", not measured
                        double[] longer = Arrays.copyOf(list, list.length + 1);
                        longer[list.length] = d;
                        distances[p] = longer;
                    }
                }
            }
        }
    }

    private static int median(int[] values, int count) {
        int[] sorted = Arrays.copyOf(values, count);
        Arrays.sort(sorted);
        return sorted[count / 2];
    }

    /** sRGB's encoding of a linear level, 0 to 1. */
    private static double encode(double c) {
        return c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
    }

    /** sRGB's decoding of an encoded level, 0 to 1. */
    private static double decode(double v) {
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
    }

    /** The level {@code c} of white gives through sRGB's gamma: a blend made in linear light. */
    private static int throughGamma(double c) {
        return Colors.level(255 * encode(c));
    }

    /** What the levels look like, or "" when none of the known weightings. */
    private String looksLike() {
        if (linearLight) {
            return "the coverage put through sRGB's gamma (" + gammaOn + " and " + gammaBeside + "), as a blend in "
                    + "linear light gives: SPEC blends the levels as they are, c * colour + (1 - c) * old, no gamma";
        }
        if (theirsOn >= FULL && oursOn < FULL && theirsBeside < oursBeside) { // nothing beside: not brighter overall
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
        String where = fitted ? "where your white lines overlap, your antialiased levels are"
                : coloured ? "where one line alone reaches a pixel, your antialiased levels (as shares of each line's "
                        + "brightest channel, out of 255) are"
                : "where one line alone reaches a pixel, your antialiased levels are";
        String how = String.format(Locale.ROOT, "medians of %,d pixels within %s of those distances", pixels, NARROW)
                + (fitted ? ", on a line where one other line reaches too: one minus the level is the product of one "
                        + "minus each line's share, the other's that one line alone gives at its distance" : "");
        return String.format(Locale.ROOT, "%s %d on the line and %d one pixel beside it, simpview's %d and %d (the share "
                + "of a disc of radius sqrt(2)/2 inside the slab of width 1, 0.818 at distance 0 and 0.091 at 1; %s)%s.",
                where, theirsOn, theirsBeside, oursOn, oursBeside, how, like.isEmpty() ? "" : "; yours look like " + like);
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}
