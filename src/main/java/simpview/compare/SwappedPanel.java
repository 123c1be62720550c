package simpview.compare;

import java.util.List;
import java.util.Locale;

/**
 * A student's panel that holds what simpview draws in another panel of the
 * page: the panels laid out in another order, or one drawer's lines drawn
 * by another (a Bresenham panel that is simpview's DDA panel). Named under
 * {@link SystematicError}'s rules: at least {@link SystematicError#BETTER}
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
            long wrong = j == k ? Long.MAX_VALUE : wrong(ours[j - 1], theirs[k - 1], tolerance);
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
