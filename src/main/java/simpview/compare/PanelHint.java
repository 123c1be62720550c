package simpview.compare;

import java.util.Arrays;
import java.util.List;

/**
 * What a student's whole panel looks like, when one mistake explains it:
 * simpview's panel moved, turned or with its channels swapped
 * ({@link SystematicError}), or on a page of several panels, another of
 * simpview's panels ({@link SwappedPanel}), or a part of simpview's whole
 * page turned ({@link WholePage}); or, when the picture fails, another of the assignment's pages
 * ({@link OtherPage}: the file named for the wrong page), or a first-assignment page drawn from the student's
 * own random numbers ({@link RandomValues}), or a line panel whose lines are a pixel short or long
 * ({@link LineEnds}), drawn with floored ends ({@link FlooredEnds}) or otherwise in some octants
 * ({@link OctantLines}), or an antialiased panel of another weighting ({@link AntialiasWeighting}), or a polygon
 * panel filled without the top-left rule ({@link FillRule}), or the z-buffer page drawn without a depth test or
 * with it turned round ({@link DepthTestMistake}).
 */
public sealed interface PanelHint permits SystematicError, SwappedPanel, WholePage, OtherPage, RandomValues,
        LineEnds, AntialiasWeighting, FlooredEnds, OctantLines, FillRule, DepthTestMistake {

    /** Briefly, to follow "looks": "upside down", "like simpview's panel 4 (antialiased)". */
    String brief();

    /** The whole hint for a panel of n x n pixels: what it looks like, how well that explains it, where to look. */
    String hint(int n);

    /**
     * Whether it is said of the page as a whole, not of one panel: of a page of several panels, every panel's
     * row has the same hint, said once, of the page.
     */
    default boolean wholePage() {
        return false;
    }

    /** The share of the pixels it matches that are within the tolerance, the mistake undone. */
    double shareThere();

    /**
     * The hint for panel k (1, 2, ...) of a page of several n x n panels, ours and theirs each row by row from
     * the top, {@code names} simpview's panels' (at k - 1): its own panel moved or turned first, another panel
     * else; null when neither explains it.
     */
    static PanelHint of(int[][] ours, int[][] theirs, int k, int n, int tolerance, List<String> names) {
        SystematicError own = SystematicError.find(ours[k - 1], theirs[k - 1], n, tolerance);
        return own != null ? own : SwappedPanel.find(ours, theirs, k, n, tolerance, names);
    }

    /**
     * Each panel's hint (null where none) on a page ({@code pageSide} a side) of four n x n panels laid out two by two (1 top left, 2
     * top right, 3 bottom left, 4 bottom right): each panel's own ({@link #of}), or the whole page turned
     * ({@link WholePage}: every panel gets that one) where that leaves more of the page within the tolerance.
     */
    static PanelHint[] ofPage(int[][] ours, int[][] theirs, int n, int pageSide, int tolerance, List<String> names) {
        PanelHint[] hints = new PanelHint[ours.length];
        double explained = 0; // the mean share within the tolerance, each panel's hint undone
        for (int k = 1; k <= ours.length; k++) {
            hints[k - 1] = of(ours, theirs, k, n, tolerance, names);
            explained += (hints[k - 1] != null ? hints[k - 1].shareThere()
                    : SwappedPanel.within(ours[k - 1], theirs[k - 1], tolerance)) / ours.length;
        }
        // The page turned whole where that explains it better: a page whose rows of panels are swapped, each
        // panel left as it is, looks much like a page upside down when its panels are nearly symmetric.
        WholePage page = WholePage.find(ours, theirs, n, pageSide, tolerance);
        if (page != null && page.shareThere() >= explained) { // a tie: the page, the simpler account
            Arrays.fill(hints, page);
        }
        return hints;
    }
}
