package simpview.compare;

import java.math.BigInteger;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Pattern;
import simpview.surface.PageCanvas;

/**
 * How one page or scene is judged and scored: the rule of a rubric that
 * matched it, every field filled in (from the rubric's defaults, and those
 * from the command line's options).
 *
 * @param match what the rule matched on: a page range ("6", "1-3"), a name pattern ("page*", "pageC") or "*"
 * @param tolerance per channel, in 1/255 steps
 * @param deviation position deviation in pixels, 0 to 2: a pixel matches when a pixel within that distance matches
 * @param minShare the share within the tolerance (with the deviation) that passes, in percent
 * @param maxFailing the most pixels that may fail (beyond the tolerance even with the deviation), or -1 for no limit
 * @param points the page's score when it passes (Gradescope's max_score)
 * @param zeroShare with partial scoring, the share (percent) at and below which the page scores nothing (or at and
 *     below an empty panel's share, when that is higher: {@link #zeroPoint})
 * @param metric exact, after a small blur, or FLIP (antialiased panels)
 * @param alternates a folder of extra accepted references, or null
 * @param visibility Gradescope's visibility of the page's test
 * @param flipThreshold with the FLIP metric, the value at or below which a pixel matches (0 to 1)
 */
public record RubricRule(String match, int tolerance, int deviation, double minShare, int maxFailing, double points,
        double zeroShare, Comparison.Metric metric, Path alternates, String visibility, double flipThreshold) {

    /** With partial scoring, the share at or below which a failing page scores nothing when no rule says (or min_share, if lower). */
    public static final double ZERO_SHARE = 90;

    /** Today's defaults: 8/255, one pixel, 99 %, no pixel limit, one point, exact. */
    public static RubricRule defaults(int tolerance, double minShare, int deviation, Comparison.Metric metric) {
        return defaults(tolerance, minShare, deviation, metric, Comparison.FLIP_THRESHOLD);
    }

    /** The same, FLIP's threshold given. */
    public static RubricRule defaults(int tolerance, double minShare, int deviation, Comparison.Metric metric,
            double flipThreshold) {
        return new RubricRule("*", tolerance, deviation, minShare, -1, 1, Math.min(ZERO_SHARE, minShare), metric, null, "visible",
                flipThreshold);
    }

    /** Gradescope's visibilities, the least visible first. */
    private static final List<String> VISIBILITIES =
            List.of("hidden", "after_due_date", "after_published", "visible");

    /**
     * The rule of a page judged in parts (the first assignment's four panels, each by its own rule) when it is
     * scored as one, because it is missing: the first part's rule, worth all the parts' points (so a missing
     * page costs what its parts would have scored), and as visible as the least visible of them.
     */
    public static RubricRule whole(List<RubricRule> parts) {
        RubricRule first = parts.get(0);
        double points = 0;
        String visibility = first.visibility();
        for (RubricRule part : parts) {
            points += part.points();
            if (VISIBILITIES.indexOf(part.visibility()) < VISIBILITIES.indexOf(visibility)) {
                visibility = part.visibility();
            }
        }
        return new RubricRule(first.match(), first.tolerance(), first.deviation(), first.minShare(), first.maxFailing(),
                points, first.zeroShare(), first.metric(), first.alternates(), visibility, first.flipThreshold());
    }

    /** A comparison of two square panels made under this rule: its deviation, metric and FLIP threshold. */
    public Comparison compare(int[] ours, int[] theirs, int size) {
        return Comparison.of(ours, theirs, size, deviation, metric, flipThreshold);
    }

    /**
     * The comparison {@link #compare} makes, unless so many of its pixels fail that it cannot pass by this rule:
     * then null, told from those pixels alone (a picture of another page is told so within its first rows).
     * Exact: null only where {@link #passes} of that comparison would be false ({@link #failingThatFails}).
     */
    Comparison compareUnlessFailing(int[] ours, int[] theirs, int size) {
        return Comparison.unlessFailing(ours, theirs, size, deviation, metric, flipThreshold, tolerance,
                failingThatFails((long) size * size));
    }

    /**
     * The fewest failing pixels of a panel of {@code total} that fail this rule, or {@code total + 1} when none
     * do: more than {@code maxFailing}, or so many that the share left within the tolerance is short of
     * {@code minShare}. Without FLIP, a comparison's {@link Comparison#verdictShare} is its pixels within the
     * tolerance, {@code total} less its failing ones, over {@code total}, a division of whole numbers below
     * 2^53 that rounds the same here; and it only falls as the failing pixels grow. So the least count whose
     * share {@link #shareReaches} refuses, found by halving, is exact: at that many failing pixels or more, the
     * comparison fails.
     */
    long failingThatFails(long total) {
        long low = 0;
        long high = total + 1;
        while (low < high) {
            long middle = (low + high) >>> 1;
            if (shareReaches((double) (total - middle) / total)) {
                low = middle + 1;
            } else {
                high = middle;
            }
        }
        return maxFailing >= 0 ? Math.min(low, maxFailing + 1L) : low;
    }

    /** The verdict of a comparison made under this rule (with its deviation and metric). */
    public boolean passes(Comparison comparison) {
        return shareReaches(comparison.verdictShare(tolerance))
                && (maxFailing < 0 || comparison.failing(tolerance) <= maxFailing);
    }

    /** Whether a verdict share (0 to 1) reaches what this rule needs, the share half of {@link #passes}. */
    public boolean shareReaches(double verdictShare) {
        return verdictShare * 100 >= minShare - 1e-9;
    }

    /** The score of a comparison, its zero point {@code zeroShare} alone ({@link #score(Comparison, boolean, double)}). */
    public double score(Comparison comparison, boolean partial) {
        return score(comparison, partial, Double.NaN);
    }

    /**
     * The score of a comparison. All or nothing: the points when it passes, else 0.
     * Partial: the points when it passes; else the points times how far the share
     * got from the zero point ({@link #zeroPoint}: {@code zeroShare}, or {@code emptyShare} when higher) towards
     * {@code minShare} (0 at or below it, at most 1:
     * a page failing by its pixel count alone is not paid for a share above minShare),
     * and when there are more failing pixels than allowed, times allowed / failing.
     * Rounded down to hundredths (docs/grading.md gives it as a formula).
     *
     * @param emptyShare what an empty panel gets against simpview's ({@link #emptyShare}), or NaN: not measured
     */
    public double score(Comparison comparison, boolean partial, double emptyShare) {
        if (passes(comparison)) {
            return points;
        }
        if (!partial) {
            return 0;
        }
        double share = comparison.verdictShare(tolerance) * 100;
        double zero = zeroPoint(emptyShare);
        double part = minShare <= zero ? (share >= minShare ? 1 : 0)
                : Math.max(0, Math.min(1, (share - zero) / (minShare - zero)));
        int failing = comparison.failing(tolerance);
        if (maxFailing >= 0 && failing > maxFailing) {
            part *= (double) maxFailing / failing;
        }
        return Math.floor(points * part * 100 + 1e-9) / 100;
    }

    /**
     * The share, in percent, that an empty panel (simpview's background alone, {@link PageCanvas#BACKGROUND}: a
     * picture of nothing) gets against simpview's own panel {@code ours}, {@code size} pixels a side, under this
     * rule. A page mostly background (lines on black, a lit object in the middle) gives a blank picture much of
     * its share, above zero_share; partial scoring pays for a share above this one only.
     */
    public double emptyShare(int[] ours, int size) {
        int[] empty = new int[size * size];
        Arrays.fill(empty, PageCanvas.BACKGROUND & 0xFFFFFF);
        return compare(ours, empty, size).verdictShare(tolerance) * 100;
    }

    /**
     * The share at or below which a failing page scores nothing, with partial scoring: {@code zeroShare}, or the
     * share an empty panel gets ({@link #emptyShare}) when that is higher, so a blank picture earns nothing.
     */
    public double zeroPoint(double emptyShare) {
        return Double.isNaN(emptyShare) ? zeroShare : Math.max(zeroShare, emptyShare);
    }

    /** Whether this rule is for the page or scene of that key ("page6", "pageC") and page number (0 for a scene). */
    boolean matches(String key, int page) {
        String m = match.trim();
        if (m.matches("[0-9][0-9 ,\\-]*")) {
            return page > 0 && inRange(m, page);
        }
        return key.matches(glob(m));
    }

    /**
     * The first part of a page range that runs backwards ("3-1" of "3-1" or "1,5-4"), which fits no page; null
     * when there is none, or {@code match} is a name pattern.
     */
    static String backwardsRange(String match) {
        String m = match.trim();
        if (!m.matches("[0-9][0-9 ,\\-]*")) {
            return null;
        }
        for (String part : m.split(",")) {
            String[] ends = part.trim().split("-");
            if (ends.length == 2 && ends[0].trim().matches("[0-9]+") && ends[1].trim().matches("[0-9]+")
                    && new BigInteger(ends[0].trim()).compareTo(new BigInteger(ends[1].trim())) > 0) {
                return part.trim();
            }
        }
        return null;
    }

    private static boolean inRange(String range, int page) {
        for (String part : range.split(",")) {
            String[] ends = part.trim().split("-");
            if (ends.length == 0 || ends[0].isBlank()) {
                continue;
            }
            int from = Integer.parseInt(ends[0].trim());
            int to = ends.length > 1 && !ends[1].isBlank() ? Integer.parseInt(ends[1].trim()) : from;
            if (page >= from && page <= to) {
                return true;
            }
        }
        return false;
    }

    private static String glob(String pattern) {
        StringBuilder regex = new StringBuilder();
        for (char c : pattern.toCharArray()) {
            switch (c) {
                case '*' -> regex.append(".*");
                case '?' -> regex.append('.');
                default -> regex.append(Pattern.quote(String.valueOf(c)));
            }
        }
        return regex.toString();
    }
}
