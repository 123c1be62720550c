package simpview.compare;

import java.util.Locale;
import simpview.geometry.Vertex;
import simpview.pages.A1Lines;
import simpview.pages.A1Rule;
import simpview.pages.LineTestPage;
import simpview.raster.LineRenderer;

/**
 * A first-assignment line panel whose lines' ends were floored, {@code floor(v)} or an int cast, where SPEC rounds
 * them, {@code floor(v + 0.5)} (SPEC, Rasterization rules: changed 2026-12-02): measured by drawing simpview's
 * own lines by the panel's own drawer with each end floored, and counting the pixels where the picture differs
 * from that and from simpview's panel as it is. An end whose x or y has a fraction of 0.5 or more is then a pixel
 * left or down, and its line leans with it, so the pixels that differ are not only ends ({@link LineEnds}).
 * Only the starburst (page 1) has such ends: the other line pages' ends are whole numbers.
 *
 * @param differing how many pixels of the panel differ from simpview's beyond the tolerance
 * @param differingFloored how many differ from simpview's lines drawn with floored ends
 * @param moved how many of the panel's lines have an end that flooring moves
 * @param lines how many lines the panel has
 * @param example one such end, in words: "line 3's end (284.589, 159.416): rounded (285, 159), floored (284, 159)"
 */
public record FlooredEnds(int differing, int differingFloored, int moved, int lines, String example)
        implements PanelHint {

    /** At least this many pixels differ from simpview's panel ... */
    static final int LEAST = 3;
    /** ... and at most this share of them differs from the lines drawn with floored ends. */
    static final double LEFT_OVER = 0.25;

    /**
     * The hint for panel k (1 to 4) of a line page, n x n pixels (ours and theirs row by row from the top), drawing
     * {@code lines} by its drawer under {@code rule}; null when the picture is no closer to the lines with floored
     * ends than to simpview's.
     */
    public static FlooredEnds find(int[] ours, int[] theirs, int n, int tolerance, int k, A1Rule rule, A1Lines lines) {
        int differing = count(ours, theirs, tolerance);
        if (differing < LEAST) {
            return null;
        }
        double[] floored = lines.numbers().clone();
        int moved = 0;
        String example = null;
        for (int i = 0; i < lines.count(); i++) {
            for (int at : new int[] {A1Lines.from(i), A1Lines.to(i)}) {
                double x = floored[at];
                double y = floored[at + 1];
                if (Math.floor(x) != Math.floor(x + 0.5) || Math.floor(y) != Math.floor(y + 0.5)) {
                    example = example != null ? example : String.format(Locale.ROOT,
                            "line %d's end (%s, %s): rounded (%.0f, %.0f), floored (%.0f, %.0f)", i + 1, number(x),
                            number(y), Math.floor(x + 0.5), Math.floor(y + 0.5), Math.floor(x), Math.floor(y));
                }
                floored[at] = Math.floor(x);
                floored[at + 1] = Math.floor(y);
            }
            moved += moves(lines.start(i)) || moves(lines.end(i)) ? 1 : 0;
        }
        if (moved == 0) {
            return null;
        }
        PanelPixels drawn = new PanelPixels(n);
        LineRenderer drawer = LineTestPage.drawer(k, rule);
        for (int i = 0; i < lines.count(); i++) {
            drawer.drawLine(floored, A1Lines.from(i), A1Lines.to(i), drawn);
        }
        int differingFloored = count(drawn.pixels(), theirs, tolerance);
        return differingFloored <= LEFT_OVER * differing
                ? new FlooredEnds(differing, differingFloored, moved, lines.count(), example) : null;
    }

    private static boolean moves(Vertex v) {
        return Math.floor(v.x()) != Math.floor(v.x() + 0.5) || Math.floor(v.y()) != Math.floor(v.y() + 0.5);
    }

    private static int count(int[] a, int[] b, int tolerance) {
        int differing = 0;
        for (int i = 0; i < a.length; i++) {
            differing += Rasters.distance(a[i], b[i]) > tolerance ? 1 : 0;
        }
        return differing;
    }

    /** A coordinate as given, to three decimals where it has any. */
    private static String number(double v) {
        return v == Math.rint(v) ? String.format(Locale.ROOT, "%.0f", v) : String.format(Locale.ROOT, "%.3f", v);
    }

    @Override
    public String brief() {
        return "to floor its lines' ends where SPEC rounds them";
    }

    @Override
    public String hint(int n) {
        return String.format(Locale.ROOT, "your lines' ends look floored, not rounded: simpview's lines drawn with each "
                + "end floored, floor(v), differ from yours at %s, as SPEC draws them (rounded) at %s. Flooring moves "
                + "an end whose x or y has a fraction of 0.5 or more a pixel left or down, and %,d of the %s have one "
                + "(%s). SPEC rounds each end to the nearest pixel first, floor(v + 0.5), not (int) v, then draws "
                + "between the two.", Count.of(differingFloored, "pixel"), Count.of(differing, "pixel"), moved,
                Count.of(lines, "line"), example);
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}
