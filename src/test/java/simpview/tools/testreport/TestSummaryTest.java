package simpview.tools.testreport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The summary and HTML report that the build writes from the JUnit XML after the tests. */
class TestSummaryTest {

    private static final String REPORT = """
            <?xml version="1.0" encoding="UTF-8"?>
            <testsuite name="JUnit Jupiter" tests="3" skipped="1" failures="1" errors="0">
            <testcase name="passes()" classname="a.PassingTest" time="0.5"/>
            <testcase name="fails()" classname="a.FailingTest" time="1,200.25">
            <failure message="expected: &lt;1&gt; but was: &lt;2&gt;" type="AssertionFailedError">trace line 1
            trace line 2</failure>
            </testcase>
            <testcase name="needsCourse()" classname="a.CourseTest" time="0">
            <skipped><![CDATA[the course's scene files are not at /x: this test needs them and is skipped]]></skipped>
            </testcase>
            </testsuite>
            """;

    @TempDir
    Path dir;

    @Test
    void countsEachOutcomeAndNamesSkipsWithTheirReasonAndFailures() throws IOException {
        Files.writeString(dir.resolve("TEST-junit-jupiter.xml"), REPORT);
        Files.writeString(dir.resolve("not-a-report.txt"), "ignored");
        TestResults results = TestResults.read(dir);
        assertEquals("Tests: 1 passed, 1 failed, 1 skipped", TestSummary.countsLine(results));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        TestSummary.print(results, null, new PrintStream(bytes, true, StandardCharsets.UTF_8));
        String out = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(out.contains("skipped: a.CourseTest > needsCourse(): the course's scene files are not at /x"), out);
        assertTrue(out.contains("FAILED:  a.FailingTest > fails(): expected: <1> but was: <2>"), out);
        assertFalse(out.contains("PassingTest"), "passing tests are only counted: " + out);
    }

    @Test
    void theHtmlReportShowsTheTraceEscaped() throws IOException {
        Files.writeString(dir.resolve("TEST-junit-jupiter.xml"), REPORT);
        Path index = HtmlReport.write(TestResults.read(dir), dir.resolve("html"));
        String html = Files.readString(index);
        assertTrue(html.contains("Tests: 1 passed, 1 failed, 1 skipped"), html);
        assertTrue(html.contains("expected: &lt;1&gt; but was: &lt;2&gt;"), html);
        assertTrue(html.contains("<pre>trace line 1\ntrace line 2</pre>"), html);
        assertTrue(html.contains("<td>a.FailingTest</td><td>0</td><td>1</td><td>0</td><td>1200.250</td>"), html);
    }

    @Test
    void aSkipsReasonIsShownWithoutTheExceptionThatCarriedIt() {
        assertEquals("the course's files are not at /x",
                TestSummary.firstLine("org.opentest4j.TestAbortedException: Assumption failed: the course's files are not at /x\n"
                        + "\tat org.junit.jupiter.api.Assumptions.throwAssumptionFailed(Assumptions.java:340)"));
        assertEquals("expected: <1> but was: <2>",
                TestSummary.firstLine("org.opentest4j.AssertionFailedError: expected: <1> but was: <2>"));
        assertEquals("Tests: kept as they are", TestSummary.firstLine("Tests: kept as they are"));
    }

    @Test
    void noResultsIsSaidPlainly() throws IOException {
        assertEquals("Tests: no results were written (did the test task run?)",
                TestSummary.countsLine(TestResults.read(dir.resolve("missing"))));
    }
}
