package simpview.compare;

import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * The outcome of comparing a picture with simpview's own, and the readable
 * report of it.
 *
 * @param theirs the picture compared
 * @param against what simpview drew, e.g. "page 6 (seed 361)"
 * @param comparison the two panels compared
 * @param margins the picture's margins
 * @param regions the patches that differ beyond the tolerance even with slack
 * @param tolerance the tolerance the verdict uses, in 1/255 steps (with slack)
 * @param minimum the share, in percent, that passes
 * @param maxFailing the most pixels that may differ beyond the tolerance even with slack, or -1 for no limit
 * @param systematic the mistake that changes the whole panel the same way, or null when none explains it
 */
public record ComparisonReport(Picture theirs, String against, Comparison comparison, Margins margins,
        DiffRegions.Found regions, int tolerance, double minimum, int maxFailing, SystematicError systematic) {

    /** How many of the largest patches a report lists. */
    public static final int REGIONS_LISTED = 5;

    /**
     * The share, in percent, that passes unless told otherwise ({@code --min}): with
     * {@link Comparison#DEFAULT_TOLERANCE} and a comparison of {@link Comparison#of(int[], int[])}, the verdict of
     * {@code simpview compare PICTURE --page N} with no other option.
     */
    public static final int DEFAULT_MINIMUM = 99;

    /**
     * The report of {@code comparison}, of the picture {@code theirs} against what simpview drew ({@code against},
     * words for the report's first line), judged within {@code tolerance} (1/255 steps, with the comparison's slack)
     * on at least {@code minimum} percent of the panel; the hint of a systematic mistake searched for.
     */
    public static ComparisonReport of(Picture theirs, String against, Comparison comparison, int tolerance, double minimum) {
        requireArguments(theirs, against, comparison);
        return of(theirs, against, comparison, tolerance, minimum, SystematicError.find(comparison, tolerance));
    }

    /** The same, with the hint found already ({@link SystematicError#find} of the same panels and tolerance). */
    public static ComparisonReport of(Picture theirs, String against, Comparison comparison, int tolerance, double minimum,
            SystematicError systematic) {
        requireArguments(theirs, against, comparison);
        return new ComparisonReport(theirs, against, comparison, theirs.margins(tolerance),
                DiffRegions.of(comparison, tolerance, REGIONS_LISTED), tolerance, minimum, -1, systematic);
    }

    /** Judged by a rubric's rule (its tolerance, minimum share and pixel limit; the comparison made with its deviation). */
    public static ComparisonReport of(Picture theirs, String against, Comparison comparison, RubricRule rule) {
        requireArguments(theirs, against, comparison);
        Objects.requireNonNull(rule, "rule must not be null");
        return of(theirs, against, comparison, rule, SystematicError.find(comparison, rule.tolerance()));
    }

    /** The same, with the hint found already ({@link SystematicError#find} of the same panels and the rule's tolerance). */
    public static ComparisonReport of(Picture theirs, String against, Comparison comparison, RubricRule rule,
            SystematicError systematic) {
        requireArguments(theirs, against, comparison);
        Objects.requireNonNull(rule, "rule must not be null");
        return new ComparisonReport(theirs, against, comparison, theirs.margins(rule.tolerance()),
                DiffRegions.of(comparison, rule.tolerance(), REGIONS_LISTED), rule.tolerance(), rule.minShare(),
                rule.maxFailing(), systematic);
    }

    /** Refuses a null picture, words or comparison where the caller hands them in, naming which. */
    private static void requireArguments(Picture theirs, String against, Comparison comparison) {
        Objects.requireNonNull(theirs, "theirs must not be null");
        Objects.requireNonNull(against, "against must not be null");
        Objects.requireNonNull(comparison, "comparison must not be null");
    }

    /** The share the verdict is on: within the tolerance, with slack; with FLIP, at most FLIP's threshold. */
    public double verdictShare() {
        return comparison.verdictShare(tolerance);
    }

    private boolean flip() {
        return comparison.metric() == Comparison.Metric.FLIP;
    }

    /** What the verdict's share counts: "within 8/255 with slack", or "within FLIP 0.130". */
    public String verdictName() {
        return flip() ? String.format(Locale.ROOT, "within FLIP %.3f", comparison.flipThreshold())
                : "within " + tolerance + "/255" + slackTail(" with slack");
    }

    /** {@code words} where the comparison has slack; nothing with deviation 0, where it has none to speak of. */
    private String slackTail(String words) {
        return comparison.deviation() == 0 ? "" : words;
    }

    /**
     * The verdict: PASS when at least {@link #minimum} percent of the panel is within the tolerance (with the
     * comparison's slack), and no more pixels fail than {@link #maxFailing} allows.
     */
    public boolean passes() {
        return verdictShare() * 100 >= minimum - 1e-9 && (maxFailing < 0 || regions.pixels() <= maxFailing);
    }

    /** "with 1 px slack", "with 2 px slack", "without slack"; and " (blurred)" for the perceptual metric. */
    public String slackName() {
        String slack = comparison.deviation() == 0 ? "no slack" : "with " + comparison.deviation() + " px slack";
        return comparison.metric() == Comparison.Metric.BLUR ? slack + ", blurred"
                : flip() ? slack + ", FLIP" : slack;
    }

    /** The report as {@code simpview compare} prints it: the shares, the patches that differ, the verdict, a hint. */
    public String text() {
        StringBuilder out = new StringBuilder();
        out.append(theirs.name()).append(" against simpview's ").append(against).append('\n');
        out.append("panel:   ").append(theirs.place().describe()).append('\n');
        out.append("margins: ").append(margins.describe()).append('\n');
        Shares exact = comparison.exact();
        Shares slack = comparison.withSlack();
        if (comparison.metric() == Comparison.Metric.BLUR) {
            out.append("metric:  both panels blurred (3x3 binomial) before they are compared\n");
        }
        if (flip()) {
            out.append(String.format(Locale.ROOT, "metric:  FLIP (LDR, %.0f pixels per degree): a pixel matches "
                    + "at FLIP %.3f or less; the shares below are colour distances%n", Flip.DEFAULT_PPD,
                    comparison.flipThreshold()));
        }
        out.append(String.format("%-22s%12s%18s%n", "panel pixels", "exactly",
                comparison.deviation() == 0 ? "no slack" : "with " + comparison.deviation() + " px slack"));
        appendRow(out, "identical", exact.identical(), slack.identical());
        appendRow(out, "within 1/255", exact.within1(), slack.within1());
        appendRow(out, "within 8/255", exact.within8(), slack.within8());
        if (flip()) {
            out.append(String.format("%-22s%12s%18s%n", "within FLIP " + String.format(Locale.ROOT, "%.3f",
                    comparison.flipThreshold()), "", Percent.of(verdictShare())));
        } else if (tolerance != 0 && tolerance != 1 && tolerance != 8) {
            appendRow(out, "within " + tolerance + "/255", comparison.share(tolerance, false), verdictShare());
        }
        appendRegions(out);
        WorstPixel look = lookAt();
        if (look != null) {
            out.append("look:    ").append(look.describe()).append('\n');
        }
        out.append(String.format("%s: %s %s (%s needed)%s%n", passes() ? "PASS" : "FAIL",
                Percent.of(verdictShare()), verdictName(), Percent.of(minimum / 100),
                maxFailing < 0 ? "" : "; " + Count.with(regions.pixels(), "pixel", "fails", "fail")
                        + String.format(" (at most %,d allowed)", maxFailing)));
        DiffRegion blob = passes() ? solidPatch(regions.largest()) : null;
        if (blob != null) {
            out.append("note: ").append(solidPatchNote(blob)).append('\n');
        }
        String bias = systematic == null ? LevelBias.note(comparison.ours(), comparison.theirs()) : null;
        if (bias != null) {
            out.append("note: ").append(bias).append('\n');
        }
        String gamma = systematic == null ? SrgbGamma.note(comparison, tolerance) : null;
        if (gamma != null) {
            out.append("note: ").append(gamma).append('\n');
        }
        String cue = systematic == null ? ReversedCue.note(comparison, tolerance) : null;
        if (cue != null) {
            out.append("note: ").append(cue).append('\n');
        }
        String background = systematic == null && !passes()
                ? Background.note(comparison.ours(), comparison.theirs(), tolerance) : null;
        if (background != null) {
            out.append("note: ").append(background).append('\n');
        }
        String colourless = passes() ? null : Colourless.note(comparison.ours(), comparison.theirs(), tolerance);
        if (colourless != null) {
            out.append("note: ").append(colourless).append('\n');
        }
        String edges = systematic == null ? EdgeShift.note(comparison, tolerance) : null;
        if (edges != null) {
            out.append("note: ").append(edges).append('\n');
        }
        if (systematic != null) {
            out.append("hint: ").append(systematic.hint(comparison.size())).append('\n');
        }
        return out.toString();
    }

    /**
     * The pixel to look at first, of a picture that fails or passes with a solid patch: the one that differs most in
     * the largest patch ({@link WorstPixel}); null for a picture that passes otherwise, has no patch, or has a hint
     * of a mistake of the whole panel (which says more than one pixel).
     */
    public WorstPixel lookAt() {
        List<DiffRegion> largest = regions.largest();
        if (largest.isEmpty() || systematic != null || passes() && solidPatch(largest) == null) {
            return null;
        }
        return WorstPixel.in(comparison, largest.get(0), tolerance);
    }

    /** How wide and tall a patch must be, at least, to be more than an edge or a line a pixel off. */
    static final int BLOB_SIDE = 4;
    /** How much of its box a patch must fill, at least: a triangle fills half, an edge's pixels on a diagonal a tenth. */
    static final double BLOB_FILL = 0.4;
    /** And how many pixels: the course's pageC differs from simpview's in a 6x6 patch of 16 (its small cubes' edges). */
    static final int BLOB_PIXELS = 64;

    /**
     * The largest of the listed patches ({@code largest}, largest first) at least {@link #BLOB_SIDE} pixels wide and
     * tall that fills {@link #BLOB_FILL} of its box with {@link #BLOB_PIXELS} or more, or null. The course's own
     * pictures, which pass, differ from simpview's in thin or sparse patches
     * only (a row along the panel's bottom, pixels along an edge); a whole
     * shape left out leaves a solid one.
     */
    public static DiffRegion solidPatch(List<DiffRegion> largest) {
        for (DiffRegion r : largest) {
            int wide = r.right() - r.left() + 1;
            int tall = r.top() - r.bottom() + 1;
            boolean solid = r.pixels() >= BLOB_PIXELS && r.pixels() >= BLOB_FILL * wide * tall;
            if (wide >= BLOB_SIDE && tall >= BLOB_SIDE && solid) {
                return r;
            }
        }
        return null;
    }

    /** What a picture that passes with a solid patch ({@link #solidPatch}) is told of it, after "note: ". */
    public static String solidPatchNote(DiffRegion patch) {
        return "it passes, but a patch of " + Count.of(patch.pixels(), "pixel") + " differs (" + patch.describe()
                + "): more than an edge, so a shape may be missing, moved or of another colour there";
    }

    /** The same briefly, for a table's note column and a progress line. */
    public static String solidPatchBrief(DiffRegion patch) {
        return "passes, but a patch of " + Count.of(patch.pixels(), "pixel") + " differs (x " + patch.left() + "-"
                + patch.right() + ", y " + patch.bottom() + "-" + patch.top() + "): a shape may be missing";
    }

    private static void appendRow(StringBuilder out, String label, double exactShare, double slackShare) {
        out.append(String.format("%-22s%12s%18s%n", label, Percent.of(exactShare), Percent.of(slackShare)));
    }

    private void appendRegions(StringBuilder out) {
        out.append(regionsText(comparison, regions, tolerance));
    }

    /**
     * The patches that differ, as a report lists them: how many pixels in how many patches differ by more than the
     * tolerance (even with slack, when the comparison has some; with FLIP, above its threshold), then the largest
     * with their boxes in panel coordinates, one a line; or that none does.
     */
    public static String regionsText(Comparison comparison, DiffRegions.Found regions, int tolerance) {
        boolean flip = comparison.metric() == Comparison.Metric.FLIP;
        String slack = comparison.deviation() == 0 ? "" : " even with slack";
        List<DiffRegion> largest = regions.largest();
        if (largest.isEmpty()) {
            return flip ? "no pixel's FLIP value is above the threshold\n"
                    : "no pixel differs by more than " + tolerance + "/255" + (slack.isEmpty() ? "" : " with slack") + "\n";
        }
        long pixels = regions.pixels();
        String what = flip ? (pixels == 1 ? "has" : "have") + " a FLIP value above the threshold"
                : (pixels == 1 ? "differs" : "differ") + " by more than " + tolerance + "/255" + slack;
        StringBuilder out = new StringBuilder(String.format("%s in %s %s%s%n(panel pixels: origin bottom-left, x right, "
                + "y up):%n", Count.of(pixels, "pixel"), Count.of(regions.count(), "patch", "patches"), what,
                regions.count() == 1 ? "" : "; the largest"));
        for (int k = 0; k < largest.size(); k++) {
            out.append("  ").append(k + 1).append(". ").append(largest.get(k).describe()).append('\n');
        }
        return out.toString();
    }
}
