package simpview.compare;

import java.util.List;
import java.util.Locale;

/**
 * A student's panel that holds what simpview draws in another panel of the
 * page: the panels laid out in another order, or one drawer's lines drawn
 * by another (a Bresenham panel that is simpview's DDA panel). Named under
 * {@link SystematicError}'s rules, among simpview's panels that differ from
 * its own on {@link #MIN_DISTINCT} of the panel or more: at least {@link SystematicError#BETTER}
 * times fewer pixels beyond the tolerance than against its own panel, at
 * least {@link SystematicError#MIN_SHARE} of them within it, and at least
 * {@link SystematicError#MIN_WRONG} of its own panel beyond it.
 *
 * @param panel the student's panel, 1, 2, ...
 * @param like simpview's panel it holds
 * @param name simpview's name for that panel ("antialiased", "mesh")
 * @param shareThere the share of its pixels within the tolerance of that panel's
 * @param shareAsIs the same against its own panel
 * @param tolerance the tolerance, in 1/255 steps
 */
public record SwappedPanel(int panel, int like, String name, double shareThere, double shareAsIs, int tolerance)
        implements PanelHint {

    /** How much of the panel two of simpview's panels must differ on, at least, for one to be named for the other. */
    static final double MIN_DISTINCT = 0.05;

    /** Theirs' panel k against each of our other panels; null when none is named by the rules above. */
    static SwappedPanel find(int[][] ours, int[][] theirs, int k, int n, int tolerance, List<String> names) {
        long pixels = (long) n * n;
        long own = wrong(ours[k - 1], theirs[k - 1], tolerance);
        if (own < SystematicError.MIN_WRONG * pixels) {
            return null;
        }
        int best = 0;
        long fewest = Long.MAX_VALUE;
        for (int j = 1; j <= ours.length; j++) {
            // A panel of simpview's that is nearly its panel k tells nothing of where the picture went wrong
            // (page 1 by the course's rule, against a picture by SPEC's: its Bresenham panel is nearer
            // simpview's DDA panel). The first assignment's DDA, Bresenham and alternating panels differ on
            // 3.4 % of a panel at most (page 1, the course's rule); the antialiased one differs from them on
            // 9.9 % (page 3) to 26 %, and the polygon scenes from each other on 6.5 % (page 5's two meshes,
            // as ghosts) to 84 %.
            boolean distinct = j != k && wrong(ours[j - 1], ours[k - 1], tolerance) >= MIN_DISTINCT * pixels;
            long wrong = distinct ? wrong(ours[j - 1], theirs[k - 1], tolerance) : Long.MAX_VALUE;
            if (wrong < fewest) {
                fewest = wrong;
                best = j;
            }
        }
        double shareThere = 1 - (double) fewest / pixels;
        if (best == 0 || fewest * SystematicError.BETTER > own || shareThere < SystematicError.MIN_SHARE) {
            return null;
        }
        return new SwappedPanel(k, best, names.get(best - 1), shareThere, 1 - (double) own / pixels, tolerance);
    }

    /** The share of two panels' pixels within the tolerance of each other. */
    static double within(int[] ours, int[] theirs, int tolerance) {
        return 1 - (double) wrong(ours, theirs, tolerance) / ours.length;
    }

    private static long wrong(int[] ours, int[] theirs, int tolerance) {
        long wrong = 0;
        for (int i = 0; i < ours.length; i++) {
            wrong += Rasters.distance(ours[i], theirs[i]) > tolerance ? 1 : 0;
        }
        return wrong;
    }

    @Override
    public String brief() {
        return "like simpview's panel " + like + " (" + name + ")";
    }

    @Override
    public String hint(int n) {
        return String.format(Locale.ROOT, "your panel %d holds what simpview draws in panel %d (%s): %s of its "
                + "pixels are within %d/255 of that panel's (%s of its own panel's). The panels go 1 top left, 2 top "
                + "right, 3 bottom left, 4 bottom right; each draws with its own drawer or scene.", panel, like, name,
                Percent.of(shareThere), tolerance, Percent.of(shareAsIs));
    }
}
