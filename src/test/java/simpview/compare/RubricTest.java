package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The rubric: each field changes a verdict or a score the way it says, and the file is read strictly. */
class RubricTest {

    @TempDir
    Path dir;

    private static final int[] STRIPES = GradingFixtures.stripes(0);
    private static final RubricRule BASE = GradingFixtures.defaults();

    private static RubricRule with(String json) throws Exception {
        Path file = Files.createTempFile("rubric", ".json");
        try {
            Files.writeString(file, "{\"pages\": [" + json + "]}");
            return Rubric.read(file, BASE).ruleFor("page4", 4);
        } finally {
            Files.delete(file);
        }
    }

    private static Comparison compare(int[] theirs, RubricRule rule) {
        return Comparison.of(STRIPES, theirs, rule.deviation(), rule.metric());
    }

    @Test
    void toleranceDecidesWhetherAnEvenDifferencePasses() throws Exception {
        int[] offByFive = GradingFixtures.nudged(STRIPES, 5);
        assertTrue(BASE.passes(compare(offByFive, BASE)), "5/255 is within today's 8/255");
        RubricRule strict = with("{\"match\": \"4\", \"tolerance\": 4}");
        assertEquals(4, strict.tolerance());
        assertFalse(strict.passes(compare(offByFive, strict)));
    }

    @Test
    void deviationDecidesWhetherAOnePixelShiftPasses() throws Exception {
        int[] shifted = GradingFixtures.stripes(1);
        assertTrue(BASE.passes(compare(shifted, BASE)));
        RubricRule exact = with("{\"match\": \"4\", \"deviation\": 0}");
        assertFalse(exact.passes(compare(shifted, exact)));
        RubricRule two = with("{\"match\": \"4\", \"deviation\": 2}");
        assertTrue(two.passes(compare(GradingFixtures.stripes(2), two)));
    }

    @Test
    void metricFlipAndItsThresholdEachDecide() throws Exception {
        int[] grey = new int[Comparison.N * Comparison.N];
        int[] lighter = new int[Comparison.N * Comparison.N];
        Arrays.fill(grey, 0x808080);
        Arrays.fill(lighter, 0x8C8C8C); // 12/255 lighter: FLIP 0.17 on every pixel
        RubricRule wide = with("{\"match\": \"4\", \"tolerance\": 12}");
        assertTrue(wide.passes(wide.compare(grey, lighter, Comparison.N)), "within 12/255");
        RubricRule flip = with("{\"match\": \"4\", \"tolerance\": 12, \"metric\": \"flip\"}");
        assertEquals(Comparison.FLIP_THRESHOLD, flip.flipThreshold());
        assertFalse(flip.passes(flip.compare(grey, lighter, Comparison.N)), "above FLIP 0.13");
        RubricRule lenient = with("{\"match\": \"4\", \"metric\": \"flip\", \"flip_threshold\": 0.2}");
        assertEquals(0.2, lenient.flipThreshold());
        assertTrue(lenient.passes(lenient.compare(grey, lighter, Comparison.N)));
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"flip_threshold\": 2}]}").getMessage()
                .contains("2.0 is not a FLIP value, 0 to 1"));
    }

    @Test
    void minShareAndMaxFailingPixelsEachDecide() throws Exception {
        // 2 % of the panel (8,450 pixels) spoiled beyond any slack.
        int[] spoiled = GradingFixtures.spoiled(STRIPES, 8_450);
        assertEquals(8_450, compare(spoiled, BASE).failing(8));
        assertFalse(BASE.passes(compare(spoiled, BASE)), "98 % < 99 %");
        RubricRule lenient = with("{\"match\": \"4\", \"min_share\": 97.5}");
        assertTrue(lenient.passes(compare(spoiled, lenient)));
        RubricRule capped = with("{\"match\": \"4\", \"min_share\": 97.5, \"max_failing_pixels\": 8000}");
        assertFalse(capped.passes(compare(spoiled, capped)), "8,450 failing pixels > 8,000");
        RubricRule enough = with("{\"match\": \"4\", \"min_share\": 97.5, \"max_failing_pixels\": 8450}");
        assertTrue(enough.passes(compare(spoiled, enough)));
    }

    @Test
    void pointsAndPartialScoring() throws Exception {
        RubricRule rule = with("{\"match\": \"4\", \"points\": 3, \"zero_share\": 90}");
        assertEquals(3, rule.score(compare(STRIPES, rule), false), "a pass scores its points");
        Comparison twoPercentOff = compare(GradingFixtures.spoiled(STRIPES, 8_450), rule);
        assertEquals(0, rule.score(twoPercentOff, false), "all or nothing");
        // 98 % is 8/9 of the way from 90 % to 99 %: 3 * 8/9 = 2.666..., rounded down to hundredths.
        assertEquals(2.66, rule.score(twoPercentOff, true), 1e-9);
        Comparison tenPercentOff = compare(GradingFixtures.spoiled(STRIPES, 42_250 + 1), rule);
        assertEquals(0, rule.score(tenPercentOff, true), "at or below zero_share nothing");
        RubricRule capped = with("{\"match\": \"4\", \"points\": 3, \"min_share\": 97, \"max_failing_pixels\": 4225}");
        // Above min_share but twice the allowed pixels: half the points.
        assertEquals(1.5, capped.score(twoPercentOff, true), 1e-9);
    }

    @Test
    void theBlurMetricForgivesAnotherAntialiasingButNotAMissingLine() throws Exception {
        // Bands 4 px white, 4 px black; each edge is one grey pixel of 128.
        int[] ours = GradingFixtures.panel((x, row) -> switch (x % 8) {
            case 0, 1, 2 -> 0xFFFFFF;
            case 3, 7 -> 0x808080;
            default -> 0;
        });
        // Another renderer's coverage: the edge pixels 24/255 lighter and darker by turns, row by row.
        int[] theirs = GradingFixtures.panel((x, row) -> {
            int rgb = ours[row * GradingFixtures.N + x];
            if (rgb != 0x808080) {
                return rgb;
            }
            int g = row % 2 == 0 ? 128 + 24 : 128 - 24;
            return g << 16 | g << 8 | g;
        });
        RubricRule exact = BASE;
        RubricRule blur = with("{\"match\": \"4\", \"metric\": \"blur\"}");
        assertEquals(Comparison.Metric.BLUR, blur.metric());
        Comparison exactly = Comparison.of(ours, theirs, exact.deviation(), exact.metric());
        assertEquals(0.75, exactly.share(8, true), 0.002, "the edge columns, a quarter, are 24/255 off");
        assertFalse(exact.passes(exactly));
        assertTrue(blur.passes(Comparison.of(ours, theirs, blur.deviation(), blur.metric())));
        // A missing white line is not another antialiasing: it still fails when blurred.
        int[] line = GradingFixtures.panel((x, row) -> x % 16 == 5 ? 0xFFFFFF : 0);
        int[] none = GradingFixtures.panel((x, row) -> 0);
        assertFalse(blur.passes(Comparison.of(line, none, blur.deviation(), blur.metric())));
    }

    @Test
    void theFirstMatchingRuleWinsAndDefaultsFillTheRest() throws Exception {
        Files.createDirectories(dir.resolve("alt/page1"));
        Path file = dir.resolve("compare.json");
        Files.writeString(file, """
                {
                  "defaults": {"points": 2, "min_share": 98, "visibility": "after_due_date"},
                  "pages": [
                    {"match": "1", "alternates": "alt/page1", "deviation": 2},
                    {"match": "1-3", "points": 5},
                    {"match": "page*", "tolerance": 12},
                    {"match": "tomsPage?", "metric": "blur", "visibility": "hidden"}
                  ]
                }
                """);
        Rubric rubric = Rubric.read(file, BASE);
        RubricRule one = rubric.ruleFor("page1", 1);
        assertEquals(2, one.deviation());
        assertEquals(2, one.points(), "page 1's rule gives no points: the defaults' 2");
        assertEquals(dir.resolve("alt/page1").toAbsolutePath(), one.alternates().toAbsolutePath());
        assertEquals(5, rubric.ruleFor("page3", 3).points());
        RubricRule pageC = rubric.ruleFor("pageC", 0);
        assertEquals(12, pageC.tolerance());
        assertEquals(98, pageC.minShare());
        assertEquals("after_due_date", pageC.visibility());
        assertEquals(Comparison.Metric.BLUR, rubric.ruleFor("tomsPageJ", 0).metric());
        RubricRule other = rubric.ruleFor("house", 0);
        assertEquals("*", other.match(), "no rule matches: the defaults");
        assertEquals(8, other.tolerance(), "from the command line");
        assertEquals(-1, other.maxFailing());
        assertNull(other.alternates());
    }

    @Test
    void aPageJudgedInPanelsIsWorthTheirPointsAsAWholeAndAsVisibleAsTheLeastVisible() throws Exception {
        Path file = dir.resolve("compare.json");
        Files.writeString(file, """
                {
                  "defaults": {"visibility": "after_published"},
                  "pages": [
                    {"match": "a1-*-panel4", "points": 2.5, "visibility": "after_due_date"},
                    {"match": "a1-page2-panel1", "points": 0.5, "visibility": "visible"}
                  ]
                }
                """);
        Rubric rubric = Rubric.read(file, BASE);
        List<RubricRule> panels = new ArrayList<>();
        for (int k = 1; k <= 4; k++) {
            panels.add(rubric.ruleFor("a1-page2-panel" + k, 0));
        }
        RubricRule whole = RubricRule.whole(panels);
        assertEquals(0.5 + 1 + 1 + 2.5, whole.points());
        assertEquals("after_due_date", whole.visibility(), "no panel's points shown before its own rule allows");
    }

    @Test
    void badRubricsSayWhereAndWhat() throws Exception {
        assertEquals("line 2, column 18 ($.pages[0].tolerence)", placeOf("{\"pages\": [\n  {\"match\": \"1\", \"tolerence\": 3}]}"));
        CompareException deviation = bad("{\"pages\": [{\"match\": \"1\", \"deviation\": 3}]}");
        assertTrue(deviation.getMessage().contains("3.0 is not a position deviation of 0, 1 or 2 pixels"), deviation.getMessage());
        assertTrue(deviation.getMessage().contains("line 1, column"), deviation.getMessage());
        assertTrue(bad("{\"pages\": [{\"tolerance\": 3}]}").getMessage().contains("has no \"match\""));
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"metric\": \"flop\"}]}").getMessage()
                .contains("\"exact\", \"blur\" or \"flip\""));
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"alternates\": \"nowhere\"}]}").getMessage().contains("no such folder"));
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"points\": \"3\"}]}").getMessage().contains("expected points, 0 or more, found a string"));
        assertTrue(bad("{\"pages\": [").getMessage().endsWith(
                "line 1, column 12 ($.pages[0]): the file ends before its JSON does (a ']' or '}' missing?)"), "cut short");
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"min_share\": 95, \"zero_share\": 96}]}").getMessage()
                .endsWith("line 1, column 12 ($.pages[0]): the rule for \"1\" has zero_share 96 (its own, line 1, column "
                        + "44) above its min_share 95 (its own, line 1, column 27); zero_share must be at most min_share"));
    }

    /** JSON readers keep the last of a key given twice; a rubric says so, at the second, whatever the object. */
    /** A min_share or zero_share of 0.95 meant as 95 % would pass, or score, nearly any picture: an error. */
    @Test
    void aFractionWhereAShareInPercentGoesIsAnError() throws Exception {
        assertTrue(bad("{\"defaults\": {\"min_share\": 0.95}}").getMessage().endsWith(
                "line 1, column 28 ($.defaults.min_share): 0.95 is a fraction, not a share in percent (0 to 100): "
                        + "for 95 %, write 95"));
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"zero_share\": 0.5}]}").getMessage().endsWith(
                "($.pages[0].zero_share): 0.5 is a fraction, not a share in percent (0 to 100): for 50 %, write 50"));
        assertEquals(0.0, with("{\"match\": \"4\", \"min_share\": 0}").minShare(), "0 % is a share");
        assertEquals(1.0, with("{\"match\": \"4\", \"min_share\": 1}").minShare(), "and so is 1 %");
    }

    @Test
    void aKeyGivenTwiceInOneObjectIsAnError() throws Exception {
        assertTrue(bad("{\"pages\": [{\"match\": \"1\", \"points\": 2, \"points\": 5}]}").getMessage().endsWith(
                "line 1, column 40 ($.pages[0].points): \"points\" is given twice in this object (first at line 1, "
                        + "column 27); give it once"));
        assertTrue(bad("{\"defaults\": {\"min_share\": 97,\n \"min_share\": 98}}").getMessage().endsWith(
                "line 2, column 2 ($.defaults.min_share): \"min_share\" is given twice in this object (first at line 1, "
                        + "column 15); give it once"));
        assertTrue(bad("{\"pages\": [], \"defaults\": {}, \"pages\": [{\"match\": \"1\"}]}").getMessage()
                .contains("($.pages): \"pages\" is given twice in this object (first at line 1, column 2)"));
        // The same key in two objects is no repeat.
        assertEquals(3, with("{\"match\": \"4\", \"points\": 3}, {\"match\": \"5\", \"points\": 4}").points());
    }

    /** A failing page scores in part between zero_share and min_share: one above the other is said with both places. */
    @Test
    void zeroShareAboveMinShareIsAnErrorSayingWhereEachCameFrom() throws Exception {
        assertTrue(bad("{\"defaults\": {\"min_share\": 95, \"zero_share\": 96}}").getMessage().endsWith(
                "line 1, column 14 ($.defaults): \"defaults\" has zero_share 96 (line 1, column 32) above its min_share 95 "
                        + "(line 1, column 15); zero_share must be at most min_share"));
        // Inherited from the defaults: silently lowered to the rule's min_share before.
        assertTrue(bad("{\"defaults\": {\"zero_share\": 95},\n \"pages\": [{\"match\": \"8\", \"min_share\": 92}]}")
                .getMessage().endsWith("line 2, column 12 ($.pages[0]): the rule for \"8\" has zero_share 95 (from "
                        + "\"defaults\", line 1, column 15) above its min_share 92 (its own, line 2, column 27); zero_share "
                        + "must be at most min_share"));
        assertTrue(bad("{\"defaults\": {\"min_share\": 92.5},\n \"pages\": [{\"match\": \"8\", \"zero_share\": 93}]}")
                .getMessage().contains("the rule for \"8\" has zero_share 93 (its own, line 2, column 27) above its "
                        + "min_share 92.5 (from \"defaults\", line 1, column 15)"));
        // min_share from the command line (--min 92), zero_share from the file.
        Path file = dir.resolve("compare.json");
        Files.writeString(file, "{\"pages\": [{\"match\": \"8\", \"zero_share\": 95}]}");
        RubricRule min92 = RubricRule.defaults(8, 92, 1, Comparison.Metric.EXACT);
        assertTrue(assertThrows(CompareException.class, () -> Rubric.read(file, min92)).getMessage().contains(
                "has zero_share 95 (its own, line 1, column 27) above its min_share 92 (from --min: the rubric sets none)"));
        Files.writeString(file, "{\"defaults\": {\"zero_share\": 95}}");
        assertTrue(assertThrows(CompareException.class, () -> Rubric.read(file, min92)).getMessage().contains(
                "\"defaults\" has zero_share 95 (line 1, column 15) above its min_share 92 (from --min: the rubric sets "
                        + "none)"));
    }

    /** Left out everywhere, zero_share is 90 or the min_share, if lower: never an error, for a rule or the defaults. */
    @Test
    void anUnsetZeroShareFollowsTheMinShare() throws Exception {
        Path file = dir.resolve("compare.json");
        Files.writeString(file, "{\"defaults\": {\"min_share\": 85}, \"pages\": [{\"match\": \"1\", \"min_share\": 80},"
                + " {\"match\": \"2\", \"min_share\": 97}]}");
        Rubric rubric = Rubric.read(file, BASE);
        assertEquals(85, rubric.defaults().zeroShare(), "the defaults' own min_share, lower than 90");
        assertEquals(80, rubric.ruleFor("page1", 1).zeroShare());
        assertEquals(90, rubric.ruleFor("page2", 2).zeroShare());
        Files.writeString(file, "{\"defaults\": {\"min_share\": 97}}");
        assertEquals(90, Rubric.read(file, RubricRule.defaults(8, 85, 1, Comparison.Metric.EXACT)).defaults().zeroShare(),
                "the file's min_share, not --min's");
    }

    /** A rule that fits no page or scene of a run is named (its place and match): a warning, not an error. */
    @Test
    void rulesThatFitNothingInTheRunAreNamed() throws Exception {
        Path file = dir.resolve("compare.json");
        Files.writeString(file, """
                {"pages": [
                  {"match": "1-3", "points": 2},
                  {"match": "9"},
                  {"match": "pageZ"},
                  {"match": "page*"},
                  {"match": "a1-*-panel4", "metric": "flip"}
                ]}
                """);
        Rubric rubric = Rubric.read(file, BASE);
        Map<String, Integer> pages = new HashMap<>();
        for (int p = 1; p <= 8; p++) {
            pages.put("page" + p, p);
        }
        pages.put("a1-page1-panel4", 0);
        assertEquals(List.of(
                "rubric " + file + ": line 3, column 3 ($.pages[1]): the rule \"match\": \"9\" fits no page or scene of "
                        + "this run, so it is not used",
                "rubric " + file + ": line 4, column 3 ($.pages[2]): the rule \"match\": \"pageZ\" fits no page or scene "
                        + "of this run, so it is not used"), rubric.unusedRules(pages));
        // A run of scenes: the page ranges and the first assignment's panels fit nothing, a scene named pageZ does.
        List<String> scenes = rubric.unusedRules(Map.of("pageZ", 0, "tomsPageJ", 0));
        assertEquals(3, scenes.size(), scenes.toString());
        assertTrue(scenes.get(0).contains("\"match\": \"1-3\"") && scenes.get(1).contains("\"match\": \"9\"")
                && scenes.get(2).contains("\"match\": \"a1-*-panel4\""), scenes.toString());
        assertEquals(List.of(), Rubric.of(BASE).unusedRules(pages), "no file, no rules");
    }

    /** JSON that is not JSON is told in words, where it goes wrong, without the JSON library's advice. */
    @Test
    void jsonThatIsNotJsonIsToldInWords() throws Exception {
        assertTrue(bad("[1, 2]").getMessage().endsWith(
                "line 1, column 1 ($): expected an object with \"defaults\" and \"pages\", found a list ('[')"));
        assertTrue(bad("{pages: []}").getMessage().endsWith(": not valid JSON here (a word without its quotes, "
                + "a missing comma, or a comment?)"), bad("{pages: []}").getMessage());
        assertTrue(bad("{\"pages\": [] \"defaults\": {}}").getMessage().endsWith(
                "line 1, column 14 ($.pages): an object's '}', or a ',' between two of its entries, is missing"));
        assertTrue(bad("").getMessage().contains("the file ends before its JSON does"));
        assertFalse(bad("{\"pages\": [], // c\n}").getMessage().contains("setLenient"));
    }

    /** A ',' after an object's or a list's last entry is said where it is, with what was expected after it. */
    @Test
    void aTrailingCommaIsToldWhereItIs() throws Exception {
        Path file = dir.resolve("compare.json");
        assertEquals("rubric " + file + ": line 2, column 28 ($.defaults.points): a ',' after the last entry of an "
                + "object, before its '}': expected another \"key\": value after it; JSON allows no ',' there, so "
                + "remove it", bad("{\n  \"defaults\": { \"points\": 1, },\n  \"pages\": []\n}").getMessage());
        assertEquals("rubric " + file + ": line 2, column 30 ($.pages[1]): a ',' after the last item of a list, "
                + "before its ']': expected another item after it; JSON allows no ',' there, so remove it",
                bad("{\n  \"pages\": [ { \"match\": \"1\" },\n  ]\n}").getMessage());
        assertFalse(bad("{\"pages\": [], }").getMessage().contains("Expected name"));
    }

    /** "3-1" fits no page: an error naming the range, not a warning that the rule is not used. */
    @Test
    void aBackwardsPageRangeIsAnError() throws Exception {
        Path file = dir.resolve("compare.json");
        assertEquals("rubric " + file + ": line 1, column 22 ($.pages[0].match): \"match\": \"3-1\": the range 3-1 runs "
                + "backwards, so it fits no page: write it 1-3", bad("{\"pages\": [{\"match\": \"3-1\"}]}").getMessage());
        assertTrue(bad("{\"pages\": [{\"match\": \"1, 8 - 6\"}]}").getMessage().contains("the range 8 - 6 runs "
                + "backwards, so it fits no page: write it 6-8"));
        Files.writeString(file, "{\"pages\": [{\"match\": \"1-3, 5\"}, {\"match\": \"4-4\"}]}");
        assertEquals(2, Rubric.read(file, BASE).rules().size(), "ranges that run forwards, or one page, are fine");
    }

    /**
     * Every place given is where what it is about starts, whatever the JSON reader has read of it by then: the
     * opening quote of a key or a string, a bracket, the first digit of a number, the first letter of a word. Each
     * column below is counted by hand from the text (from 1).
     */
    @Test
    void placesAreWhereTheirTokensStart() throws Exception {
        String defaults = "{ \"defaults\": { ";
        assertEquals(17, defaults.length() + 1, "a value after it starts at column 17");
        assertEquals("line 1, column 27 ($.defaults.points)", placeOf(defaults + "\"points\": \"x\" } }"), "a string");
        assertEquals("line 1, column 27 ($.defaults.points)", placeOf(defaults + "\"points\": true } }"), "a word");
        assertEquals("line 1, column 27 ($.defaults.points)", placeOf(defaults + "\"points\": null } }"), "null");
        assertEquals("line 1, column 27 ($.defaults.points)", placeOf(defaults + "\"points\": [2] } }"), "a list");
        assertEquals("line 1, column 30 ($.defaults.min_share)", placeOf(defaults + "\"min_share\": 300 } }"),
                "a whole number, which the reader reads whole as it looks at it");
        assertEquals("line 1, column 30 ($.defaults.min_share)", placeOf(defaults + "\"min_share\": -3e5 } }"),
                "a number it does not");
        assertEquals("line 1, column 17 ($.defaults.bogus)", placeOf(defaults + "\"bogus\": 1 } }"), "a key");
        assertEquals("line 1, column 31 ($.defaults.visibility)", placeOf(defaults + "\"visibility\": \"nope\" } }"),
                "a string read, then found wrong");
        // What the JSON reader cannot read: at the character it stopped at.
        assertEquals("line 1, column 29 ($.defaults.points)", placeOf(defaults + "\"points\": 1 \"min_share\": 3 } }"),
                "the key where a ',' was missing");
        assertEquals("line 1, column 29 ($.defaults.points)", placeOf(defaults + "\"points\": 1 ] }"), "a ']' in an object");
        assertEquals("line 1, column 26 ($.defaults.points)", placeOf(defaults + "\"points\":x } }"), "a word without quotes");
        assertEquals("line 1, column 33 ($)", placeOf(defaults + "\"points\": 1 } } }"), "a third '}'");
        assertEquals("line 2, column 5 ($.pages[1])", placeOf("{ \"pages\": [ {\"match\": \"1\"}\n    {\"match\": \"2\"} ] }"),
                "a list's item where a ',' was missing, on the next line");
        assertEquals("line 1, column 14 ($.defaults): a ':' between a key and its value is missing",
                bad("{ \"defaults\" 1 }").getMessage().replaceFirst(".*compare.json: ", ""));
    }

    private String placeOf(String json) throws Exception {
        String message = bad(json).getMessage();
        int colon = message.indexOf(": ", message.indexOf("compare.json"));
        String rest = message.substring(colon + 2);
        return rest.substring(0, rest.indexOf("): ") + 1);
    }

    private CompareException bad(String json) throws Exception {
        Path file = dir.resolve("compare.json");
        Files.writeString(file, json);
        return assertThrows(CompareException.class, () -> Rubric.read(file, BASE));
    }
}
