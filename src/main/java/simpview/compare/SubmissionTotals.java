package simpview.compare;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import simpview.pages.SceneList;

/**
 * Each submission's total, the number a teacher enters in a gradebook: the sum of the scores of its rows (each page
 * counted once, {@link OnePerPage}: a picture that does not count scores nothing and is worth nothing) out of what
 * its rows and the pages it lacks are worth, and how many of its rows that count pass, fail or could not be
 * compared, and how many pages it lacks. The same numbers as Gradescope's {@code results.json} of that submission's
 * folder graded alone ({@link GradescopeResults}: its top-level score, and the sum of its tests' {@code max_score}),
 * rounded to hundredths as it rounds them. The table and the web report show them after the rows, and
 * {@code totals.csv} holds them for a gradebook to import.
 */
public final class SubmissionTotals {

    /** The CSV's headings: what a gradebook's import is told each column is. */
    private static final String[] CSV_HEADINGS = {"submission", "score", "max_score", "passed", "failed", "errors",
        "missing"};
    /** The Markdown table's headings, in the words of the table's last line. */
    private static final String[] HEADINGS = {"submission", "score", "out of", "pass", "fail", "could not be compared",
        "missing"};

    private SubmissionTotals() {
    }

    /**
     * One submission's total.
     *
     * @param submission its name as the JUnit suites and the web report give it: its first-level folder,
     *     {@link JUnitResults#TOP} for the pictures at the top of the folder (or a folder that is one student's),
     *     or a picture's path where each picture is a student's (one scene for every picture)
     * @param score the sum of its rows' scores, rounded to hundredths
     * @param maxScore what its rows and the pages it lacks are worth, rounded to hundredths
     * @param passed its rows that count and pass
     * @param failed its rows that count and fail
     * @param errors its rows that count and could not be compared
     * @param missing the pages asked for that it has no picture of
     */
    public record Total(String submission, double score, double maxScore, int passed, int failed, int errors,
            int missing) {
    }

    /**
     * The totals of every submission that has a row scored or a page missing, in natural order of their names.
     *
     * @param rows the batch's rows, those that do not count marked so
     * @param missing the pages each submission lacks, by the submission's key (as {@link Wanted#missingBySubmission}
     *     gives them: "" for the whole folder)
     * @param submissionOf the key of a row's submission, as {@code missing} keys them (a picture that is a
     *     student's of its own: its path)
     */
    public static List<Total> of(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing,
            Function<String, String> submissionOf) {
        Map<String, double[]> points = new LinkedHashMap<>(); // score, max score
        Map<String, int[]> counts = new LinkedHashMap<>(); // passed, failed, errors, missing
        for (BatchRow row : rows) {
            if (row.result() == BatchRow.Result.SKIPPED) {
                continue; // no page: no test in results.json, no score
            }
            String key = shown(submissionOf.apply(row.file()));
            double[] p = points.computeIfAbsent(key, k -> new double[2]);
            int[] c = counts.computeIfAbsent(key, k -> new int[4]);
            p[0] += row.score();
            p[1] += row.rule() == null ? 0 : row.rule().points();
            if (row.counts()) {
                switch (row.result()) {
                    case PASS -> c[0]++;
                    case FAIL -> c[1]++;
                    case ERROR -> c[2]++;
                    default -> { }
                }
            }
        }
        for (Map.Entry<String, Wanted> lack : missing) {
            String key = shown(lack.getKey());
            points.computeIfAbsent(key, k -> new double[2])[1] += lack.getValue().rule().points();
            counts.computeIfAbsent(key, k -> new int[4])[3]++;
        }
        List<Total> totals = new ArrayList<>();
        points.forEach((key, p) -> {
            int[] c = counts.get(key);
            totals.add(new Total(key, GradescopeResults.hundredths(p[0]), GradescopeResults.hundredths(p[1]), c[0], c[1],
                    c[2], c[3]));
        });
        totals.sort((a, b) -> SceneList.NATURAL_ORDER.compare(a.submission(), b.submission()));
        return totals;
    }

    /** A submission's name as shown: the whole folder ("") is {@link JUnitResults#TOP}. */
    private static String shown(String key) {
        return key.isEmpty() ? JUnitResults.TOP : key;
    }

    /**
     * The totals as a short Markdown table with a line above it, to follow the table of rows: "" when there are
     * none. {@code csv}: the file that holds them too, or null when none is written.
     */
    public static String markdown(List<Total> totals, String csv) {
        if (totals.isEmpty()) {
            return "";
        }
        StringBuilder out = new StringBuilder();
        out.append(String.format("%nEach submission's total: the sum of its scores (each page counted once) out of "
                + "what its pages are worth, as results.json scores the submission graded alone%s.%n%n",
                csv == null ? "" : "; also in " + csv));
        out.append('|');
        for (String heading : HEADINGS) {
            out.append(' ').append(heading).append(" |");
        }
        out.append("\n|---|");
        out.append("---:|".repeat(HEADINGS.length - 1)).append('\n');
        for (List<String> cells : cells(totals)) {
            out.append('|');
            for (String cell : cells) {
                out.append(' ').append(BatchTable.markdownCell(cell)).append(" |");
            }
            out.append('\n');
        }
        return out.toString();
    }

    /** The totals as CSV, a line a submission under the headings a gradebook's import maps. */
    public static String csv(List<Total> totals) {
        StringBuilder out = new StringBuilder();
        out.append(String.join(",", CSV_HEADINGS)).append("\r\n");
        for (List<String> cells : cells(totals)) {
            for (int i = 0; i < cells.size(); i++) {
                out.append(i == 0 ? "" : ",").append(BatchTable.quoted(cells.get(i)));
            }
            out.append("\r\n");
        }
        return out.toString();
    }

    /** Each total's cells: its name, score and maximum as scores are read ("6.76", "10"), then the counts. */
    static List<List<String>> cells(List<Total> totals) {
        List<List<String>> lines = new ArrayList<>();
        for (Total t : totals) {
            lines.add(List.of(t.submission(), GradescopeResults.points(t.score()),
                    GradescopeResults.points(t.maxScore()), String.valueOf(t.passed()), String.valueOf(t.failed()),
                    String.valueOf(t.errors()), String.valueOf(t.missing())));
        }
        return lines;
    }

    /** The headings of the web report's table, those of the Markdown table. */
    static List<String> headings() {
        return List.of(HEADINGS);
    }
}
