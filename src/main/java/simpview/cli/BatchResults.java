package simpview.cli;

import static simpview.cli.CompareBatch.CSV;
import static simpview.cli.CompareBatch.TABLE;
import static simpview.cli.CompareBatch.TOTALS;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;
import java.util.function.Predicate;
import simpview.cli.CompareBatch.Outputs;
import simpview.compare.BatchRow;
import simpview.compare.BatchTable;
import simpview.compare.Count;
import simpview.compare.GradescopeResults;
import simpview.compare.HtmlReport;
import simpview.compare.JUnitResults;
import simpview.compare.OnePerPage;
import simpview.compare.OutputFiles;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.StudentTable;
import simpview.compare.SubmissionTotals;
import simpview.compare.Wanted;
import simpview.pages.SceneList;

/**
 * A batch's results: its rows, each page counted once per submission, against what each submission was asked for,
 * written to the tables, totals and reports its {@link Outputs} name; the teacher's table or the student's printed;
 * and the exit code they make, a diff image that could not be written failing the run as a table would.
 */
final class BatchResults {

    private final Rubric rubric;
    private final PrintWriter out;
    private final PrintWriter err;
    /** What its messages start with: the command that runs the batch ("simpview compare: "). */
    private final String says;
    /**
     * For the student's table: the command that compares one failing row's picture alone, which names the pixel to
     * look at first and how to inspect it; null for a row it cannot be given for. None unless {@link #nextSteps}
     * sets it.
     */
    private Function<BatchRow, String> nextStep = row -> null;

    /** The results of a batch judged by {@code rubric}, printed on {@code out}; said on {@code err} after {@code says}. */
    BatchResults(Rubric rubric, PrintWriter out, PrintWriter err, String says) {
        this.rubric = rubric;
        this.out = out;
        this.err = err;
        this.says = says;
    }

    /** Follows the student's table by {@code command} of each failing row for which it gives one. */
    void nextSteps(Function<BatchRow, String> command) {
        this.nextStep = command;
    }

    /**
     * Writes and prints the results, each page counted once per submission ({@link OnePerPage}: the pictures of
     * a page but one are rows that score nothing), and says what the exit code is: 0 when every row that
     * counts passes and no submission lacks a page asked for.
     */
    int write(Path dir, List<BatchRow> compared, List<Wanted> wanted, Outputs outputs, double seconds,
            Predicate<String> plainlyNamed, Predicate<String> alone, String instead, boolean oneStudent) {
        // A student's folder (check's, or one whose pictures are at its top and in one folder) is one submission,
        // however its pictures are foldered; a class's, one a first-level folder.
        List<BatchRow> rows = oneStudent ? OnePerPage.asOne(compared, plainlyNamed)
                : OnePerPage.bySubmission(compared, plainlyNamed, alone);
        Function<String, String> submissionOf = oneStudent ? file -> "" : JUnitResults::submission;
        RubricRule base = rubric.defaults();
        List<Map.Entry<String, Wanted>> missing = oneStudent
                ? Wanted.missing(wanted, rows).stream().map(w -> Map.entry("", w)).toList()
                : Wanted.missingBySubmission(wanted, rows);
        Path outDir = outputs.outDir();
        // each submission's total, by the submission its pages are counted in (a picture of its own where each
        // picture is a student's), as results.json would score it graded alone
        List<SubmissionTotals.Total> totals = SubmissionTotals.of(rows, missing,
                oneStudent ? submissionOf : file -> alone.test(file) ? file : submissionOf.apply(file));
        String markdown = BatchTable.markdown(rows, missing, base.tolerance(), base.minShare(), base.deviation(),
                base.metric(), base.flipThreshold()) + SubmissionTotals.markdown(totals, outDir == null ? null : TOTALS);
        try {
            OutputPaths files = outputs.files();
            if (outDir != null) {
                writeString(files, outDir.resolve(TABLE), markdown);
                writeString(files, outDir.resolve(CSV), BatchTable.csv(rows, missing));
                writeString(files, outDir.resolve(TOTALS), SubmissionTotals.csv(totals));
            }
            if (outputs.gradescope() != null) {
                // results.json is one submission's, however its pictures are foldered (see grading.md)
                writeString(files, outputs.gradescope(),
                        GradescopeResults.json(OnePerPage.asOne(compared, plainlyNamed), wanted, seconds));
                sayIfAClass(compared, outputs.gradescope());
            }
            if (outputs.junit() != null) {
                writeString(files, outputs.junit(), JUnitResults.xml(rows, wanted, seconds, submissionOf));
            }
            if (outputs.html() != null) {
                HtmlReport.write(rows, Wanted.missingBySubmission(wanted, rows, submissionOf), outputs.html(), outDir,
                        submissionOf, totals);
                files.wrote(outputs.html().resolve(HtmlReport.INDEX));
            }
        } catch (IOException e) {
            err.println(says + e.getMessage()); // "cannot write report/compare.md: ...", and why
            return ExitCode.SCENE_ERROR;
        }
        if (outputs.student()) {
            out.print(StudentTable.text(rows, Wanted.missing(wanted, rows), nextStep));
        } else {
            out.print(markdown);
            if (outDir != null) {
                out.println("table: " + outDir.resolve(TABLE) + " and " + outDir.resolve(CSV));
                out.println("totals: " + outDir.resolve(TOTALS));
            }
        }
        if (rows.isEmpty()) {
            // a folder holding only a zip: the student is told to unzip it
            err.println(says + "no pictures (.png, .jpg, .gif, .bmp) found"
                    + (instead.isEmpty() ? "" : " in " + dir + ": " + instead));
            return ExitCode.SCENE_ERROR;
        }
        boolean allPass = rows.stream().filter(BatchRow::counts)
                .allMatch(r -> r.result() != BatchRow.Result.FAIL && r.result() != BatchRow.Result.ERROR);
        if (outputs.student() && rows.stream().noneMatch(r -> r.result() == BatchRow.Result.PASS)) {
            return ExitCode.SCENE_ERROR;
        }
        // a page asked for without a picture is work not done: it fails as a failing picture does
        return allPass && missing.isEmpty() ? ExitCode.OK : ExitCode.SCENE_ERROR;
    }

    /** Writes a table or report as {@link OutputFiles#writeString} does, and tells {@code files} it is written. */
    private static void writeString(OutputPaths files, Path file, String text) throws IOException {
        OutputFiles.writeString(file, text);
        files.wrote(file);
    }

    /**
     * Says so when results.json was written for what looks like a class: one page handed in by the pictures of
     * several first-level folders. It is one submission's (Gradescope grades one student at a time), so all of
     * them were counted as one, each page once; the class's own results are the table, JUnit and the web report.
     */
    private void sayIfAClass(List<BatchRow> compared, Path results) {
        Map<String, Set<String>> foldersOfPage = new HashMap<>();
        for (BatchRow row : compared) {
            String folder = JUnitResults.submission(row.file());
            if (row.compared() && !folder.equals(JUnitResults.TOP)) {
                foldersOfPage.computeIfAbsent(row.page(), p -> new TreeSet<>(SceneList.NATURAL_ORDER)).add(folder);
            }
        }
        Set<String> folders = foldersOfPage.values().stream().filter(f -> f.size() > 1).findFirst().orElse(null);
        if (folders == null) {
            return;
        }
        List<String> named = folders.stream().limit(3).map(f -> f + "/").toList();
        err.println(says + "note: " + results + " is one submission's, as Gradescope grades one student at a time, "
                + "but " + UsageWords.joined(named, "and") + (folders.size() > 3 ? " and others" : "")
                + " each hold a picture of one page: they were counted as one submission, each page once. For a "
                + "class, read the table, --junit or --html (a submission a first-level folder), or run compare "
                + "on each student's folder for a results.json of its own.");
    }

    /**
     * Whether some diff image could not be written, said once on stderr with the first reason (each row
     * says its own): an output file that cannot be written fails the run, as a table that cannot does.
     */
    boolean saidUnwrittenDiffs(List<BatchRow> rows, DiffPlan diffs) {
        List<BatchRow> unwritten = rows.stream().filter(r -> r.compared() && r.diff().isEmpty()
                && diffs.writes(r.result() == BatchRow.Result.PASS)).toList();
        if (unwritten.isEmpty()) {
            return false;
        }
        String first = unwritten.get(0).note().replaceFirst("^" + DiffPlan.NOT_WRITTEN, "");
        err.println(says + Count.of(unwritten.size(), "diff image") + " could not be written ("
                + first + (unwritten.size() == 1 ? "" : "; each row says why") + ")");
        return true;
    }
}
