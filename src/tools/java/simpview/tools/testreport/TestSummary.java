package simpview.tools.testreport;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.regex.Pattern;

/**
 * Run by the build after the tests: {@code TestSummary RESULTS [REPORTS]}
 * prints how many tests passed, failed and were skipped, names each skipped
 * test with its reason and each failed one, and when REPORTS is given
 * writes the HTML report there. Exits 0: the test task itself fails the build.
 */
public final class TestSummary {

    /** "org.opentest4j.TestAbortedException: " and the like, at the start of a trace's first line. */
    private static final Pattern THROWN = Pattern.compile("^(?:[a-z_][\\w$]*\\.)+[A-Z][\\w$]*(?:Exception|Error): ");
    private static final String ASSUMPTION = "Assumption failed: ";

    private TestSummary() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: TestSummary RESULTS_DIR [HTML_REPORT_DIR]");
            System.exit(2);
        }
        TestResults results = TestResults.read(Path.of(args[0]));
        Path report = args.length == 2 ? HtmlReport.write(results, Path.of(args[1])) : null;
        print(results, report, System.out);
    }

    static void print(TestResults results, Path report, PrintStream out) {
        out.println();
        out.println(countsLine(results));
        for (TestCase c : results.with(TestCase.Outcome.SKIPPED)) {
            out.println("  skipped: " + c.title() + ": " + firstLine(c.message()));
        }
        for (TestCase c : results.with(TestCase.Outcome.FAILED)) {
            out.println("  FAILED:  " + c.title() + ": " + firstLine(c.message()));
        }
        if (report != null) {
            out.println("Report: " + report.toAbsolutePath().normalize());
        }
    }

    /** "Tests: 330 passed, 0 failed, 2 skipped", or a line saying none ran. */
    public static String countsLine(TestResults results) {
        if (results.cases().isEmpty()) {
            return "Tests: no results were written (did the test task run?)";
        }
        return "Tests: " + results.count(TestCase.Outcome.PASSED) + " passed, "
                + results.count(TestCase.Outcome.FAILED) + " failed, "
                + results.count(TestCase.Outcome.SKIPPED) + " skipped";
    }

    /** The first line of a message, without the exception class a stack trace starts with. */
    static String firstLine(String text) {
        String line = text.lines().findFirst().orElse("").strip();
        line = THROWN.matcher(line).replaceFirst("");
        if (line.startsWith(ASSUMPTION)) {
            line = line.substring(ASSUMPTION.length());
        }
        return line.isEmpty() ? "(no reason given)" : line;
    }
}
