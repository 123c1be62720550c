package simpview.compare;

/**
 * One submitted picture in a batch: what it was compared with and how it
 * came out, or why it could not be.
 *
 * @param file the picture, relative to the submissions folder
 * @param target the page or scene it was matched to, or "" when none matched
 * @param exact shares without slack, or null when there was no comparison
 * @param slack shares with one pixel of slack, or null
 * @param verdict the share the result is on (within the tolerance, with slack), or NaN
 * @param result PASS, FAIL, ERROR (the picture or the scene is broken) or SKIPPED (no page matches)
 * @param margins whether the margins are white: "white", "not white" or ""
 * @param diff the diff image, relative to the table, or ""
 * @param note where the panel was found, or the problem
 */
public record BatchRow(String file, String target, Shares exact, Shares slack, double verdict,
        Result result, String margins, String diff, String note) {

    public enum Result { PASS, FAIL, ERROR, SKIPPED }

    public static BatchRow compared(String file, String target, ComparisonReport report, String diff) {
        return new BatchRow(file, target, report.comparison().exact(), report.comparison().withSlack(),
                report.verdictShare(), report.passes() ? Result.PASS : Result.FAIL,
                report.margins().white() ? "white" : "not white", diff, "panel at " + report.theirs().place().describe());
    }

    public static BatchRow broken(String file, String target, String problem) {
        return new BatchRow(file, target, null, null, Double.NaN, Result.ERROR, "", "", problem);
    }

    public static BatchRow skipped(String file, String why) {
        return new BatchRow(file, "", null, null, Double.NaN, Result.SKIPPED, "", "", why);
    }
}
