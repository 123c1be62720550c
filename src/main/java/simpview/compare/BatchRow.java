package simpview.compare;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One submitted picture in a batch: what it was compared with and how it
 * came out, or why it could not be.
 *
 * @param file the picture, relative to the submissions folder
 * @param target the page or scene it was matched to, or "" when none matched
 * @param exact shares without slack, or null when there was no comparison
 * @param slack shares with slack (the rule's position deviation), or null
 * @param verdict the share the result is on (within the tolerance, with slack), or NaN
 * @param result PASS, FAIL, ERROR (the picture or the scene is broken) or SKIPPED (no page matches)
 * @param margins whether the margins are white: "white", "not white" or ""
 * @param diff the diff image, relative to the table, or ""
 * @param note where the panel was found, or the problem
 * @param rule the rule it was judged by, or null when it was skipped
 * @param score its score under the rule (0 when it could not be compared)
 * @param failing pixels beyond the tolerance even with slack (0 when not compared)
 * @param regions the largest of those patches, largest first
 * @param alternate the accepted alternate picture it matched best, relative to its folder, or "" for simpview's own
 * @param size the side of the panel compared, in pixels: 650 for a page, 300 for a panel of the first assignment's
 * @param notCounted "" when the row counts; else why not: which other picture of its page counts in its
 *     submission, and why that one ({@link OnePerPage}). It is compared and listed all the same, but scores
 *     nothing and is worth nothing.
 * @param panelHint what its whole panel looks like when one mistake explains it, or null
 * @param emptyShare of a row scored in part (with --partial, one that fails), the share an empty panel gets
 *     against simpview's under its rule ({@link RubricRule#emptyShare}), which its zero point is at least; else NaN
 * @param format the format its file's bytes were decoded as ({@link Picture#format}), or null when it was not read
 * @param colourless of a row that fails, whether its panel has no colour where simpview's has ({@link Colourless})
 */
public record BatchRow(String file, String target, Shares exact, Shares slack, double verdict,
        Result result, String margins, String diff, String note, RubricRule rule, double score, int failing,
        List<DiffRegion> regions, String alternate, int size, String notCounted, PanelHint panelHint,
        double emptyShare, PictureFormat format, boolean colourless) {

    public enum Result { PASS, FAIL, ERROR, SKIPPED }

    public static BatchRow compared(String file, String target, ComparisonReport report, String diff) {
        return compared(file, target, report, diff, null, 0, "");
    }

    public static BatchRow compared(String file, String target, ComparisonReport report, String diff,
            RubricRule rule, double score, String alternate) {
        return compared(file, target, report, diff, rule, score, alternate, Double.NaN);
    }

    /** The same, scored in part with {@code emptyShare} the share an empty panel gets (NaN: not measured). */
    public static BatchRow compared(String file, String target, ComparisonReport report, String diff,
            RubricRule rule, double score, String alternate, double emptyShare) {
        String note = "panel at " + report.theirs().place().describe()
                + (alternate.isEmpty() ? "" : "; matched the accepted alternate " + alternate);
        return new BatchRow(file, target, report.comparison().exact(), report.comparison().withSlack(),
                report.verdictShare(), report.passes() ? Result.PASS : Result.FAIL,
                report.margins().white() ? "white" : "not white", diff, note, rule, score,
                report.regions().pixels(), report.regions().largest(), alternate, report.comparison().size(), "",
                report.systematic(), emptyShare, report.theirs().format(), !report.passes()
                        && Colourless.note(report.comparison().ours(), report.comparison().theirs(),
                                report.tolerance()) != null);
    }

    /**
     * One panel of a page of several (the first assignment's four), compared under {@code rule}: no margins of
     * its own (the page was found by the white rings around its panels); {@code hint} what the whole panel looks
     * like ({@link PanelHint#of}), or null.
     */
    public static BatchRow panel(String file, String target, Comparison comparison, RubricRule rule, double score,
            String diff, String note, PanelHint hint) {
        return panel(file, target, comparison, rule, score, diff, note, hint, Double.NaN);
    }

    /** The same, scored in part with {@code emptyShare} the share an empty panel gets (NaN: not measured). */
    public static BatchRow panel(String file, String target, Comparison comparison, RubricRule rule, double score,
            String diff, String note, PanelHint hint, double emptyShare) {
        DiffRegions.Found regions = DiffRegions.of(comparison, rule.tolerance(), ComparisonReport.REGIONS_LISTED);
        boolean passes = rule.passes(comparison);
        return new BatchRow(file, target, comparison.exact(), comparison.withSlack(),
                comparison.verdictShare(rule.tolerance()), passes ? Result.PASS : Result.FAIL, "",
                diff, note, rule, score, regions.pixels(), regions.largest(), "", comparison.size(), "", hint,
                emptyShare, null, !passes && Colourless.note(comparison.ours(), comparison.theirs(),
                        rule.tolerance()) != null);
    }

    public static BatchRow broken(String file, String target, String problem) {
        return broken(file, target, problem, null);
    }

    public static BatchRow broken(String file, String target, String problem, RubricRule rule) {
        return new BatchRow(file, target, null, null, Double.NaN, Result.ERROR, "", "", problem, rule, 0, 0,
                List.of(), "", Comparison.N, "", null, Double.NaN, null, false);
    }

    public static BatchRow skipped(String file, String why) {
        return new BatchRow(file, "", null, null, Double.NaN, Result.SKIPPED, "", "", why, null, 0, 0, List.of(), "",
                Comparison.N, "", null, Double.NaN, null, false);
    }

    /** The same row with another note (and no diff image). */
    public BatchRow withoutDiff(String why) {
        return new BatchRow(file, target, exact, slack, verdict, result, margins, "", why, rule, score, failing,
                regions, alternate, size, notCounted, panelHint, emptyShare, format, colourless);
    }

    /** The same row with {@code hint} what its panel looks like ({@link OtherPage}: another page, found after it failed). */
    public BatchRow withHint(PanelHint hint) {
        return new BatchRow(file, target, exact, slack, verdict, result, margins, diff, note, rule, score, failing,
                regions, alternate, size, notCounted, hint, emptyShare, format, colourless);
    }

    /** The same row of a picture whose bytes were decoded as {@code decoded} (a first-assignment panel's page). */
    public BatchRow decodedAs(PictureFormat decoded) {
        return new BatchRow(file, target, exact, slack, verdict, result, margins, diff, note, rule, score, failing,
                regions, alternate, size, notCounted, panelHint, emptyShare, decoded, colourless);
    }

    /**
     * The same row not counted, {@code why} (another picture of its page counts): it scores nothing and its
     * rule is worth nothing (Gradescope's max_score 0), so the total stays what the pages asked for are worth.
     */
    public BatchRow notCounted(String why) {
        RubricRule worthNothing = new RubricRule(rule.match(), rule.tolerance(), rule.deviation(), rule.minShare(),
                rule.maxFailing(), 0, rule.zeroShare(), rule.metric(), rule.alternates(), rule.visibility(),
                rule.flipThreshold());
        return new BatchRow(file, target, exact, slack, verdict, result, margins, diff, note, worthNothing, 0, failing,
                regions, alternate, size, why, panelHint, emptyShare, format, colourless);
    }

    /**
     * The page it is of: its target, or for a panel of a page compared panel by panel (the first assignment's,
     * whose panels are smaller than a page's), that page ("A1 page 2" for "A1 page 2 panel 4 (antialiased)"), so
     * that a picture of it that cannot be read is of the same page as its panels.
     */
    public String page() {
        int at = target.indexOf(" panel ");
        return size != Comparison.N && at >= 0 ? target.substring(0, at) : target;
    }

    /** Its panel's number (1, 2, ...) when it is one panel of a page compared panel by panel; 0 else. */
    public int panel() {
        int at = target.indexOf(" panel ");
        if (size == Comparison.N || at < 0) {
            return 0;
        }
        int from = at + " panel ".length();
        int end = from;
        while (end < target.length() && Character.isDigit(target.charAt(end))) {
            end++;
        }
        return end > from ? Integer.parseInt(target.substring(from, end)) : 0;
    }

    /** Whether it counts: it is the picture of its page that is scored in its submission (or was skipped). */
    public boolean counts() {
        return notCounted.isEmpty();
    }

    /**
     * Its note, after why it does not count when it does not, and before the mistake that explains its panel
     * when one does: the table's note column.
     */
    public String remarks() {
        String remarks = counts() ? note : "not counted: " + notCounted + (note.isEmpty() ? "" : "; " + note);
        List<String> told = new ArrayList<>();
        if (!remarks.isEmpty()) {
            told.add(remarks);
        }
        if (panelHint != null) {
            told.add("looks " + panelHint.brief());
        }
        told.addAll(briefNotes());
        return String.join("; ", told);
    }

    /**
     * The patch that makes its pass worth a look ({@link ComparisonReport#solidPatch}): of a page, a scene or a
     * first-assignment panel that passes, its largest solid patch, or null. A panel of the first assignment's is
     * judged without slack, so an antialiased line a shade off is a patch too; but such patches are thin, and
     * the course's own pictures of its five pages, all passing, have no solid one.
     */
    public DiffRegion solidPatch() {
        return result == Result.PASS ? ComparisonReport.solidPatch(regions) : null;
    }

    /**
     * What is worth telling of it besides its shares and its hint, whole, one sentence each: the Gradescope and
     * JUnit feedback, the web report and {@code check} give them after "note: ".
     */
    public List<String> notes() {
        return notes(false);
    }

    /** The same briefly: the table's note column and the progress line. */
    public List<String> briefNotes() {
        return notes(true);
    }

    private List<String> notes(boolean brief) {
        List<String> notes = new ArrayList<>();
        if (brief) { // the whole of it is in the FAIL line of the Gradescope and JUnit feedback and the web report
            String limit = pixelLimit(true);
            if (!limit.isEmpty()) {
                notes.add(limit);
            }
        }
        DiffRegion patch = solidPatch();
        if (patch != null) {
            notes.add(brief ? ComparisonReport.solidPatchBrief(patch) : ComparisonReport.solidPatchNote(patch));
        }
        if (colourless && result == Result.FAIL) {
            notes.add(brief ? Colourless.BRIEF : Colourless.NOTE);
        }
        String format = formatAdvice();
        if (!format.isEmpty()) {
            notes.add(format);
        }
        return notes;
    }

    /**
     * Of a row that fails and has more failing pixels than its rule's {@code max_failing_pixels} allows, how many
     * fail and how many may; "" for any other. Briefly ("449 pixels fail, at most 300 allowed"; of a panel of the
     * first assignment's, after "panel 2: "), for the table's note column and the progress line, whose FAIL and
     * share alone ("FAIL 99.89 %" where 99 % is needed) read as a wrong verdict; whole for {@code check}'s table,
     * with the share beside what its rule needs, so that the reason is plain whichever of the two failed it.
     */
    public String pixelLimit(boolean brief) {
        if (result != Result.FAIL || rule == null || rule.maxFailing() < 0 || failing <= rule.maxFailing()) {
            return "";
        }
        String count = Count.with(failing, "pixel", "fails", "fail");
        if (brief) {
            return (panel() > 0 ? "panel " + panel() + ": " : "")
                    + String.format(Locale.ROOT, "%s, at most %,d allowed", count, rule.maxFailing());
        }
        boolean shareEnough = rule.shareReaches(verdict);
        return String.format(Locale.ROOT, "%s%s, and the rubric's max_failing_pixels allows at most %,d; its share, %s, "
                + "%s the %s needed", shareEnough ? "it fails on its pixel count, not its share: " : "", count,
                rule.maxFailing(), Percent.of(verdict), shareEnough ? "reaches" : "is below",
                Percent.of(rule.minShare() / 100)) + (shareEnough ? "" : " too");
    }

    /**
     * What a picture that fails is told of its file's format ({@link PictureFormat#failingAdvice(String,
     * PictureFormat, boolean)}, as a single picture's {@code compare} tells it), by the format its bytes were
     * decoded as: "" for a PNG or a BMP, and for a picture that does not fail; not told to hand in a PNG when it
     * does not count.
     */
    public String formatAdvice() {
        if (result != Result.FAIL) {
            return "";
        }
        return PictureFormat.failingAdvice(file, format, counts());
    }

    /** What its verdict's share counts, e.g. "within 8/255 with 1 px slack" or "within FLIP 0.130". */
    public String verdictName() {
        if (rule.metric() == Comparison.Metric.FLIP) {
            return String.format(Locale.ROOT, "within FLIP %.3f", rule.flipThreshold());
        }
        return "within " + rule.tolerance() + "/255 " + (rule.deviation() == 0 ? "without slack"
                : "with " + rule.deviation() + " px slack") + (rule.metric() == Comparison.Metric.BLUR ? ", blurred" : "");
    }

    /** Whether it was compared (PASS or FAIL). */
    public boolean compared() {
        return exact != null;
    }
}
