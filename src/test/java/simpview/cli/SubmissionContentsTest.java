package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;
import static simpview.testing.Images.writePng;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;

/**
 * What a submission hands in, as {@code compare --dir} and {@code check} grade it: several pictures of one
 * page count once; a page handed in only in a format simpview does not read is missing, saying so; a page
 * asked for without a picture fails the run.
 */
class SubmissionContentsTest {

    @TempDir
    Path dir;

    @Test
    void severalPicturesOfAPageCountOnce() throws Exception {
        Path sub = dir.resolve("submission");
        for (int p = 1; p <= 3; p++) {
            writePng(sub.resolve("page" + p + ".png"), page(p));
        }
        writePng(sub.resolve("page3 copy.png"), page(3));
        writePng(sub.resolve("old_page3.png"), page(3));
        writePng(sub.resolve("page3_v2.png"), page(4)); // fails, but does not count
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"pages\": [{\"match\": \"3\", \"points\": 2}]}");
        Path results = dir.resolve("results.json");
        Path xml = dir.resolve("results.xml");

        CliRun run = CliRun.of("compare", "--dir", sub.toString(), "--pages", "1-3", "--rubric", rubric.toString(),
                "--gradescope", results.toString(), "--junit", xml.toString(), "--out-dir", dir.resolve("out").toString());
        assertEquals(ExitCode.OK, run.exitCode(), "the picture of page 3 that counts passes: " + run.err());
        JsonObject json = JsonParser.parseString(Files.readString(results)).getAsJsonObject();
        double max = 0;
        for (JsonElement test : json.getAsJsonArray("tests")) {
            max += test.getAsJsonObject().get("max_score").getAsDouble();
        }
        assertEquals(4, max, 1e-9, "pages 1 and 2 a point each, page 3 two: " + json);
        assertEquals(4, json.get("score").getAsDouble(), 1e-9, json.toString());
        assertTrue(run.out().contains("| page3_v2.png | 3 (seed 361) |"), "still compared and listed: " + run.out());
        assertTrue(run.out().contains("| FAIL | white | [diff](diffs/page3_v2-diff.png) | not counted: page3.png counts for "
                + "page 3 (seed 361) instead: its name is the page's name and nothing else; panel at "), run.out());
        // tallied as check tallies them (below), JUnit's suite and the exit code: the failing page3_v2.png does
        // not count, so it is no failure
        assertTrue(run.out().contains("6 pictures: 3 pass, 0 fail, 0 could not be compared, 0 skipped, 3 not counted "
                + "(another picture of the same page counts)"), run.out());
        assertTrue(Files.readString(xml).contains("tests=\"6\" failures=\"0\" errors=\"0\" skipped=\"3\""),
                Files.readString(xml));

        CliRun check = CliRun.of("check", sub.toString(), "--pages", "1-3");
        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertTrue(check.out().contains("page3_v2.png: not counted, page3.png counts for page 3 (seed 361) instead: "
                + "its name is the page's name and nothing else\n"), check.out());
        assertTrue(check.out().endsWith("3 of 3 pictures pass; 3 pictures not counted\n"), check.out());
    }

    /** A right page as PNG beside the same page as JPEG: both are named the page alone, and the exact one counts. */
    @Test
    void aPngCountsOverAJpegOfTheSamePageNamedAsWell() throws Exception {
        Path sub = dir.resolve("a1");
        writePng(sub.resolve("a1-page3.png"), Assignment1.render(3, PageContext.defaults()));
        ImageIO.write(Assignment1.render(3, PageContext.defaults()), "jpg", sub.resolve("a1-page3.jpg").toFile());
        writePng(sub.resolve("page2.png"), page(2));
        ImageIO.write(page(2), "jpg", sub.resolve("page2.jpg").toFile());

        CliRun check = CliRun.of("check", sub.toString(), "--assignment", "1", "--pages", "3");
        assertEquals(ExitCode.OK, check.exitCode(), "the PNG counts, and passes: " + check.out() + check.err());
        assertTrue(check.out().contains("a1-page3.jpg: not counted, a1-page3.png counts for A1 page 3 (seed 361) "
                + "instead: both are named the page's name and nothing else, and a PNG is exact, a JPEG is not\n"),
                check.out());

        CliRun eight = CliRun.of("check", sub.toString(), "--pages", "2");
        assertEquals(ExitCode.OK, eight.exitCode(), eight.out() + eight.err());
        assertTrue(eight.out().contains("page2.jpg: not counted, page2.png counts for page 2 (seed 361) instead: both "
                + "are named the page's name and nothing else, and a PNG is exact, a JPEG is not\n"), eight.out());
    }

    @Test
    void aMissingPageNamesTheFileHandedInInAFormatSimpviewDoesNotRead() throws Exception {
        Path class_ = dir.resolve("class");
        writePng(class_.resolve("st/page1.png"), page(1));
        Files.writeString(class_.resolve("st/page2.webp"), "RIFF....WEBP");
        Files.writeString(class_.resolve("st/.page2.webp"), "hidden: not named");
        Files.createDirectories(class_.resolve("carl"));
        Files.writeString(class_.resolve("carl/page1.tif"), "II*.");
        Path out = dir.resolve("out");
        String why = " is named like it, but is in a format simpview does not read (it reads PNG, JPEG, GIF and BMP)";

        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--pages", "1-2", "--out-dir", out.toString(),
                "--gradescope", dir.resolve("results.json").toString(), "--junit", dir.resolve("results.xml").toString());
        List<String> csv = Files.readAllLines(out.resolve("compare.csv"));
        assertTrue(csv.contains("st/,2 (seed 361),,,,,,,,MISSING,,,\"no picture of page 2 (seed 361) in st was found; "
                + "st/page2.webp" + why + "\""), String.join("\n", csv));
        assertTrue(csv.contains("carl/,1 (seed 361),,,,,,,,MISSING,,,\"no picture of page 1 (seed 361) in carl was found; "
                + "carl/page1.tif" + why + "\""), "carl handed in no picture at all: " + String.join("\n", csv));
        // carl is a student of the class who handed in no picture (st alone holds pictures), told what he holds
        assertTrue(csv.contains("carl/,2 (seed 361),,,,,,,,MISSING,,,\"no picture of page 2 (seed 361) in carl was found; "
                + "carl holds no picture (.png, .jpg, .gif, .bmp), only carl/page1.tif\""), String.join("\n", csv));
        assertFalse(String.join("\n", csv).contains(".page2"), "hidden files are no one's");
        String json = Files.readString(dir.resolve("results.json"));
        assertTrue(json.contains("\"output\": \"No picture of page 2 (seed 361) was found in the submission: st/page2.webp"
                + why + ".\""), json);
        String xml = Files.readString(dir.resolve("results.xml"));
        assertTrue(xml.contains("<testcase name=\"page 1 (seed 361) (no picture)\" classname=\"carl\"><failure message=\"no "
                + "picture of page 1 (seed 361) found; carl/page1.tif" + why + "\" type=\"missing\">"), xml);

        CliRun check = CliRun.of("check", class_.resolve("st").toString(), "--pages", "1-2");
        assertTrue(check.out().contains("\nno picture of page 2 (seed 361) found: page2.webp" + why + "\n"), check.out());
    }

    @Test
    void aPageAskedForWithoutAPictureFailsTheRun() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        CliRun check = CliRun.of("check", mine.toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), "pages 2 to 8 are not handed in: " + check.out());
        assertTrue(check.out().endsWith("1 of 1 pictures pass; 7 pages without a picture\n"), check.out());
        CliRun compare = CliRun.of("compare", "--dir", mine.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());
        assertEquals(ExitCode.SCENE_ERROR, compare.exitCode(), compare.out());
        assertTrue(compare.out().contains("1 picture: 1 pass, 0 fail, 0 could not be compared, 0 skipped; 1 page asked "
                + "for without a picture"), compare.out());
        assertEquals(ExitCode.OK, CliRun.of("check", mine.toString(), "--pages", "1").exitCode(), "all asked for is there");
    }

    @Test
    void withoutPagesCheckAsksForTheEightPagesOnlyWhenOneIsHandedIn() throws Exception {
        Path first = dir.resolve("first");
        PageContext context = PageContext.defaults();
        ImageIO.write(Assignment1.render(2, context), "png", Files.createDirectories(first).resolve("a1-page2.png").toFile());
        CliRun check = CliRun.of("check", first.toString());
        // a folder of the first assignment's pages is asked for its five pages, as --assignment 1 asks, not the eight
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), "a folder of the first assignment's pages: " + check.out());
        assertTrue(check.out().contains("no picture of A1 page 1 found"), check.out());
        assertFalse(check.out().contains("no picture of page "), check.out());
        assertTrue(CheckCommand.checkFolder(first, context).endsWith("4 of 4 panels pass (1 page of the first assignment); "
                + "4 pages without a picture\n"), "a folder dropped on the window, the same");

        Path scenes = dir.resolve("scenes");
        Files.createDirectories(scenes);
        Files.writeString(scenes.resolve("blank.simp"), "# draws nothing: a black panel\n");
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scenes.resolve("blank.simp").toString(), "--out",
                scenes.resolve("blank.png").toString()).exitCode());
        CliRun own = CliRun.of("check", scenes.toString());
        assertEquals(ExitCode.OK, own.exitCode(), "a folder of its own scenes and their pictures: " + own.out());
        assertFalse(own.out().contains("no picture of"), own.out());

        CliRun asked = CliRun.of("check", first.toString(), "--pages", "1-8");
        assertEquals(ExitCode.SCENE_ERROR, asked.exitCode(), "--pages asks for them whatever is handed in");
        assertTrue(asked.out().contains("no picture of page 8 found"), asked.out());
        writePng(first.resolve("page3.png"), page(3));
        CliRun mixed = CliRun.of("check", first.toString());
        assertEquals(ExitCode.SCENE_ERROR, mixed.exitCode(), "one of the eight handed in: all eight asked for");
        assertTrue(mixed.out().contains("no picture of page 1 (seed 361) found"), mixed.out());
    }

    @Test
    void aStudentWhoseFolderHoldsNoPictureLacksEveryPageAndIsToldWhy() throws Exception {
        Path class_ = dir.resolve("class");
        writePng(class_.resolve("ann/page1.png"), page(1));
        writePng(class_.resolve("bob/page1.png"), page(1));
        Files.createDirectories(class_.resolve("sybil"));
        Files.write(class_.resolve("sybil/sybil_A2.zip"), new byte[] {'P', 'K', 3, 4});
        Files.writeString(class_.resolve("sybil/.DS_Store"), "hidden: not hers");
        Files.createDirectories(class_.resolve("ghost"));
        Path out = dir.resolve("out");
        String sybil = "no picture of page 1 (seed 361) in sybil was found; sybil holds no picture (.png, .jpg, .gif, "
                + ".bmp), only sybil/sybil_A2.zip: unzip it (simpview does not look inside a zip)";

        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--pages", "1", "--out-dir", out.toString(),
                "--junit", dir.resolve("results.xml").toString(), "--html", dir.resolve("web").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "two students lack page 1: " + run.out());
        List<String> csv = Files.readAllLines(out.resolve("compare.csv"));
        assertTrue(csv.contains("sybil/,1 (seed 361),,,,,,,,MISSING,,,\"" + sybil + "\""), String.join("\n", csv));
        assertTrue(csv.contains("ghost/,1 (seed 361),,,,,,,,MISSING,,,\"no picture of page 1 (seed 361) in ghost was "
                + "found; ghost holds no picture (.png, .jpg, .gif, .bmp): it is empty\""), String.join("\n", csv));
        String xml = Files.readString(dir.resolve("results.xml"));
        assertTrue(xml.contains("<testsuite name=\"sybil\" id=\"3\" tests=\"1\" failures=\"1\""), xml);
        String html = Files.readString(dir.resolve("web/index.html"));
        assertTrue(html.contains("<td>sybil</td><td></td><td>page 1 (seed 361)</td><td>MISSING</td>"), html);
        assertTrue(html.contains("<td>" + sybil + "</td>"), html);

        CliRun check = CliRun.of("check", class_.resolve("sybil").toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode());
        assertTrue(check.err().contains("simpview check: no pictures (.png, .jpg, .gif, .bmp) found in "
                + class_.resolve("sybil") + ": it holds only sybil_A2.zip: unzip it (simpview does not look inside a "
                + "zip)"), check.err());
        assertEquals("No pictures (.png, .jpg, .gif, .bmp) in " + class_.resolve("sybil") + ": it holds only "
                + "sybil_A2.zip: unzip it (simpview does not look inside a zip).\n",
                CheckCommand.checkFolder(class_.resolve("sybil"), PageContext.defaults()), "dropped on the window");
    }

    /**
     * A student's folder holding pictures and a zip: the pages it lacks may be in the zip, which simpview does not
     * open; the MISSING row says the zip is there, in the table, the web report and JUnit's, and for one student in
     * Gradescope's results and check's table. A student without a zip is told nothing of it.
     */
    @Test
    void aStudentWithPicturesAndAZipLacksPagesAndIsToldTheZipIsThere() throws Exception {
        Path class_ = dir.resolve("class");
        writePng(class_.resolve("ann/page1.png"), page(1));
        writePng(class_.resolve("ann/page2.png"), page(2));
        writePng(class_.resolve("bob/page1.png"), page(1));
        Files.write(class_.resolve("bob/bob_A2.zip"), new byte[] {'P', 'K', 3, 4});
        Path out = dir.resolve("out");
        String zip = "bob/bob_A2.zip is in the folder too, not opened (simpview does not look inside a zip): the page "
                + "may be in it; unzip it";

        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--pages", "1-2", "--out-dir", out.toString(),
                "--junit", dir.resolve("results.xml").toString(), "--html", dir.resolve("web").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob lacks page 2: " + run.out());
        String csv = Files.readString(out.resolve("compare.csv"));
        assertTrue(csv.contains("bob/,2 (seed 361),,,,,,,,MISSING,,,\"no picture of page 2 (seed 361) in bob was "
                + "found; " + zip + "\""), csv);
        assertEquals(1, csv.split("not opened", -1).length - 1, "ann holds no zip: " + csv);
        assertTrue(Files.readString(out.resolve("compare.md")).contains(zip), "the Markdown table too");
        assertTrue(Files.readString(dir.resolve("web/index.html")).contains(zip), "the web report too");
        assertTrue(Files.readString(dir.resolve("results.xml")).contains(zip), "JUnit's too");

        Path results = dir.resolve("results.json");
        CliRun one = CliRun.of("compare", "--dir", class_.resolve("bob").toString(), "--pages", "1-2",
                "--gradescope", results.toString());
        assertEquals(ExitCode.SCENE_ERROR, one.exitCode(), one.out() + one.err());
        String mine = "bob_A2.zip is in the folder too, not opened (simpview does not look inside a zip): the page "
                + "may be in it; unzip it";
        assertTrue(Files.readString(results).contains("No picture of page 2 (seed 361) was found in the submission: "
                + mine + "."), Files.readString(results));
        CliRun check = CliRun.of("check", class_.resolve("bob").toString(), "--pages", "1-2");
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out());
        assertTrue(check.out().contains("no picture of page 2 (seed 361) found: " + mine + "\n"), check.out());
    }

    @Test
    void aStudentsFolderWithPicturesAtItsTopHasNoOtherSubmissions() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        Files.createDirectories(mine.resolve("src"));
        Files.writeString(mine.resolve("src/Main.java"), "class Main {}");
        CliRun run = CliRun.of("compare", "--dir", mine.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());
        assertEquals(ExitCode.OK, run.exitCode(), "src/ is no student: " + run.out());
    }

    @Test
    void checkNamesEachFileItSkippedWithWhyAndTheNameItExpects() throws Exception {
        Path judy = dir.resolve("judy");
        writePng(judy.resolve("p1.png"), page(1));
        writePng(judy.resolve("notes.png"), page(2));
        CliRun check = CliRun.of("check", judy.toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out());
        assertTrue(check.out().contains("\np1.png: not checked, no page number in the name: its number, 1, is not after "
                + "the word \"page\" (expected a name like page1.png)\n"), check.out());
        assertTrue(check.out().contains("\nnotes.png: not checked, no page number in the name (expected a name like "
                + "page3.png)\n"), check.out());
        assertTrue(check.out().endsWith("0 of 0 pictures pass; 2 other files not checked (each said above)\n"), check.out());
    }

    @Test
    void paginaNamesAPage() throws Exception {
        Path zoe = dir.resolve("class/Zoë Ñúñez");
        writePng(zoe.resolve("página1.png"), page(1));
        writePng(zoe.resolve("página2.png"), page(2));
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("class").toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().contains("| Zoë Ñúñez/página2.png | 2 (seed 361) | 100.00 |"), run.out());
    }

    @Test
    void inAClassFolderEachStudentsPagesCountOnce() throws Exception {
        Path class_ = dir.resolve("class");
        writePng(class_.resolve("ann/page1.png"), page(1));
        writePng(class_.resolve("bob/Page1 copy.png"), page(2));
        writePng(class_.resolve("bob/page_1.png"), page(1));
        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());
        assertEquals(ExitCode.OK, run.exitCode(), "ann's page 1 is the only picture of hers: " + run.out());
        assertTrue(run.out().contains("| bob/Page1 copy.png | 1 (seed 361) |"), run.out());
        assertTrue(run.out().contains("not counted: bob/page_1.png counts for page 1 (seed 361) instead"), run.out());
        assertFalse(run.out().contains("not counted: ann"), run.out());
    }
}
