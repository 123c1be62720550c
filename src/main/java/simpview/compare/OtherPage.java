package simpview.compare;

import java.util.Arrays;
import java.util.function.IntFunction;
import simpview.surface.PageCanvas;

/**
 * A picture that fails against the page its file is named for but passes as
 * another page of the same assignment: {@code page5.png} that holds page 4.
 * The picture is still graded as the page its name names, and fails; this
 * only tells the student and the teacher why.
 *
 * <p>The rule: against another page K (same seed, same options), the
 * picture must <em>pass</em> by the very rule it failed by (its tolerance,
 * slack, metric, minimum share and pixel limit; of a page of several panels,
 * every panel by its own); nearly passing is not enough. And K must not be
 * plain: where an empty panel (all background) would pass against K too, a
 * picture that passes says nothing of K, and K is no candidate. When two or
 * more pages pass, no page is named: no hint is better than a wrong one. A
 * seeded page of another seed passes against none of them (the pages are
 * drawn with the seed asked for), so it gets no hint.
 *
 * @param page the page it passes as, as the report names pages: "page 4", "page 2 (seed 361)", "A1 page 4"
 * @param named the page its file is named for, the same way
 * @param shareThere its verdict share against {@code page} (of a page of panels, its lowest panel's)
 */
public record OtherPage(String page, String named, double shareThere) implements PanelHint {

    /**
     * The other page of pages 1 to {@code count} (not {@code named}) that theirs passes as, or null when none does,
     * or more than one. {@code ours} gives simpview's panels of page k (one panel for a page of the eight, four for
     * the first assignment's), or null when page k cannot be drawn (the course's files absent): it is then no
     * candidate. Page k of {@code rules.length} panels is judged panel by panel by {@code rules}, each n x n
     * pixels; {@code label} names page k in the hint.
     */
    public static OtherPage find(int named, int count, int[][] theirs, int n, RubricRule[] rules,
            IntFunction<int[][]> ours, IntFunction<String> label) {
        OtherPage found = null;
        for (int k = 1; k <= count; k++) {
            if (k == named) {
                continue;
            }
            int[][] page = ours.apply(k);
            if (page == null) {
                continue;
            }
            double lowest = passes(page, theirs, n, rules);
            if (Double.isNaN(lowest) || plain(page, n, rules)) {
                continue;
            }
            if (found != null) {
                return null; // two pages it passes as: which one it is cannot be told
            }
            found = new OtherPage(label.apply(k), label.apply(named), lowest);
        }
        return found;
    }

    /** The lowest panel's verdict share when every panel of theirs passes against ours by its rule, else NaN. */
    static double passes(int[][] ours, int[][] theirs, int n, RubricRule[] rules) {
        double lowest = 1;
        for (int k = 0; k < rules.length; k++) {
            // null: so many pixels fail that it cannot pass, told without measuring the rest (exact)
            Comparison comparison = rules[k].compareUnlessFailing(ours[k], theirs[k], n);
            if (comparison == null || !rules[k].passes(comparison)) {
                return Double.NaN;
            }
            lowest = Math.min(lowest, comparison.verdictShare(rules[k].tolerance()));
        }
        return lowest;
    }

    /** Whether an empty page (every panel background) would pass against ours: a page too plain to be told. */
    private static boolean plain(int[][] ours, int n, RubricRule[] rules) {
        int[] empty = new int[n * n];
        Arrays.fill(empty, PageCanvas.BACKGROUND & 0xFFFFFF);
        for (int k = 0; k < rules.length; k++) {
            Comparison comparison = rules[k].compareUnlessFailing(ours[k], empty, n);
            if (comparison == null || !rules[k].passes(comparison)) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String brief() {
        return "like " + page + ": is the file named for the wrong page?";
    }

    @Override
    public String hint(int n) {
        return "your picture passes as simpview's " + page + ", " + Percent.of(shareThere) + " by the same rule, not as "
                + named + ": is the file named for the wrong page? It is graded as " + named + ", the page its name "
                + "names.";
    }

    @Override
    public boolean wholePage() {
        return true;
    }
}
