package simpview.cli;

import static simpview.testing.Images.writePng;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;
import static simpview.testing.Images.paint;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;

/** Grading from the command line: a rubric with alternates, the three result files, and {@code simpview check}. */
class GradingCommandTest {

    @TempDir
    Path dir;

    /** The page with a 100x100 block of its panel painted cyan: about 2.4 % of the panel wrong. */
    private static BufferedImage spoiled(int number) throws Exception {
        return paint(page(number), 200, 200, 300, 300, 0x00FFFF);
    }

    @Test
    void aPictureMatchingAnAcceptedAlternatePasses() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("alice/page1.png"), spoiled(1));
        writePng(subs.resolve("bob/page1.png"), spoiled(2)); // the wrong page: no alternate is like it
        writePng(dir.resolve("alternates/page1-other-method.png"), spoiled(1));
        writePng(dir.resolve("alternates/page2-alt.png"), spoiled(2)); // names page 2: not an alternate of page 1
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"pages\": [{\"match\": \"1-2\", \"alternates\": \"alternates\"}]}");

        CliRun without = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", dir.resolve("a").toString());
        assertEquals(ExitCode.SCENE_ERROR, without.exitCode(), without.err());
        assertTrue(without.out().contains("| alice/page1.png | 1 (seed 361) |") && without.out().contains("| FAIL |"), without.out());

        CliRun with = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--rubric", rubric.toString(),
                "--out-dir", dir.resolve("b").toString());
        List<String> csv = Files.readAllLines(dir.resolve("b/compare.csv"));
        assertTrue(csv.get(1).startsWith("alice/page1.png,1 (seed 361),100.00,"), csv.get(1));
        assertTrue(csv.get(1).contains(",PASS,") && csv.get(1).contains("matched the accepted alternate page1-other-method.png"),
                csv.get(1));
        assertTrue(csv.get(2).startsWith("bob/page1.png,") && csv.get(2).contains(",FAIL,"), csv.get(2));
        assertFalse(csv.get(2).contains("alternate"), "page2-alt.png names page 2: " + csv.get(2));
        assertEquals(ExitCode.SCENE_ERROR, with.exitCode(), "bob still fails");
    }

    @Test
    void aBatchWritesGradescopeJUnitAndHtmlAndABrokenFileStopsNothing() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("page1.png"), page(1));
        writePng(subs.resolve("page2.png"), spoiled(2));
        Files.write(subs.resolve("page3.png"), new byte[] {1, 2, 3});
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"defaults\": {\"points\": 4, \"zero_share\": 90}}");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-4", "--rubric", rubric.toString(),
                "--partial", "--gradescope", out.resolve("results.json").toString(), "--junit",
                out.resolve("results.xml").toString(), "--html", out.resolve("report").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertFalse(run.showsStackTrace(), run.err());
        assertTrue(run.err().contains("page3.png: ERROR"), run.err());
        JsonObject results = JsonParser.parseString(Files.readString(out.resolve("results.json"))).getAsJsonObject();
        assertEquals(4, results.getAsJsonArray("tests").size(), "pages 1, 2 and 3 found, page 4 missing");
        double page2 = results.getAsJsonArray("tests").get(1).getAsJsonObject().get("score").getAsDouble();
        assertTrue(page2 > 0 && page2 < 4, "partial: " + page2);
        assertEquals(4 + page2, results.get("score").getAsDouble(), 1e-9);
        String xml = Files.readString(out.resolve("results.xml"));
        assertTrue(xml.contains("<testsuite name=\"submission\" id=\"0\" tests=\"4\" failures=\"2\" errors=\"1\" skipped=\"0\">"), xml);
        String html = Files.readString(out.resolve("report/index.html"));
        assertEquals(4, html.split("<tr class=\"row ", -1).length - 1, "three pictures and the missing page");
        assertTrue(Files.isRegularFile(out.resolve("report/diffs/page2-diff.png")), "the diffs beside the report");
        assertTrue(html.contains("src=\"diffs/page2-diff.png\""), "linked relative to the page");
    }

    @Test
    void diffsFailingWritesTheDiffsOfThoseThatDoNotPassOnly() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("page1.png"), page(1));
        writePng(subs.resolve("page2.png"), spoiled(2));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir", out.toString(),
                "--diffs", "failing");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertFalse(Files.exists(out.resolve("diffs/page1-diff.png")), "page 1 passes");
        assertTrue(Files.isRegularFile(out.resolve("diffs/page2-diff.png")));
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2",
                "--out-dir", out.toString(), "--diffs", "some").exitCode());
    }

    /**
     * Page 4 with an 80x60 block of its panel painted black over a shape's edge: 3,447 pixels differ, in one solid
     * patch, and the page still passes (99.18 %).
     */
    private static BufferedImage holed() throws Exception {
        return paint(page(4), 300, 240, 380, 300, 0x000000);
    }

    @Test
    void aPassWithASolidPatchSaysSoInEveryResult() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("st/page4.png"), holed());
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "4", "--out-dir", out.toString(),
                "--gradescope", out.resolve("results.json").toString(), "--junit", out.resolve("results.xml").toString(),
                "--html", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        String brief = "passes, but a patch of 3,447 pixels differs (x 250-329, y 400-459): a shape may be missing";
        String whole = "it passes, but a patch of 3,447 pixels differs (x 250-329, y 400-459 (80x60): 3,447 pixels): "
                + "more than an edge, so a shape may be missing";
        assertTrue(run.err().contains("st/page4.png: PASS 99.18 %; " + brief), run.err());
        String table = Files.readString(out.resolve("compare.md"));
        assertTrue(table.contains("| PASS |") && table.contains("(a 750x750 page); " + brief + " |"), table);
        String csv = Files.readAllLines(out.resolve("compare.csv")).get(1);
        assertTrue(csv.contains(",PASS,") && csv.contains(brief), csv);
        String output = JsonParser.parseString(Files.readString(out.resolve("results.json"))).getAsJsonObject()
                .getAsJsonArray("tests").get(0).getAsJsonObject().get("output").getAsString();
        assertTrue(output.startsWith("PASS: 99.18 %") && output.contains("\nnote: " + whole), output);
        assertTrue(Files.readString(out.resolve("index.html")).contains("note: " + whole), "the web report's view");
        String xml = Files.readString(out.resolve("results.xml"));
        assertTrue(xml.matches("(?s).*<testcase name=\"page 4 \\(st/page4.png\\)\" classname=\"st\"><system-out>PASS: "
                + "99.18 %[^<]*\nnote: " + Pattern.quote(whole) + "[^<]*</system-out></testcase>.*"), xml);

        CliRun check = CliRun.of("check", subs.resolve("st").toString(), "--pages", "4");
        assertEquals(ExitCode.OK, check.exitCode(), check.err());
        assertTrue(check.out().contains("\nnote: page4.png (page 4): " + whole), check.out());
    }

    /**
     * A picture whose share passes but whose failing pixels are more than the rubric's max_failing_pixels allows
     * fails, and says why where its share alone is shown (99.18 % FAIL, where 99 % is needed, read as a wrong
     * verdict): the progress line, the table's note column and check's table.
     */
    @Test
    void aFailByTheRubricsPixelLimitSaysSoBesideItsShare() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("st/page4.png"), holed());
        Path rubric = Files.writeString(dir.resolve("compare.json"),
                "{\"pages\": [{\"match\": \"4\", \"max_failing_pixels\": 1000}]}");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "4", "--rubric", rubric.toString(),
                "--out-dir", out.toString(), "--diffs", "none");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        String brief = "3,447 pixels fail, at most 1,000 allowed";
        assertTrue(run.err().contains("st/page4.png: FAIL 99.18 %; " + brief + "\n"), run.err());
        assertTrue(Files.readString(out.resolve("compare.md")).contains("| FAIL | white |  | panel at x 50-699, y 50-699 "
                + "of the picture, counted from its top-left (a 750x750 page); " + brief + " |"), "the note column");

        CliRun check = CliRun.of("check", subs.resolve("st").toString(), "--pages", "4", "--rubric", rubric.toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.err());
        assertTrue(check.out().contains("\nnote: page4.png (page 4): it fails on its pixel count, not its share: 3,447 "
                + "pixels fail, and the rubric's max_failing_pixels allows at most 1,000; its share, 99.18 %, reaches "
                + "the 99.00 % needed\n"), check.out());

        // below both: said too, the share first not being enough either
        Path stricter = Files.writeString(dir.resolve("stricter.json"),
                "{\"pages\": [{\"match\": \"4\", \"min_share\": 99.5, \"max_failing_pixels\": 1000}]}");
        CliRun both = CliRun.of("check", subs.resolve("st").toString(), "--pages", "4", "--rubric", stricter.toString());
        assertTrue(both.out().contains("\nnote: page4.png (page 4): 3,447 pixels fail, and the rubric's "
                + "max_failing_pixels allows at most 1,000; its share, 99.18 %, is below the 99.50 % needed too\n"),
                both.out());
    }

    /**
     * A right page saved in greyscale fails with its shapes where simpview's are and nothing said why: it is told its
     * panel has no colour, by compare of one picture, the batch (progress line, table, Gradescope) and check; a
     * coloured picture that fails is not.
     */
    @Test
    void aPageSavedInGreyscaleIsToldItHasNoColour() throws Exception {
        Path st = dir.resolve("subs/st");
        BufferedImage grey = new BufferedImage(750, 750, BufferedImage.TYPE_BYTE_GRAY);
        grey.createGraphics().drawImage(page(4), 0, 0, null);
        writePng(st.resolve("page4.png"), grey);
        writePng(st.resolve("page5.png"), spoiled(5)); // fails, in colour
        String whole = "your picture has no colour: every pixel of its panel is a shade of grey, where simpview's "
                + "panel is coloured; was it saved in greyscale, or does your renderer write one channel into all "
                + "three? Save it in colour (RGB) and compare again";
        String brief = "no colour: every pixel is grey where simpview's are coloured; save it in colour (RGB)";

        CliRun one = CliRun.of("compare", st.resolve("page4.png").toString(), "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, one.exitCode(), one.err());
        assertTrue(one.out().contains("\nnote: " + whole + "\n"), one.out());

        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("subs").toString(), "--pages", "4-5", "--out-dir",
                out.toString(), "--diffs", "none", "--gradescope", out.resolve("results.json").toString());
        assertTrue(run.err().matches("(?s).*st/page4\\.png: FAIL [0-9.]+ %; " + Pattern.quote(brief) + "\n.*"),
                run.err());
        assertTrue(run.err().matches("(?s).*st/page5\\.png: FAIL [0-9.]+ %\n.*"), "in colour: " + run.err());
        assertTrue(Files.readString(out.resolve("compare.md")).contains(brief + " |"), "the note column");
        String results = Files.readString(out.resolve("results.json"));
        assertEquals(1, results.split(Pattern.quote("no colour"), -1).length - 1, results);

        CliRun check = CliRun.of("check", st.toString(), "--pages", "4-5");
        assertTrue(check.out().contains("\nnote: page4.png (page 4): " + whole + "\n"), check.out());
        assertFalse(check.out().contains("page5.png (page 5): your picture has no colour"), check.out());
    }

    /**
     * A page whose panel holds nothing drawn, black throughout in its white margins (a renderer that never wrote a
     * pixel), is grey everywhere too, but saving it in colour would change nothing: it is not told to.
     */
    @Test
    void aBlankPanelIsNotToldToBeSavedInColour() throws Exception {
        Path st = dir.resolve("subs/st");
        writePng(st.resolve("page4.png"), paint(paint(page(4), 0, 0, 750, 750, 0xFFFFFF), 50, 50, 700, 700, 0));

        CliRun one = CliRun.of("compare", st.resolve("page4.png").toString(), "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, one.exitCode(), one.err());
        assertFalse(one.out().contains("no colour"), one.out());

        CliRun run = CliRun.of("compare", "--dir", dir.resolve("subs").toString(), "--pages", "4", "--out-dir",
                dir.resolve("out").toString(), "--diffs", "none");
        assertTrue(run.err().matches("(?s).*st/page4\\.png: FAIL [0-9.]+ %\n.*"), run.err());
    }

    @Test
    void aPictureSavedAsJpegOrGifThatFailsIsToldToBeHandedInAsPng() throws Exception {
        Path st = dir.resolve("subs/st");
        Files.createDirectories(st);
        ImageIO.write(page(1), "jpeg", st.resolve("page1.jpg").toFile()); // lossy: fails
        ImageIO.write(page(2), "gif", st.resolve("page2.gif").toFile()); // thousands of colours: fails
        ImageIO.write(page(4), "gif", st.resolve("page4.gif").toFile()); // few colours: passes, nothing to say
        writePng(st.resolve("page5.png"), spoiled(5)); // fails, but not for its format
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("subs").toString(), "--pages", "1-5", "--out-dir",
                out.toString(), "--gradescope", out.resolve("results.json").toString(), "--junit",
                out.resolve("results.xml").toString(), "--html", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        String jpeg = "JPEG is lossy: saving a page as JPEG changes its colours near every edge, so even a right page "
                + "can fail; save it as PNG and hand that in";
        String gif = "GIF holds at most 256 colours: saving a page as GIF changes (or dithers) the others, so even a "
                + "right page can fail; save it as PNG and hand that in";
        assertTrue(run.err().matches("(?s).*st/page1\\.jpg: FAIL [0-9.]+ %; " + jpeg + "\n.*"), run.err());
        assertTrue(run.err().matches("(?s).*st/page2\\.gif: FAIL [0-9.]+ %; " + Pattern.quote(gif)
                + "\n.*"), run.err());
        assertTrue(run.err().contains("st/page4.gif: PASS 100.00 %\n") && run.err().contains("st/page5.png: FAIL "),
                run.err());
        List<String> csv = Files.readAllLines(out.resolve("compare.csv"));
        assertTrue(csv.get(1).startsWith("st/page1.jpg,") && csv.get(1).contains(",FAIL,") && csv.get(1).contains(jpeg),
                csv.get(1));
        assertTrue(csv.get(2).startsWith("st/page2.gif,") && csv.get(2).contains(gif), csv.get(2));
        assertFalse(csv.get(3).contains("hand that in") || csv.get(4).contains("hand that in"), csv.get(3) + csv.get(4));
        assertTrue(Files.readString(out.resolve("compare.md")).contains(jpeg + " |"));
        String results = Files.readString(out.resolve("results.json"));
        assertEquals(2, results.split("hand that in", -1).length - 1, results);
        assertTrue(results.contains("\\nnote: " + jpeg) && results.contains("\\nnote: " + gif), results);
        String xml = Files.readString(out.resolve("results.xml"));
        assertTrue(xml.contains("note: " + jpeg + "\n") && xml.contains("note: " + gif + "\n"), xml);
        String html = Files.readString(out.resolve("index.html"));
        assertTrue(html.contains("note: " + jpeg) && html.contains("note: " + gif), "the web report's views");

        CliRun check = CliRun.of("check", st.toString(), "--pages", "1-5");
        assertTrue(check.out().contains("\nnote: page1.jpg (page 1 (seed 361)): " + jpeg + "\n")
                && check.out().contains("\nnote: page2.gif (page 2 (seed 361)): " + gif + "\n"), check.out());
        assertEquals(2, check.out().split("hand that in", -1).length - 1, check.out());
    }

    /**
     * A JPEG not counted (a PNG of its page counts) is told JPEG is lossy, not to hand in a PNG, which is handed in
     * already; a first-assignment page's note names its page, as a page of the eight's does.
     */
    @Test
    void aJpegNotCountedIsNotToldToHandInAPng() throws Exception {
        Path st = dir.resolve("subs/st");
        Files.createDirectories(st);
        ImageIO.write(page(1), "jpeg", st.resolve("page1.jpg").toFile());
        writePng(st.resolve("page1.png"), spoiled(1)); // counts over the JPEG, and fails
        CliRun check = CliRun.of("check", st.toString(), "--pages", "1");
        assertTrue(check.out().contains("\nnote: page1.jpg (page 1 (seed 361)): JPEG is lossy: saving a page as JPEG "
                + "changes its colours near every edge, so even a right page can fail\n"), check.out());
        assertFalse(check.out().contains("hand that in"), check.out());

        Path first = dir.resolve("first");
        Files.createDirectories(first);
        // at quality 95, as an image program saves it "at high quality": at ImageIO's 75 the panels' white rings
        // are not white enough for the page to be found
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpg").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
        param.setCompressionQuality(0.95f);
        try (ImageOutputStream out = ImageIO.createImageOutputStream(
                first.resolve("a1-page3.jpg").toFile())) {
            writer.setOutput(out);
            writer.write(null, new IIOImage(Assignment1.render(3, PageContext.defaults()),
                    null, null), param);
        } finally {
            writer.dispose();
        }
        CliRun a1 = CliRun.of("check", first.toString(), "--assignment", "1", "--pages", "3");
        assertTrue(a1.out().contains("\nnote: a1-page3.jpg (A1 page 3 (seed 361)): JPEG is lossy: "), a1.out());
    }

    /** Page 1 with the top {@code rows} rows of its panel painted black, its background: those lines left out. */
    private static BufferedImage withoutTopRows(int rows) throws Exception {
        return paint(page(1), 50, 50, 700, 50 + rows, 0x000000);
    }

    /** The one test of a run of compare --partial over {@code picture} as page 1, judged by the defaults. */
    private JsonObject partiallyScored(String name, BufferedImage picture) throws Exception {
        Path student = dir.resolve(name);
        writePng(student.resolve("page1.png"), picture);
        Path results = dir.resolve(name + ".json");
        CliRun run = CliRun.of("compare", "--dir", student.toString(), "--pages", "1", "--partial", "--gradescope",
                results.toString());
        assertFalse(run.showsStackTrace(), run.err());
        return JsonParser.parseString(Files.readString(results)).getAsJsonObject().getAsJsonArray("tests").get(0)
                .getAsJsonObject();
    }

    /**
     * Page 1 is thin lines on black: a blank panel has 95.31 % of simpview's within 8/255, above the default
     * zero_share, 90. Partial credit starts at that share, so a blank picture earns nothing.
     */
    @Test
    void partialCreditStartsAtTheShareOfAnEmptyPanel() throws Exception {
        JsonObject blank = partiallyScored("blank", withoutTopRows(650));
        assertEquals(0.0, blank.get("score").getAsDouble(), "was 0.59 when partial credit started at zero_share 90");
        String empty = "partial credit: 0 of 1 point: the share counts from 95.31 %, what an empty panel (simpview's "
                + "black background alone) gets here, above zero_share 90.00 %, up to 99.00 %";
        assertTrue(blank.get("output").getAsString().startsWith("FAIL: 95.31 % of panel pixels within 8/255 with 1 px "
                + "slack (99.00 % needed)\n" + empty + "\n"), blank.get("output").getAsString());

        assertEquals(1.0, partiallyScored("right", page(1)).get("score").getAsDouble());

        JsonObject half = partiallyScored("half", withoutTopRows(380));
        String output = half.get("output").getAsString();
        double share = Double.parseDouble(output.substring("FAIL: ".length(), output.indexOf(" %")));
        double score = half.get("score").getAsDouble();
        assertEquals((share - 95.31) / (99 - 95.31), score, 0.015, "in proportion from the empty panel's share: " + output);
        assertTrue(score > 0.3 && score < 0.7, "about halfway: " + output);
        assertTrue(output.contains(String.format(Locale.ROOT, "%npartial credit: %.2f of 1 point: the share "
                + "counts from 95.31 %%", score)), output);
    }

    /** compare --pages 1 of an empty folder of submissions, judged by a compare.json of {@code rubric}. */
    private CliRun gradedByRubric(String rubric) throws IOException {
        Path file = dir.resolve("compare.json");
        Files.writeString(file, rubric);
        Files.createDirectories(dir.resolve("subs"));
        return CliRun.of("compare", "--dir", dir.resolve("subs").toString(), "--pages", "1", "--rubric",
                file.toString(), "--out-dir", dir.resolve("o").toString());
    }

    @Test
    void aBadRubricIsAUsageErrorNamingTheLine() throws Exception {
        CliRun run = gradedByRubric("{\"pages\": [\n {\"match\": \"1\", \"deviation\": 5}\n]}");
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().contains("compare.json: line 2, column"), run.err());
        assertTrue(run.err().contains("is not a position deviation of 0, 1 or 2 pixels"), run.err());
        assertFalse(run.showsStackTrace(), run.err());
    }

    @Test
    void aKeyGivenTwiceInTheRubricIsAUsageError() throws Exception {
        CliRun run = gradedByRubric("{\"pages\": [\n {\"match\": \"1\", \"points\": 2, \"points\": 5}\n]}");
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().contains("compare.json: line 2, column 30 ($.pages[0].points): \"points\" is given twice"),
                run.err());
        assertFalse(run.showsStackTrace(), run.err());
        CliRun check = CliRun.of("check", dir.resolve("subs").toString(), "--rubric",
                dir.resolve("compare.json").toString());
        assertEquals(ExitCode.USAGE_ERROR, check.exitCode(), check.err());
        assertTrue(check.err().contains("\"points\" is given twice"), check.err());
    }

    @Test
    void aRubricRuleThatFitsNothingInTheRunIsAWarning() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("page1.png"), page(1));
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"pages\": [\n {\"match\": \"1\"},\n {\"match\": \"9\"},\n {\"match\": \"pageZ\"}\n]}");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--rubric", rubric.toString(),
                "--out-dir", dir.resolve("o").toString());
        assertEquals(ExitCode.OK, run.exitCode(), "a warning only: " + run.err());
        assertTrue(run.err().contains("simpview compare: warning: rubric " + rubric + ": line 3, column 2 ($.pages[1]): "
                + "the rule \"match\": \"9\" fits no page or scene of this run, so it is not used"), run.err());
        assertTrue(run.err().contains("($.pages[2]): the rule \"match\": \"pageZ\" fits no page"), run.err());
        assertFalse(run.err().contains("\"match\": \"1\" fits"), run.err());
    }

    @Test
    void checkPrintsOneTableAndPassesOnlyWhenEveryPictureDoes() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        writePng(mine.resolve("Page_2.png"), spoiled(2));
        Files.writeString(mine.resolve("readme.txt"), "not a picture");
        CliRun run = CliRun.of("check", mine.toString(), "--pages", "1-3");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        String[] lines = run.out().split("\n");
        assertTrue(lines[0].matches("picture +page +result +share +worst region"), lines[0]);
        assertTrue(lines[2].matches("Page_2\\.png +page 2 \\(seed 361\\) +FAIL +9[0-9]\\.[0-9]{2} % +x \\d+-\\d+, y \\d+-\\d+ .*"), lines[2]);
        assertTrue(lines[1].matches("page1\\.png +page 1 \\(seed 361\\) +PASS +100\\.00 % +none"), lines[1]);
        assertTrue(run.out().contains("no picture of page 3 (seed 361) found"), run.out());
        assertTrue(run.out().contains("1 of 2 pictures pass"), run.out());

        // The window's drop of a folder (issue 21) gives the same rows (it asks for all eight pages).
        String[] window = CheckCommand.checkFolder(mine, PageContext.defaults()).split("\n");
        assertEquals(List.of(lines[0], lines[1], lines[2]), List.of(window[0], window[1], window[2]));

        Files.delete(mine.resolve("Page_2.png"));
        CliRun good = CliRun.of("check", mine.toString(), "--pages", "1");
        assertEquals(ExitCode.OK, good.exitCode(), good.out() + good.err());
        assertTrue(good.out().contains("1 of 1 pictures pass"), good.out());

        Path empty = Files.createDirectories(dir.resolve("empty"));
        assertEquals(ExitCode.SCENE_ERROR, CliRun.of("check", empty.toString()).exitCode(), "nothing found is no pass");
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("check", mine.toString(), "--pages", "1", "--scene", "x.simp").exitCode());
    }
}
