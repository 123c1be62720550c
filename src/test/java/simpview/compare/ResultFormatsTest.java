package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.StringReader;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.SchemaFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;

/**
 * Gradescope's results.json and JUnit XML of one batch: two submissions,
 * alice and bob, each missing page 3; a pass, two fails, a broken picture
 * and a file that names no page.
 */
class ResultFormatsTest {

    private static final int[] STRIPES = GradingFixtures.stripes(0);
    private static final RubricRule ONE = GradingFixtures.defaults();
    private static final RubricRule TWO = new RubricRule("2", 8, 1, 99, -1, 2.5, 90, Comparison.Metric.EXACT, null,
            "after_due_date", Comparison.FLIP_THRESHOLD);

    private static List<BatchRow> rows(boolean partial) throws Exception {
        int[] spoiled = GradingFixtures.spoiled(STRIPES, 8_450); // 98 %: fails, 8/9 of the points when partial
        return List.of(
                GradingFixtures.row("alice/page1.png", "1 (seed 361)", STRIPES, STRIPES, ONE, partial, null),
                GradingFixtures.row("alice/page2.png", "2 (seed 361)", STRIPES, spoiled, TWO, partial, null),
                GradingFixtures.row("bob/page1.png", "1 (seed 361)", STRIPES, GradingFixtures.stripes(2), ONE, partial, null),
                BatchRow.broken("bob/page2.png", "2 (seed 361)", "bob/page2.png: cannot be read as a picture", TWO),
                BatchRow.skipped("bob/notes.png", "no page number in the name"));
    }

    private static final List<Wanted> WANTED = List.of(new Wanted("1 (seed 361)", ONE), new Wanted("2 (seed 361)", TWO),
            new Wanted("3 (seed 361)", ONE));

    @Test
    void gradescopeResultsHaveTheFieldsTypesAndTotals() throws Exception {
        for (boolean partial : new boolean[] {false, true}) {
            JsonObject results = JsonParser.parseString(GradescopeResults.json(rows(partial), WANTED, 3.2)).getAsJsonObject();
            assertEquals(Set.of("score", "execution_time", "output", "stdout_visibility", "tests"), results.keySet());
            assertTrue(results.get("score").getAsJsonPrimitive().isNumber());
            assertEquals(4, results.get("execution_time").getAsInt(), "whole seconds, rounded up");
            assertTrue(results.get("output").getAsJsonPrimitive().isString());
            assertTrue(Set.of("hidden", "after_due_date", "after_published", "visible")
                    .contains(results.get("stdout_visibility").getAsString()));
            JsonArray tests = results.getAsJsonArray("tests");
            // Four pictures compared or broken, page 3 missing once (one submission per results.json).
            assertEquals(5, tests.size());
            double sum = 0;
            double max = 0;
            Map<String, Double> scores = new HashMap<>();
            for (JsonElement element : tests) {
                JsonObject test = element.getAsJsonObject();
                assertTrue(Set.of("name", "score", "max_score", "output", "visibility", "number", "tags")
                        .containsAll(test.keySet()), test.keySet().toString());
                assertTrue(test.get("name").getAsJsonPrimitive().isString());
                assertTrue(test.get("score").getAsJsonPrimitive().isNumber());
                assertTrue(test.get("max_score").getAsJsonPrimitive().isNumber());
                assertTrue(test.get("output").getAsJsonPrimitive().isString());
                assertTrue(test.get("number").getAsJsonPrimitive().isString());
                assertTrue(Set.of("hidden", "after_due_date", "after_published", "visible").contains(test.get("visibility").getAsString()));
                for (JsonElement tag : test.getAsJsonArray("tags")) {
                    assertTrue(tag.getAsJsonPrimitive().isString());
                }
                double score = test.get("score").getAsDouble();
                assertTrue(score >= 0 && score <= test.get("max_score").getAsDouble(), test.toString());
                sum += score;
                max += test.get("max_score").getAsDouble();
                scores.put(test.get("name").getAsString(), score);
            }
            assertEquals(sum, results.get("score").getAsDouble(), 1e-9, "the total is the sum of the tests");
            assertEquals(1 + 2.5 + 1 + 2.5 + 1, max, 1e-9);
            assertEquals(1.0, scores.get("page 1 (seed 361) (alice/page1.png)"));
            assertEquals(partial ? 2.22 : 0.0, scores.get("page 2 (seed 361) (alice/page2.png)"), 1e-9, "2.5 * 8/9, rounded down");
            assertEquals(0.0, scores.get("page 2 (seed 361) (bob/page2.png)"), "broken: nothing");
            assertEquals(0.0, scores.get("page 3 (seed 361) (no picture)"));
            assertEquals(partial ? 1 + 2.22 : 1, sum, 1e-9);
        }
        JsonObject results = JsonParser.parseString(GradescopeResults.json(rows(false), WANTED, 3.2)).getAsJsonObject();
        JsonObject failed = results.getAsJsonArray("tests").get(1).getAsJsonObject();
        String output = failed.get("output").getAsString();
        assertTrue(output.startsWith("FAIL: 98.00 % of panel pixels within 8/255 with 1 px slack (99.00 % needed)"), output);
        assertTrue(output.contains("x 0-649, y "), "the region: " + output);
        assertEquals("after_due_date", failed.get("visibility").getAsString(), "the rule's visibility");
        assertTrue(results.get("output").getAsString().contains("bob/notes.png: no page number in the name"));
    }

    @Test
    void resultsJsonAndTheTableCountMissingPagesInTheSameWords() throws Exception {
        String json = JsonParser.parseString(GradescopeResults.json(rows(false), WANTED, 3.2)).getAsJsonObject()
                .get("output").getAsString();
        // results.json is one submission (page 3 lacking once); the table counts alice's and bob's.
        String counts = "5 pictures: 1 pass, 2 fail, 1 could not be compared, 1 skipped";
        assertTrue(json.startsWith(counts + "; 1 page asked for without a picture\n"), json);
        String table = BatchTable.markdown(rows(false), Wanted.missingBySubmission(WANTED, rows(false)), 8, 99, 1,
                Comparison.Metric.EXACT, Comparison.FLIP_THRESHOLD);
        assertTrue(table.endsWith("\n" + counts + "; 2 pages asked for without a picture\n"), table);
    }

    @Test
    void junitXmlIsValidAgainstTheSchemaAndCountsAddUp() throws Exception {
        String xml = JUnitResults.xml(rows(false), WANTED, 3.2);
        SchemaFactory schemas = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
        schemas.newSchema(new StreamSource(getClass().getResourceAsStream("junit.xsd")))
                .newValidator().validate(new StreamSource(new StringReader(xml)));

        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        Document doc = factory.newDocumentBuilder().parse(new InputSource(new StringReader(xml)));
        Element root = doc.getDocumentElement();
        assertEquals("testsuites", root.getTagName());
        NodeList suites = root.getElementsByTagName("testsuite");
        assertEquals(2, suites.getLength(), "alice and bob");
        int tests = 0;
        int failures = 0;
        int errors = 0;
        int skipped = 0;
        for (int s = 0; s < suites.getLength(); s++) {
            Element suite = (Element) suites.item(s);
            NodeList cases = suite.getElementsByTagName("testcase");
            assertEquals(Integer.parseInt(suite.getAttribute("tests")), cases.getLength());
            assertEquals(Integer.parseInt(suite.getAttribute("failures")), suite.getElementsByTagName("failure").getLength());
            assertEquals(Integer.parseInt(suite.getAttribute("errors")), suite.getElementsByTagName("error").getLength());
            assertEquals(Integer.parseInt(suite.getAttribute("skipped")), suite.getElementsByTagName("skipped").getLength());
            tests += cases.getLength();
            failures += suite.getElementsByTagName("failure").getLength();
            errors += suite.getElementsByTagName("error").getLength();
            skipped += suite.getElementsByTagName("skipped").getLength();
            for (int c = 0; c < cases.getLength(); c++) {
                assertEquals(suite.getAttribute("name"), ((Element) cases.item(c)).getAttribute("classname"));
            }
        }
        // alice: page1 pass, page2 fail, page3 missing; bob: page1 fail, page2 error, notes skipped, page3 missing.
        assertEquals(7, tests);
        assertEquals(4, failures);
        assertEquals(1, errors);
        assertEquals(1, skipped);
        assertEquals(String.valueOf(tests), root.getAttribute("tests"));
        assertEquals(String.valueOf(failures), root.getAttribute("failures"));
        assertEquals("3.200", root.getAttribute("time"));
        Element alice = (Element) suites.item(0);
        assertEquals("alice", alice.getAttribute("name"));
        Element failure = (Element) alice.getElementsByTagName("failure").item(0);
        assertEquals("98.00 % within 8/255 with 1 px slack, 99.00 % needed", failure.getAttribute("message"));
        assertEquals("page 2 (seed 361) (alice/page2.png)", ((Element) failure.getParentNode()).getAttribute("name"));
        assertFalse(xml.contains("null"));
    }

    /**
     * A file name with a control character in it (Linux allows any but '/' and NUL) was written into the XML as it
     * is, which XML 1.0 allows in no form: the whole class's file could not be read. It is U+FFFD there now.
     */
    @Test
    void aControlCharacterInAFileNameLeavesTheXmlReadable() throws Exception {
        List<BatchRow> rows = List.of(
                GradingFixtures.row("ann/page1\u0001.png", "1 (seed 361)", STRIPES, STRIPES, ONE, false, null),
                BatchRow.broken("ann/page2\u001b.png", "2 (seed 361)", "ann/page2\u001b.png: cannot be read", ONE));
        String xml = JUnitResults.xml(rows, List.of(), 1);
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new InputSource(new StringReader(xml)));
        NodeList cases = doc.getElementsByTagName("testcase");
        assertEquals("page 1 (seed 361) (ann/page1\ufffd.png)", ((Element) cases.item(0)).getAttribute("name"));
        assertEquals("ann/page2\ufffd.png: cannot be read",
                ((Element) doc.getElementsByTagName("error").item(0)).getAttribute("message"));
    }

    @Test
    void theSchemaRefusesWhatJUnitDoesNotKnow() throws Exception {
        // The check above could fail: a testcase without a name, or an unknown element, is refused.
        SchemaFactory schemas = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
        var validator = schemas.newSchema(new StreamSource(getClass().getResourceAsStream("junit.xsd"))).newValidator();
        for (String bad : List.of("<testsuites><testsuite name=\"a\" tests=\"1\"><testcase/></testsuite></testsuites>",
                "<testsuites><testsuite name=\"a\" tests=\"1\"><case name=\"x\"/></testsuite></testsuites>",
                "<testsuites><testsuite tests=\"1\"/></testsuites>")) {
            org.junit.jupiter.api.Assertions.assertThrows(org.xml.sax.SAXException.class,
                    () -> validator.validate(new StreamSource(new StringReader(bad))), bad);
        }
    }
}
