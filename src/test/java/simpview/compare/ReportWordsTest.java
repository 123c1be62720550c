package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * What the table (Markdown), JUnit and the web report say of the same rows in the same words: the submission of
 * the pictures at the top of a class's folder, why a page is missing, and names that hold what Markdown or HTML
 * would read as markup.
 */
class ReportWordsTest {

    private static final RubricRule ONE = GradingFixtures.defaults();
    private static final int[] STRIPES = GradingFixtures.stripes(0);

    private static String markdown(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing) {
        return BatchTable.markdown(rows, missing, 8, 99, 1, Comparison.Metric.EXACT, Comparison.FLIP_THRESHOLD);
    }

    @Test
    void thePicturesAtTheTopOfAClassFolderAreTheSubmissionNamedSubmissionEverywhere() throws Exception {
        List<BatchRow> rows = List.of(
                GradingFixtures.row("page1.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("ann/page2.png", "2 (seed 361)", STRIPES, STRIPES, ONE, false, null));
        List<Wanted> wanted = List.of(new Wanted("1 (seed 361)", ONE), new Wanted("2 (seed 361)", ONE));
        List<Map.Entry<String, Wanted>> missing = Wanted.missingBySubmission(wanted, rows);

        String table = markdown(rows, missing);
        assertTrue(table.contains("| submission | 2 (seed 361) |  |  |  |  |  |  |  | MISSING |  |  | no picture of page 2 "
                + "(seed 361) at the top of the folder was found |"), table);
        assertFalse(table.contains("|  | 2 (seed 361) |"), "no MISSING row without its submission: " + table);
        String xml = JUnitResults.xml(rows, wanted, 1);
        assertTrue(xml.contains("<testcase name=\"page 2 (seed 361) (no picture)\" classname=\"submission\">"), xml);
        String html = HtmlReport.page(rows, missing, Path.of("web"), null);
        assertTrue(html.contains("<tr class=\"row missing\"><td>submission</td><td></td><td>page 2 (seed 361)</td>"),
                html);
    }

    @Test
    void theWebReportSaysWhyAPageIsMissingAsTheTableDoes() throws Exception {
        List<BatchRow> rows = List.of(GradingFixtures.row("zed/page1.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false,
                null));
        List<Wanted> wanted = List.of(new Wanted("1 (seed 361)", ONE), new Wanted("5", ONE, List.of("zed/page5.webp")));
        List<Map.Entry<String, Wanted>> missing = Wanted.missingBySubmission(wanted, rows);
        String why = "no picture of page 5 in zed was found; zed/page5.webp is named like it, but is in a format simpview "
                + "does not read (it reads PNG, JPEG, GIF and BMP)";

        assertTrue(markdown(rows, missing).contains("| " + why + " |"), markdown(rows, missing));
        String html = HtmlReport.page(rows, missing, Path.of("web"), null);
        assertTrue(html.contains("<td>" + why + "</td>"), html);
        assertFalse(html.contains("no picture of this page"), html);
    }

    /**
     * A picture that does not count (another of its page does) is no failure in the web report, as in the tallies
     * and JUnit: a failing "page3 copy.png" beside the page3.png that counts is a grey row that says it is not
     * counted, not a red FAIL among the student's rows; the details still give its result.
     */
    @Test
    void theWebReportSaysWhichPictureDoesNotCount() throws Exception {
        int[] wrong = GradingFixtures.stripes(2);
        List<BatchRow> rows = OnePerPage.bySubmission(List.of(
                GradingFixtures.row("ann/page3 copy.png", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("ann/page3.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null)),
                "ann/page3.png"::equals, file -> false);

        String html = HtmlReport.page(rows, List.of(), Path.of("web"), null);
        assertTrue(html.contains("<tr class=\"row notcounted\"><td>ann</td><td>ann/page3 copy.png</td>"
                + "<td>page 3 (seed 361)</td><td>FAIL, not counted</td>"), html);
        assertFalse(html.contains("<tr class=\"row fail\">"), html);
        assertTrue(html.contains("<tr class=\"row pass\"><td>ann</td><td>ann/page3.png</td>"), html);
    }

    /**
     * Why a page is missing ends a sentence once: a why that ends in "?" (a picture named for a page there is not,
     * asked whether it was meant as the page lacked) is not followed by ".", in JUnit's text or Gradescope's.
     */
    @Test
    void aWhyThatEndsInAQuestionMarkIsNotEndedAgain() throws Exception {
        List<BatchRow> rows = List.of(GradingFixtures.row("bob/page1.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false,
                null));
        String asked = "bob/page9.png is named for page 9, and there is no page 9 (the pages are 1 to 8): was it meant "
                + "as page 3, which bob lacks?";
        List<Wanted> wanted = List.of(new Wanted("1 (seed 361)", ONE), new Wanted("3", ONE, List.of(),
                Wanted.PAGE_EXAMPLE, List.of(), List.of(new Wanted.Misnamed("bob/page9.png", asked))));

        String xml = JUnitResults.xml(rows, wanted, 1);
        assertTrue(xml.contains(" which bob lacks?</failure>"), xml);
        assertFalse(xml.contains("lacks?."), xml);
        String json = GradescopeResults.json(rows, wanted, 1);
        assertTrue(json.contains(" which bob lacks?\""), json);
        assertFalse(json.contains("lacks?."), json);
    }

    @Test
    void theTableShowsNamesAsTheyAreWrittenNotAsMarkup() throws Exception {
        List<BatchRow> rows = List.of(
                GradingFixtures.row("<b>x</b>/page1 <i>.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("a|b & c/page1.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false, null));
        String table = markdown(rows, List.of());
        assertTrue(table.contains("| &lt;b&gt;x&lt;/b&gt;/page1 &lt;i&gt;.png | 1 (seed 361) |"), table);
        assertTrue(table.contains("| a\\|b &amp; c/page1.png | 1 (seed 361) |"), table);
        assertFalse(table.contains("<b>") || table.contains("<i>"), table);
    }

    @Test
    void theWebReportWrapsTheLongLinesOfADetailsText() throws Exception {
        List<BatchRow> rows = List.of(GradingFixtures.row("ann/page1.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false,
                null));
        String html = HtmlReport.page(rows, List.of(), Path.of("web"), null);
        // a hint: line is a few hundred characters; in a <pre> it would run off the box
        assertTrue(html.matches("(?s).*\\bpre \\{[^}]*white-space: pre-wrap;[^}]*}.*"), html);
    }
}
