package simpview.compare;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A batch's rows as a Markdown table and as CSV, one row per submitted
 * picture, then one per page asked for that a submission has no picture of
 * (result MISSING).
 */
public final class BatchTable {

    private static final String[] HEADINGS = {"file", "page", "identical", "within 1/255", "within 8/255",
        "identical (slack)", "within 1/255 (slack)", "within 8/255 (slack)", "judged share", "result", "margins", "diff",
        "note"};

    private BatchTable() {
    }

    public static String markdown(List<BatchRow> rows, int tolerance, double minimum) {
        return markdown(rows, tolerance, minimum, 1);
    }

    /** The table, its heading saying the tolerance, minimum and slack ({@code deviation} pixels) the rows are judged by. */
    public static String markdown(List<BatchRow> rows, int tolerance, double minimum, int deviation) {
        return markdown(rows, List.of(), tolerance, minimum, deviation, Comparison.Metric.EXACT,
                Comparison.FLIP_THRESHOLD);
    }

    /**
     * The same with the pages each submission lacks ({@link Wanted#missingBySubmission}), judged by
     * {@code metric}: with FLIP the judged share is that of pixels at most FLIP's threshold.
     */
    public static String markdown(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing, int tolerance,
            double minimum, int deviation, Comparison.Metric metric, double flipThreshold) {
        StringBuilder out = new StringBuilder();
        // The first assignment's panels are judged by the defaults without slack: a table of nothing else says so,
        // and a table of both says which are which.
        boolean panelsWithout = deviation != 0
                && rows.stream().anyMatch(r -> judgedByDefaults(r) && r.rule().deviation() == 0);
        boolean othersWith = rows.stream().anyMatch(r -> judgedByDefaults(r) && r.rule().deviation() == deviation);
        int judgedDeviation = panelsWithout && !othersWith ? 0 : deviation;
        String slack = judgedDeviation == 0 ? "no slack"
                : (judgedDeviation == 1 ? "one pixel of slack" : judgedDeviation + " pixels of slack")
                        + (panelsWithout ? " (the first assignment's panels: no slack)" : "");
        String judged = metric == Comparison.Metric.FLIP
                ? String.format(Locale.ROOT, "FLIP at most %.3f (the shares are colour distances)",
                        flipThreshold)
                : String.format("within %d/255 with %s%s", tolerance, slack,
                        metric == Comparison.Metric.BLUR ? ", both panels blurred" : "");
        out.append(String.format("Shares of panel pixels in percent; the result is on the judged share: %s, %s "
                + "needed.%n%n", judged, Percent.of(minimum / 100)));
        if (rows.stream().anyMatch(r -> r.rule() != null && !"*".equals(r.rule().match()))) {
            out.setLength(out.length() - System.lineSeparator().length());
            out.append(String.format("Pages the rubric names are judged by its rules (tolerance, slack, minimum, "
                    + "pixel limit) and their slack columns use their own slack.%n%n"));
        }
        out.append('|');
        for (String heading : HEADINGS) {
            out.append(' ').append(heading).append(" |");
        }
        out.append("\n|");
        for (int i = 0; i < HEADINGS.length; i++) {
            out.append(i >= 2 && i <= 8 ? "---:|" : "---|");
        }
        out.append('\n');
        for (List<String> cells : lines(rows, missing, true)) {
            out.append('|');
            for (String cell : cells) {
                out.append(' ').append(markdownCell(cell)).append(" |");
            }
            out.append('\n');
        }
        out.append('\n').append(summary(rows, missing)).append('\n');
        return out.toString();
    }

    /**
     * A cell as Markdown shows it as written: on one line, its '|' not ending the cell, and its '&lt;', '&gt;' and
     * '&amp;' not read as HTML (a file named "&lt;b&gt;x&lt;/b&gt;/page1.png" would otherwise be shown in bold, or not
     * at all).
     */
    static String markdownCell(String cell) {
        return cell.replace("\r", "").replace("\n", " / ").replace("&", "&amp;").replace("<", "&lt;")
                .replace(">", "&gt;").replace("|", "\\|");
    }

    /** Whether a row was compared under the command line's own rule, not one a rubric names. */
    private static boolean judgedByDefaults(BatchRow row) {
        return row.compared() && row.rule() != null && "*".equals(row.rule().match());
    }

    public static String csv(List<BatchRow> rows) {
        return csv(rows, List.of());
    }

    /** The same rows, and the pages each submission lacks, as CSV. */
    public static String csv(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing) {
        StringBuilder out = new StringBuilder();
        out.append(String.join(",", HEADINGS)).append("\r\n");
        for (List<String> cells : lines(rows, missing, false)) {
            for (int i = 0; i < cells.size(); i++) {
                out.append(i == 0 ? "" : ",").append(quoted(cells.get(i)));
            }
            out.append("\r\n");
        }
        return out.toString();
    }

    /** The cells of every row, then of every page a submission lacks. */
    private static List<List<String>> lines(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing,
            boolean markdown) {
        List<List<String>> lines = new ArrayList<>();
        for (BatchRow row : rows) {
            lines.add(cells(row, markdown));
        }
        for (Map.Entry<String, Wanted> lack : missing) {
            String submission = lack.getKey();
            boolean named = !submission.isEmpty() && !submission.equals(JUnitResults.TOP);
            // the pictures at the top of the folder are a submission: JUnit's suite and the web report name it so
            lines.add(List.of(named ? submission + "/" : submission, lack.getValue().target(), "", "", "", "", "", "",
                    "", "MISSING", "", "", missingNote(submission, lack.getValue())));
        }
        return lines;
    }

    /**
     * What a MISSING row says of a page a submission lacks ("" the whole folder, {@link JUnitResults#TOP} the
     * pictures at its top), and why when a file handed in tells: "no picture of page 6 in st was found;
     * st/page6.tif is named like it, but is in a format simpview does not read (...)". The web report says the same.
     */
    static String missingNote(String submission, Wanted wanted) {
        boolean top = submission.equals(JUnitResults.TOP);
        String unreadable = wanted.whyMissing(submission);
        return "no picture of " + GradescopeResults.name(wanted.target())
                + (top ? " at the top of the folder" : submission.isEmpty() ? "" : " in " + submission) + " was found"
                + (unreadable.isEmpty() ? "" : "; " + unreadable);
    }

    /**
     * E.g. "12 pictures: 9 pass, 2 fail, 1 could not be compared, 0 skipped", and when some do not count (another
     * picture of their page counts), how many: "12 pictures: 7 pass, 1 fail, 1 could not be compared, 0 skipped, 3
     * not counted (another picture of the same page counts)". A row that does not count is tallied there alone,
     * whatever it came to, so the five add up to the whole, and pass, fail and could not be compared are of the
     * rows that count: those the scores, the exit code, JUnit's suites and check's tally go by.
     */
    public static String summary(List<BatchRow> rows) {
        long[] counts = new long[BatchRow.Result.values().length];
        long notCounted = 0;
        for (BatchRow row : rows) {
            if (row.counts()) {
                counts[row.result().ordinal()]++;
            } else {
                notCounted++;
            }
        }
        long files = rows.stream().map(BatchRow::file).distinct().count();
        // a page of the first assignment is a row per panel: then every count is of rows
        String what = files == rows.size() ? Count.of(rows.size(), "picture")
                : Count.of(rows.size(), "row") + " (" + Count.of(files, "picture") + ")";
        return String.format("%s: %d pass, %d fail, %d could not be compared, %d skipped",
                what, counts[0], counts[1], counts[2], counts[3])
                + (notCounted == 0 ? "" : ", " + notCounted + " not counted (another picture of the same page counts)");
    }

    /** The same, then how many pages asked for have no picture: "...; 3 pages asked for without a picture". */
    public static String summary(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing) {
        return summary(rows, missing.size());
    }

    /**
     * The same with the count of pages missing given: results.json counts them in one submission, the table
     * and the web report in each; the words are the same.
     */
    public static String summary(List<BatchRow> rows, int missing) {
        return summary(rows) + (missing == 0 ? "" : "; " + Count.of(missing, "page") + " asked for without a picture");
    }

    private static List<String> cells(BatchRow row, boolean markdown) {
        boolean shares = row.exact() != null;
        String diff = row.diff().isEmpty() || !markdown ? row.diff() : "[diff](" + UrlPath.of(row.diff()) + ")";
        return List.of(row.file(), row.target(),
                shares ? Percent.number(row.exact().identical()) : "",
                shares ? Percent.number(row.exact().within1()) : "",
                shares ? Percent.number(row.exact().within8()) : "",
                shares ? Percent.number(row.slack().identical()) : "",
                shares ? Percent.number(row.slack().within1()) : "",
                shares ? Percent.number(row.slack().within8()) : "",
                shares ? Percent.number(row.verdict()) : "",
                row.result().name(), row.margins(), diff, row.remarks());
    }

    static String quoted(String cell) {
        if (cell.contains(",") || cell.contains("\"") || cell.contains("\n") || cell.contains("\r")) {
            return "\"" + cell.replace("\"", "\"\"") + "\"";
        }
        return cell;
    }
}
