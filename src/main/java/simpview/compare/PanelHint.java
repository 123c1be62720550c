package simpview.compare;

import java.util.List;

/**
 * What a student's whole panel looks like, when one mistake explains it:
 * simpview's panel moved, turned or with its channels swapped
 * ({@link SystematicError}), or on a page of several panels, another of
 * simpview's panels ({@link SwappedPanel}).
 */
public sealed interface PanelHint permits SystematicError, SwappedPanel {

    /** Briefly, to follow "looks": "upside down", "like simpview's panel 4 (antialiased)". */
    String brief();

    /** The whole hint for a panel of n x n pixels: what it looks like, how well that explains it, where to look. */
    String hint(int n);

    /**
     * The hint for panel k (1, 2, ...) of a page of several n x n panels, ours and theirs each row by row from
     * the top, {@code names} simpview's panels' (at k - 1): its own panel moved or turned first, another panel
     * else; null when neither explains it.
     */
    static PanelHint of(int[][] ours, int[][] theirs, int k, int n, int tolerance, List<String> names) {
        SystematicError own = SystematicError.find(ours[k - 1], theirs[k - 1], n, tolerance);
        return own != null ? own : SwappedPanel.find(ours, theirs, k, n, tolerance, names);
    }
}
