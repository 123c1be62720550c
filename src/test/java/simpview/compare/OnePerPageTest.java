package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * Each page counts once per submission: of several pictures of a page, the one named the page and nothing
 * else, or the first by name; the others score nothing and are worth nothing, in every result.
 */
class OnePerPageTest {

    private static final int[] STRIPES = GradingFixtures.stripes(0);
    private static final RubricRule ONE = GradingFixtures.defaults();
    private static final Set<String> PLAIN = Set.of("page3.png", "bob/page_3.png");

    /** ann: four pictures of page 3, only page3.png named plainly; bob: two, page_3.png plainly; cy: two, neither. */
    private static List<BatchRow> rows() throws Exception {
        int[] wrong = GradingFixtures.stripes(2);
        return List.of(
                GradingFixtures.row("old_page3.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("page3 copy.png", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("page3.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                BatchRow.broken("page3_v2.png", "3 (seed 361)", "page3_v2.png: cannot be read as a picture", ONE),
                GradingFixtures.row("bob/Page3 copy.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("bob/page_3.png", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("cy/page3_a.png", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("cy/page3_b.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                BatchRow.skipped("cy/notes.png", "no page number in the name"));
    }

    @Test
    void thePicturesNamedThePageAloneOrElseTheFirstByNameCount() throws Exception {
        List<BatchRow> marked = OnePerPage.bySubmission(rows(), PLAIN::contains, file -> false);
        assertEquals(List.of("page3.png", "bob/page_3.png", "cy/page3_a.png", "cy/notes.png"),
                marked.stream().filter(BatchRow::counts).map(BatchRow::file).toList());
        BatchRow copy = marked.get(1);
        assertEquals("page3.png counts for page 3 (seed 361) instead: its name is the page's name and nothing else",
                copy.notCounted());
        assertEquals(0, copy.score());
        assertEquals(0, copy.rule().points(), "worth nothing");
        assertEquals(BatchRow.Result.FAIL, copy.result(), "still compared and listed as it came out");
        assertTrue(copy.remarks().startsWith("not counted: page3.png counts for page 3 (seed 361) instead"), copy.remarks());
        assertEquals("bob/page_3.png counts for page 3 (seed 361) instead: its name is the page's name and nothing else",
                marked.get(4).notCounted(), "the one named plainly, though it is not first and fails");
        assertEquals("cy/page3_a.png counts for page 3 (seed 361) instead: no picture's name is the page's name alone, "
                + "and it is the first by name", marked.get(7).notCounted());
        // the tally is of the rows that count (as check's, JUnit's and the exit code are), those that do not apart:
        // the broken page3_v2.png and the failing "page3 copy.png" are neither a failure nor an error of the run
        assertEquals("9 pictures: 1 pass, 2 fail, 0 could not be compared, 1 skipped, 5 not counted (another picture "
                + "of the same page counts)", BatchTable.summary(marked));
    }

    /**
     * Of pictures named the page equally well, the truest format counts: PNG, then BMP (exact too), then GIF (256
     * colours), then JPEG (lossy), whatever their order by name; a name that is the page's alone still comes first.
     */
    @Test
    void ofPicturesNamedAsWellThePngCountsOverABmpAGifAndAJpeg() throws Exception {
        int[] wrong = GradingFixtures.stripes(2);
        List<BatchRow> rows = List.of(
                GradingFixtures.row("ann/page3.bmp", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("ann/page3.gif", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("ann/page3.jpg", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("ann/page3.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("bob/page3.gif", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("bob/page3.jpeg", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("cy/page3 copy.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("cy/page3.jpg", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("dee/page3.PNG", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("dee/page3_v2.bmp", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null));
        Set<String> plain = Set.of("ann/page3.bmp", "ann/page3.gif", "ann/page3.jpg", "ann/page3.png", "bob/page3.gif",
                "bob/page3.jpeg", "cy/page3.jpg");
        List<BatchRow> marked = OnePerPage.bySubmission(rows, plain::contains, file -> false);
        assertEquals(List.of("ann/page3.png", "bob/page3.gif", "cy/page3.jpg", "dee/page3.PNG"),
                marked.stream().filter(BatchRow::counts).map(BatchRow::file).toList());
        String both = "ann/page3.png counts for page 3 (seed 361) instead: both are named the page's name and nothing "
                + "else, and ";
        assertEquals(both + "a PNG is what simpview asks for (a BMP is exact too)", marked.get(0).notCounted());
        assertEquals(both + "a PNG is exact, a GIF is not", marked.get(1).notCounted());
        assertEquals(both + "a PNG is exact, a JPEG is not", marked.get(2).notCounted());
        assertEquals("bob/page3.gif counts for page 3 (seed 361) instead: both are named the page's name and nothing "
                + "else, and a GIF changes only colours past 256 of them, a JPEG changes those near every edge",
                marked.get(5).notCounted());
        assertEquals("cy/page3.jpg counts for page 3 (seed 361) instead: its name is the page's name and nothing else",
                marked.get(6).notCounted(), "the name decides before the format");
        assertEquals("dee/page3.PNG counts for page 3 (seed 361) instead: no picture's name is the page's name alone, "
                + "and a PNG is what simpview asks for (a BMP is exact too)", marked.get(9).notCounted());
    }

    /**
     * A draft kept in a folder (old/page3.png) came before the page3.png at the top by the alphabet, and counted
     * instead of it: the picture in fewer folders counts, before its format is looked at.
     */
    @Test
    void ofPicturesNamedAsWellTheOneNearerTheTopCounts() throws Exception {
        int[] wrong = GradingFixtures.stripes(2);
        List<BatchRow> rows = List.of(
                GradingFixtures.row("ann/backup/page3.png", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("ann/page3.jpg", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                GradingFixtures.row("old/page3.png", "3 (seed 361)", STRIPES, wrong, ONE, false, null),
                GradingFixtures.row("page3.png", "3 (seed 361)", STRIPES, STRIPES, ONE, false, null));
        Set<String> plain = Set.of("ann/backup/page3.png", "ann/page3.jpg", "old/page3.png", "page3.png");
        List<BatchRow> mine = OnePerPage.asOne(rows.subList(2, 4), plain::contains);
        assertEquals(List.of("page3.png"), mine.stream().filter(BatchRow::counts).map(BatchRow::file).toList());
        assertEquals("page3.png counts for page 3 (seed 361) instead: both are named the page's name and nothing "
                + "else, and it is nearer the top of the submission's folder", mine.get(0).notCounted());
        List<BatchRow> ann = OnePerPage.bySubmission(rows.subList(0, 2), plain::contains, file -> false);
        assertEquals(List.of("ann/page3.jpg"), ann.stream().filter(BatchRow::counts).map(BatchRow::file).toList(),
                "in ann's folder, the JPEG at its top over the PNG in backup/");
    }

    @Test
    void gradescopesTotalIsWhatThePagesAskedForAreWorth() throws Exception {
        List<Wanted> wanted = List.of(new Wanted("3 (seed 361)", ONE), new Wanted("4", ONE));
        // results.json is one submission's: one picture of page 3 counts in the whole folder
        JsonObject results = JsonParser.parseString(GradescopeResults.json(OnePerPage.asOne(rows(), PLAIN::contains),
                wanted, 1)).getAsJsonObject();
        double max = 0;
        for (JsonElement test : results.getAsJsonArray("tests")) {
            max += test.getAsJsonObject().get("max_score").getAsDouble();
        }
        assertEquals(2, max, 1e-9, "page 3 and page 4, a point each");
        assertEquals(1, results.get("score").getAsDouble(), 1e-9, "page3.png passes; page 4 is missing");
        JsonObject copy = results.getAsJsonArray("tests").get(1).getAsJsonObject();
        assertEquals("page 3 (seed 361) (page3 copy.png)", copy.get("name").getAsString());
        assertEquals(0, copy.get("max_score").getAsDouble());
        assertTrue(copy.get("output").getAsString().startsWith("NOT COUNTED (scores nothing): page3.png counts for "
                + "page 3 (seed 361) instead"), copy.get("output").getAsString());
        assertTrue(copy.get("tags").toString().contains("NOT COUNTED"), copy.toString());

        String xml = JUnitResults.xml(OnePerPage.bySubmission(rows(), PLAIN::contains, file -> false), wanted, 1);
        assertTrue(xml.contains("<testsuite name=\"submission\" id=\"0\" tests=\"5\" failures=\"1\" errors=\"0\" "
                + "skipped=\"3\">"), "page3.png passes, three skipped, page 4 missing: " + xml);
        assertTrue(xml.contains("<testcase name=\"page 3 (seed 361) (page3_v2.png)\" classname=\"submission\"><skipped "
                + "message=\"not counted: page3.png counts for page 3 (seed 361) instead: its name is the page's name and "
                + "nothing else\">"), xml);
        assertTrue(xml.contains("<testsuite name=\"bob\" id=\"1\" tests=\"3\" failures=\"2\" errors=\"0\" skipped=\"1\">"),
                "bob's page_3.png counts, and fails: " + xml);

        String table = StudentTable.text(OnePerPage.asOne(rows(), PLAIN::contains), List.of());
        assertTrue(table.contains("page3 copy.png: not counted, page3.png counts for page 3 (seed 361) instead"), table);
        assertTrue(table.endsWith("1 of 1 pictures pass; 7 pictures not counted; 1 other file not checked (each said above)\n"), table);
    }
}
