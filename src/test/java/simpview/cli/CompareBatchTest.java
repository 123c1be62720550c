package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;
import static simpview.testing.Images.paint;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.compare.HtmlReport;

/** {@code simpview compare --dir ...}: one row per picture, good, bad or broken, in Markdown and CSV. */
public class CompareBatchTest {

    @TempDir
    Path dir;

    private Path png(Path file, BufferedImage image) throws Exception {
        Files.createDirectories(file.getParent());
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    private static List<String> csvRows(Path out) throws Exception {
        return Files.readAllLines(out.resolve("compare.csv"));
    }

    @Test
    void everyPictureGetsOneRowAndABrokenOneSaysWhatIsWrong() throws Exception {
        Path submissions = dir.resolve("submissions");
        png(submissions.resolve("page1.png"), page(1));
        BufferedImage wrong = page(2);
        for (int y = 100; y < 300; y++) {
            for (int x = 100; x < 300; x++) {
                wrong.setRGB(x, y, 0x00FFFF);
            }
        }
        png(submissions.resolve("bob/Page_2.png"), wrong);
        png(submissions.resolve("cy/page5.png"), page(5));
        Files.write(submissions.resolve("page3.png"), new byte[] {(byte) 0x89, 'P', 'N', 'G', 13, 10, 26, 10, 0, 0});
        Files.writeString(submissions.resolve("page10.png"), "x");
        Files.writeString(submissions.resolve("notes.txt"), "not a picture, and not named like one");
        Path out = dir.resolve("report");

        CliRun run = CliRun.of("compare", "--dir", submissions.toString(), "--pages", "1-8", "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "a failing and a broken picture: " + run.err());
        assertFalse(run.showsStackTrace(), run.err());
        List<String> rows = csvRows(out);
        // a heading, one row per picture, then one per page of --pages each submission lacks: bob (his
        // folder) has only page 2, cy (hers) only page 5, the top folder pages 1, 3 and 10 (a class's folder: its
        // pictures are in two first-level folders, and at its top)
        assertEquals(6 + 7 + 7 + 6, rows.size(), "a heading, one row per picture, one per page lacking: " + rows);
        assertTrue(rows.get(0).startsWith("file,page,identical,within 1/255,within 8/255,identical (slack)"), rows.get(0));
        assertTrue(rows.get(1).startsWith("bob/Page_2.png,2 (seed 361),"), rows.get(1));
        assertTrue(rows.get(1).contains(",FAIL,white,diffs/bob_Page_2-diff.png,"), rows.get(1));
        assertTrue(rows.get(2).startsWith("cy/page5.png,5,"), rows.get(2));
        assertTrue(rows.get(3).startsWith("page1.png,1 (seed 361),100.00,100.00,100.00,100.00,100.00,100.00,100.00,PASS,white,"
                + "diffs/page1-diff.png,"), rows.get(3));
        assertTrue(rows.get(4).startsWith("page3.png,3 (seed 361),,,,,,,,ERROR,,,"), rows.get(4));
        assertTrue(rows.get(4).contains("page3.png: cannot be read as a picture, it is damaged or cut short"), rows.get(4));
        assertTrue(rows.get(5).startsWith("page10.png,,,,,,,,,SKIPPED,,,page 10 is not among --pages 1-8"), rows.get(5));
        assertEquals("bob/,1 (seed 361),,,,,,,,MISSING,,,no picture of page 1 (seed 361) in bob was found", rows.get(6));
        assertEquals("bob/,8,,,,,,,,MISSING,,,no picture of page 8 in bob was found", rows.get(12));
        assertEquals("cy/,1 (seed 361),,,,,,,,MISSING,,,no picture of page 1 (seed 361) in cy was found", rows.get(13));
        // page10.png is named for a page there is not: each page the top lacks may be the one it was meant as, said
        // once, on the first
        assertEquals("submission,2 (seed 361),,,,,,,,MISSING,,,\"no picture of page 2 (seed 361) at the top of the folder "
                + "was found; page10.png is named for page 10, and there is no page 10 (the pages are 1 to 8): was it "
                + "meant as page 2, page 4, page 5, page 6, page 7 or page 8, which the top of the folder lacks?\"",
                rows.get(20));
        assertEquals("submission,4,,,,,,,,MISSING,,,no picture of page 4 at the top of the folder was found",
                rows.get(21));
        assertTrue(rows.subList(6, 26).stream().allMatch(r -> r.contains(",MISSING,")), rows.toString());
        BufferedImage diff = ImageIO.read(out.resolve("diffs/bob_Page_2-diff.png").toFile());
        assertEquals(1970, diff.getWidth());
        assertTrue(Files.isRegularFile(out.resolve("diffs/page1-diff.png")));

        String table = Files.readString(out.resolve("compare.md"));
        assertEquals(table, run.out().substring(0, table.length()), "the table is printed too");
        assertTrue(table.contains("| page1.png | 1 (seed 361) | 100.00 |"), table);
        assertTrue(table.contains("[diff](diffs/bob_Page_2-diff.png)"), table);
        assertTrue(table.contains("5 pictures: 2 pass, 1 fail, 1 could not be compared, 1 skipped; "
                + "20 pages asked for without a picture"), table);
        assertTrue(table.contains("| bob/ | 7 |  |  |  |  |  |  |  | MISSING |  |  | no picture of page 7 in bob was found |"),
                table);
        assertTrue(run.err().contains("/5] page1.png: PASS 100.00 %"), run.err());
        assertTrue(run.err().contains("/5] page3.png: ERROR: "), run.err());
    }

    @Test
    void theSharesInTheTableAreThoseOfTheSingleComparison() throws Exception {
        Path submissions = dir.resolve("in");
        BufferedImage theirs = page(3);
        for (int x = 50; x < 700; x += 3) {
            theirs.setRGB(x, 400, 0xFFFFFF);
        }
        Path file = png(submissions.resolve("page3.png"), theirs);
        Path out = dir.resolve("out");
        CliRun batch = CliRun.of("compare", "--dir", submissions.toString(), "--pages", "3", "--out-dir", out.toString());
        assertEquals(ExitCode.OK, batch.exitCode(), batch.err());
        CliRun one = CliRun.of("compare", file.toString(), "--page", "3");
        String[] cells = csvRows(out).get(1).split(",");
        assertEquals(CompareCommandTest.printed(one.out(), "identical")[0], Double.parseDouble(cells[2]));
        assertEquals(CompareCommandTest.printed(one.out(), "within 8/255")[1], Double.parseDouble(cells[7]));
        assertEquals(CompareCommandTest.asPrinted(CompareCommandTest.independentDirect(page(3), theirs, 0)),
                Double.parseDouble(cells[2]));
    }

    /** A folder of two scenes: a triangle, tri.simp, and a bar, {@code barName}.simp. */
    private Path scenes(String barName) throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("tri.simp"), "polygon (-50,-50,-10) (50,-50,-10) (0,50,-100)\n");
        Files.writeString(scenes.resolve(barName + ".simp"), "polygon (-90,-10,-5) (90,-10,-5) (90,10,-5)\n");
        return scenes;
    }

    /** The scene as simpview draws it, into {@code picture} (its folders made). */
    private static void render(Path scene, Path picture) {
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scene.toString(), "--out", picture.toString()).exitCode());
    }

    /** --scene may name the scene without .simp in a batch too, as compare, render and inspect take it. */
    @Test
    void aBatchsSceneMayBeNamedWithoutItsExtension() throws Exception {
        Path scenes = scenes("bar");
        Path ann = dir.resolve("ann");
        render(scenes.resolve("tri.simp"), ann.resolve("tri.png"));
        String named = scenes.resolve("tri").toString();
        CliRun check = CliRun.of("check", ann.toString(), "--scene", named);
        assertEquals(ExitCode.OK, check.exitCode(), check.err());
        assertTrue(check.out().contains("tri.png  tri.simp  PASS"), check.out());
        CliRun batch = CliRun.of("compare", "--dir", ann.toString(), "--scene", named, "--out-dir",
                dir.resolve("out").toString());
        assertEquals(ExitCode.OK, batch.exitCode(), batch.err());
        CliRun missing = CliRun.of("check", ann.toString(), "--scene", scenes.resolve("nothere").toString());
        assertEquals(ExitCode.USAGE_ERROR, missing.exitCode(), missing.err());
        assertTrue(missing.err().startsWith("simpview check: --scene " + scenes.resolve("nothere")
                + ": no such file or folder"), missing.err());
    }

    @Test
    void aSceneFolderIsMatchedToPicturesByName() throws Exception {
        Path scenes = scenes("triBar");
        Path tri = scenes.resolve("tri.simp");
        Path submissions = dir.resolve("pics");
        render(tri, submissions.resolve("tri.png"));
        render(scenes.resolve("triBar.simp"), submissions.resolve("page_triBar_v2.png"));
        png(submissions.resolve("other.png"), page(1));
        Path out = dir.resolve("out");

        CliRun run = CliRun.of("compare", "--dir", submissions.toString(), "--scene", scenes.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        List<String> rows = csvRows(out);
        assertEquals(4, rows.size(), rows.toString());
        assertTrue(rows.get(1).startsWith("other.png,,,,,,,,,SKIPPED,,,its name names none of the scenes"), rows.get(1));
        assertTrue(rows.get(2).startsWith("page_triBar_v2.png,triBar.simp,100.00,"), rows.get(2));
        assertTrue(rows.get(3).startsWith("tri.png,tri.simp,100.00,"), rows.get(3));

        // One scene file: every picture is compared with it.
        CliRun one = CliRun.of("compare", "--dir", submissions.toString(), "--scene", tri.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, one.exitCode(), "other.png and the bar are not the triangle");
        List<String> against = csvRows(out);
        assertEquals(4, against.size());
        assertTrue(against.stream().skip(1).allMatch(r -> r.contains(",tri.simp,")), against.toString());
        assertTrue(against.get(3).contains(",PASS,"), against.toString());
    }

    @Test
    void aSceneOneSubmissionHandedInAndAnotherDidNotIsAMissingRow() throws Exception {
        Path scenes = scenes("bar");
        Path class_ = dir.resolve("class");
        render(scenes.resolve("tri.simp"), class_.resolve("alice/tri.png"));
        render(scenes.resolve("tri.simp"), class_.resolve("bob/tri.png"));
        render(scenes.resolve("bar.simp"), class_.resolve("alice/bar.png"));
        Path out = dir.resolve("out");

        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--out-dir",
                out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "every picture handed in passes, but bob lacks bar: " + run.err());
        List<String> rows = csvRows(out);
        assertEquals(List.of("alice/bar.png", "alice/tri.png", "bob/tri.png", "bob/"),
                rows.stream().skip(1).map(r -> r.substring(0, r.indexOf(','))).toList(), rows.toString());
        assertEquals("bob/,bar.simp,,,,,,,,MISSING,,,no picture of bar.simp in bob was found", rows.get(4));
        assertTrue(run.out().contains("3 pictures: 3 pass, 0 fail, 0 could not be compared, 0 skipped; "
                + "1 page asked for without a picture"), run.out());
    }

    /**
     * A class's folder without pictures is a student's only when it is empty or holds what pictures may be handed
     * in as (a zip): the folders of a rubric and of last run's reports are not, so a second run grades as the first.
     */
    @Test
    void foldersOfReportsOrARubricAreNoStudents() throws Exception {
        Path subs = dir.resolve("subs");
        png(subs.resolve("ann/page1.png"), page(1));
        png(subs.resolve("bob/page1.png"), page(1));
        Files.createDirectories(subs.resolve("rubric"));
        Files.writeString(subs.resolve("rubric/compare.json"), "{\"defaults\": {\"points\": 2}}\n");
        String[] args = {"compare", "--dir", subs.toString(), "--pages", "1", "--rubric",
            subs.resolve("rubric/compare.json").toString(), "--junit", subs.resolve("junit/results.xml").toString(),
            "--out-dir", dir.resolve("out").toString()};
        CliRun first = CliRun.of(args);
        assertEquals(ExitCode.OK, first.exitCode(), first.out() + first.err());
        CliRun second = CliRun.of(args);
        assertEquals(ExitCode.OK, second.exitCode(), second.out() + second.err());
        assertFalse(second.out().contains("MISSING"), second.out());
        Files.createDirectories(subs.resolve("cy"));
        Files.writeString(subs.resolve("cy/cy.zip"), "PK");
        CliRun zipped = CliRun.of(args);
        assertTrue(zipped.out().contains("| cy/ | 1 (seed 361) |"), zipped.out());
        assertFalse(zipped.out().contains("| rubric/") || zipped.out().contains("| junit/"), zipped.out());
    }

    /** A picture named like no scene is told a page's name for its example, not that of a file the pages include. */
    @Test
    void aPictureNamedLikeNoSceneIsToldAPagesNameForItsExample() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("a3"));
        Files.writeString(scenes.resolve("cube.simp"), "polygon (-50,-50,-10) (50,-50,-10) (0,50,-10)\n");
        Files.writeString(scenes.resolve("pageA.simp"), "file \"cube\"\n");
        Path subs = dir.resolve("subs");
        png(subs.resolve("mine.png"), page(1));
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--scene", scenes.toString(), "--out-dir",
                dir.resolve("out").toString());
        assertTrue(run.out().contains("its name names none of the scenes in " + scenes + " (expected a name like "
                + "pageA.png)"), run.out());
    }

    /** results.json written for a class (one page in several students' folders) says that it counted them as one. */
    @Test
    void gradescopesResultsForAClassSayTheyCountedItAsOneSubmission() throws Exception {
        Path subs = dir.resolve("subs");
        png(subs.resolve("ann/page1.png"), page(1));
        png(subs.resolve("bob/page1.png"), page(1));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--gradescope",
                out.resolve("results.json").toString());
        assertTrue(run.err().contains("note: " + out.resolve("results.json") + " is one submission's, as Gradescope "
                + "grades one student at a time, but ann/ and bob/ each hold a picture of one page: they were counted "
                + "as one submission"), run.err());
        CliRun one = CliRun.of("compare", "--dir", subs.resolve("ann").toString(), "--pages", "1", "--gradescope",
                out.resolve("ann.json").toString());
        assertFalse(one.err().contains("note:"), one.err());
        assertEquals(ExitCode.OK, one.exitCode(), one.err());
    }

    /** The picture with rows 300 to 399 of its panel painted black: a band across the middle of tri.simp. */
    private static BufferedImage banded(Path picture) throws Exception {
        return paint(ImageIO.read(picture.toFile()), 50, 300, 700, 400, 0x000000);
    }

    /**
     * Each submission's total, in the printed table, totals.csv and the web report, is what results.json gives
     * that student's folder graded alone: a student who passes, one who fails a page scored in part, one who lacks
     * a page and handed in a second picture of another (not counted).
     */
    @Test
    void eachSubmissionsTotalIsWhatItsOwnResultsJsonScores() throws Exception {
        Path scenes = scenes("bar");
        Path right = dir.resolve("right");
        render(scenes.resolve("tri.simp"), right.resolve("tri.png"));
        render(scenes.resolve("bar.simp"), right.resolve("bar.png"));
        Path class_ = dir.resolve("class");
        for (String student : new String[] {"ann", "bob", "cy"}) {
            Files.createDirectories(class_.resolve(student));
            Files.copy(right.resolve("bar.png"), class_.resolve(student + "/bar.png"));
        }
        Files.copy(right.resolve("tri.png"), class_.resolve("ann/tri.png"));
        png(class_.resolve("bob/tri.png"), banded(right.resolve("tri.png"))); // 96.74 %: 1.49 of 2 points
        Files.delete(class_.resolve("cy/bar.png"));
        Files.copy(right.resolve("tri.png"), class_.resolve("cy/tri.png"));
        Files.copy(class_.resolve("bob/tri.png"), class_.resolve("cy/tri copy.png")); // fails, and does not count
        // the rubric names both scenes, so each is asked of a student's folder graded alone too
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"pages\": [{\"match\": \"tri\", \"points\": 2}, {\"match\": \"bar\", "
                + "\"points\": 0.5}]}");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--rubric",
                rubric.toString(), "--partial", "--diffs", "none", "--out-dir", out.toString(), "--html",
                out.toString());
        assertFalse(run.showsStackTrace(), run.err());
        List<String> totals = Files.readAllLines(out.resolve("totals.csv"));
        assertEquals("submission,score,max_score,passed,failed,errors,missing", totals.get(0));
        assertEquals("ann,2.50,2.50,2,0,0,0", totals.get(1));
        assertEquals("bob,1.99,2.50,1,1,0,0", totals.get(2), "his tri scored in part, 1.49 of 2");
        assertEquals("cy,2,2.50,1,0,0,1", totals.get(3), "her copy of tri counts nothing; bar is missing");
        assertEquals(4, totals.size(), totals.toString());
        for (String line : totals.subList(1, totals.size())) {
            String[] cells = line.split(",");
            Path results = dir.resolve(cells[0] + ".json");
            CliRun alone = CliRun.of("compare", "--dir", class_.resolve(cells[0]).toString(), "--scene",
                    scenes.toString(), "--rubric", rubric.toString(), "--partial", "--diffs", "none", "--gradescope",
                    results.toString());
            assertFalse(alone.showsStackTrace(), alone.err());
            JsonObject json = JsonParser.parseString(Files.readString(results)).getAsJsonObject();
            double worth = 0;
            for (JsonElement test : json.getAsJsonArray("tests")) {
                worth += test.getAsJsonObject().get("max_score").getAsDouble();
            }
            assertEquals(json.get("score").getAsDouble(), Double.parseDouble(cells[1]), 1e-9, line);
            assertEquals(worth, Double.parseDouble(cells[2]), 1e-9, line);
        }
        assertTrue(run.out().contains("| submission | score | out of | pass | fail | could not be compared | missing |\n"
                + "|---|---:|---:|---:|---:|---:|---:|\n| ann | 2.50 | 2.50 | 2 | 0 | 0 | 0 |\n"
                + "| bob | 1.99 | 2.50 | 1 | 1 | 0 | 0 |\n| cy | 2 | 2.50 | 1 | 0 | 0 | 1 |\n"), run.out());
        assertTrue(Files.readString(out.resolve("compare.md")).endsWith("| cy | 2 | 2.50 | 1 | 0 | 0 | 1 |\n"));
        assertTrue(run.out().contains("\ntotals: " + out.resolve("totals.csv") + "\n"), run.out());
        String html = Files.readString(out.resolve(HtmlReport.INDEX));
        assertTrue(html.contains("<tr class=\"total\"><td>cy</td><td data-v=\"2.0\">2</td><td data-v=\"2.5\">2.50</td>"),
                html);
    }

    /**
     * Of two pictures whose names differ only in case (tri.png and tri.PNG, side by side on Linux), the first by name
     * is tri.PNG: it counted even when it was no picture, and the right tri.png scored nothing. The one that can be
     * compared counts, and then the one whose bytes hold a PNG.
     */
    @Test
    void ofTwoNamesDifferingOnlyInCaseTheReadablePngCounts() throws Exception {
        Path scenes = scenes("bar");
        Path class_ = dir.resolve("class");
        render(scenes.resolve("tri.simp"), class_.resolve("bob/tri.png"));
        Files.writeString(class_.resolve("bob/tri.PNG"), "not a picture");
        Files.createDirectories(class_.resolve("cy"));
        Files.copy(class_.resolve("bob/tri.png"), class_.resolve("cy/tri.png"));
        ImageIO.write(banded(class_.resolve("bob/tri.png")), "jpeg", class_.resolve("cy/tri.PNG").toFile());
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--diffs", "none",
                "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        List<String> rows = csvRows(out);
        assertTrue(rows.get(1).startsWith("bob/tri.PNG,tri.simp,,,,,,,,ERROR,,,\"not counted: bob/tri.png counts for "
                + "tri.simp instead: both are named the page's name and nothing else, their names differ only in case, "
                + "and it could be compared, this one not; "), rows.get(1));
        assertTrue(rows.get(3).startsWith("cy/tri.PNG,tri.simp,") && rows.get(3).contains(",FAIL,white,,\"not counted: "
                + "cy/tri.png counts for tri.simp instead: both are named the page's name and nothing else, their "
                + "names differ only in case, and by what their bytes hold a PNG is exact, a JPEG is not;"), rows.get(3));
        assertEquals(List.of("bob,1,1,1,0,0,0", "cy,1,1,1,0,0,0"),
                Files.readAllLines(out.resolve("totals.csv")).subList(1, 3));
    }

    /**
     * A scene is asked of every submission when at least half of them handed it in: one student's picture of
     * another scene of the folder (cube.simp, which the pages include) asks nothing of the others.
     */
    @Test
    void aSceneFewerThanHalfTheClassHandedInIsAskedOfNobodyElse() throws Exception {
        Path scenes = scenes("bar");
        Path class_ = dir.resolve("class");
        for (String student : new String[] {"alice", "bob", "carol"}) {
            render(scenes.resolve("tri.simp"), class_.resolve(student + "/tri.png"));
        }
        render(scenes.resolve("bar.simp"), class_.resolve("alice/bar.png"));
        Path out = dir.resolve("out");
        CliRun one = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--out-dir",
                out.toString());
        assertEquals(ExitCode.OK, one.exitCode(), "one of three handed in bar: " + one.out() + one.err());
        assertFalse(one.out().contains("MISSING"), one.out());
        assertTrue(one.out().contains("| alice/bar.png | bar.simp |"), "it is compared all the same: " + one.out());

        render(scenes.resolve("bar.simp"), class_.resolve("bob/bar.png"));
        CliRun two = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--out-dir",
                out.toString());
        assertEquals(ExitCode.SCENE_ERROR, two.exitCode(), "two of three handed in bar: " + two.out());
        assertEquals(List.of("carol/,bar.simp,,,,,,,,MISSING,,,no picture of bar.simp in carol was found"),
                csvRows(out).stream().filter(r -> r.contains(",MISSING,")).toList());

        // two more students, who handed in zips: two of five handed in bar, which is then asked of nobody else
        for (String student : new String[] {"dee", "eve"}) {
            Files.createDirectories(class_.resolve(student));
            Files.writeString(class_.resolve(student + "/pages.zip"), "PK");
        }
        CliRun five = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--out-dir",
                out.toString());
        assertEquals(List.of(), csvRows(out).stream().filter(r -> r.contains("bar.simp,,,,,,,,MISSING")).toList(),
                five.out());
    }

    @Test
    void aStudentsFolderIsOneSubmissionHoweverItsPicturesAreFoldered() throws Exception {
        Path mine = dir.resolve("mine");
        png(mine.resolve("part1/page1.png"), page(1));
        png(mine.resolve("part2/page2.png"), page(2));
        Path out = dir.resolve("r");
        CliRun run = CliRun.of("check", mine.toString(), "--pages", "1-3", "--out-dir", out.toString());
        assertTrue(run.out().contains("no picture of page 3 (seed 361) found"), run.out());
        List<String> rows = csvRows(out);
        assertEquals(1 + 2 + 1, rows.size(), "a heading, the two pictures, page 3 missing once: " + rows);
        assertEquals(",3 (seed 361),,,,,,,,MISSING,,,no picture of page 3 (seed 361) was found", rows.get(3));
    }

    @Test
    void aSecondCheckLeavesOutTheReportTheFirstWroteInsideTheFolder() throws Exception {
        Path mine = dir.resolve("mine");
        png(mine.resolve("page4.png"), page(5));
        String[] check = {"check", mine.toString(), "--pages", "4", "--out-dir", mine.resolve("report").toString()};
        assertEquals(ExitCode.SCENE_ERROR, CliRun.of(check).exitCode(), "page 5 is not page 4");
        assertTrue(Files.isRegularFile(mine.resolve("report/diffs/page4-diff.png")));
        png(mine.resolve("page4.png"), page(4));
        CliRun again = CliRun.of(check);
        assertEquals(ExitCode.OK, again.exitCode(), again.out() + again.err());
        assertTrue(again.out().contains("1 of 1 pictures pass"), again.out());
        assertEquals(2, csvRows(mine.resolve("report")).size(), "a heading and page4.png");
    }

    @Test
    void aBatchWritingIntoItsOwnFolderLeavesOutItsDiffImagesAndThoseOfOtherRuns() throws Exception {
        Path mine = dir.resolve("mine");
        png(mine.resolve("page4.png"), page(4));
        String[] compare = {"compare", "--dir", mine.toString(), "--pages", "4", "--out-dir", mine.toString()};
        for (int run = 1; run <= 2; run++) {
            CliRun same = CliRun.of(compare);
            assertEquals(ExitCode.OK, same.exitCode(), "run " + run + ": " + same.out() + same.err());
            assertEquals(2, csvRows(mine).size(), "run " + run + ": a heading and page4.png");
        }
        assertTrue(Files.isRegularFile(mine.resolve("diffs/page4-diff.png")));
        // check's report elsewhere in the folder: a diffs folder beside a compare.csv is a batch's output
        CliRun.of("check", mine.toString(), "--pages", "4", "--out-dir", mine.resolve("report").toString());
        png(mine.resolve("report/diffs/page4-diff.png"), page(5));
        CliRun after = CliRun.of(compare);
        assertEquals(ExitCode.OK, after.exitCode(), after.out() + after.err());
        assertEquals(2, csvRows(mine).size(), "a heading and page4.png");
    }

    @Test
    void noTwoPicturesShareADiffImage() throws Exception {
        Path class_ = dir.resolve("coll");
        png(class_.resolve("s/t_page1.png"), page(1));
        png(class_.resolve("s_t/page1.png"), page(2));
        png(class_.resolve("u/page2.png"), page(2));
        Files.createDirectories(class_.resolve("u"));
        ImageIO.write(page(3), "bmp", class_.resolve("u/page2.bmp").toFile());
        Path out = dir.resolve("out");
        CliRun.of("compare", "--dir", class_.toString(), "--pages", "1-2", "--out-dir", out.toString());
        List<String> diffs = csvRows(out).stream().skip(1).filter(r -> !r.contains(",MISSING,"))
                .map(r -> r.split(",")[11]).toList();
        assertEquals(List.of("diffs/s_t_page1-diff.png", "diffs/s_t_page1-2-diff.png", "diffs/u_page2-diff.png",
                "diffs/u_page2-2-diff.png"), diffs);
        try (var written = Files.list(out.resolve("diffs"))) {
            assertEquals(4, written.count(), "none written over another");
        }
    }

    @Test
    void aDiffImageThatCannotBeWrittenFailsTheRun() throws Exception {
        Path mine = dir.resolve("mine");
        png(mine.resolve("page1.png"), page(1));
        png(mine.resolve("page2.png"), page(3));
        Path out = dir.resolve("out");
        // A folder where each diff image goes: it cannot be written, even by root (permissions would not stop root).
        Files.createDirectories(out.resolve("diffs/page1-diff.png"));
        Files.createDirectories(out.resolve("diffs/page2-diff.png"));
        CliRun run = CliRun.of("compare", "--dir", mine.toString(), "--pages", "1", "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "page 1 passes, but its diff image is not written: " + run.err());
        assertTrue(csvRows(out).get(1).contains(",PASS,white,,diff not written: cannot write "), csvRows(out).get(1));
        assertTrue(run.err().contains("simpview compare: 1 diff image could not be written (cannot write "
                + out.resolve("diffs/page1-diff.png") + ": it is a folder)"), run.err());
        assertFalse(run.showsStackTrace(), run.err());

        // check writes diff images of the pictures that fail only (which fail the run already): it says so too.
        CliRun check = CliRun.of("check", mine.toString(), "--pages", "2", "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.err());
        assertTrue(check.err().contains("simpview check: 1 diff image could not be written (cannot write "), check.err());
    }

    @Test
    void hiddenFilesAndAMacZipsLeftoversAreLeftOutAndCounted() throws Exception {
        Path class_ = dir.resolve("class");
        png(class_.resolve("ann/page1.png"), page(1));
        png(class_.resolve("ann/.page1.png"), page(2)); // a hidden copy: would be a second page 1, failing
        png(class_.resolve("ann/.thumbs/page1.png"), page(3));
        Files.createDirectories(class_.resolve("ann/__MACOSX"));
        Files.write(class_.resolve("ann/__MACOSX/._page1.png"), new byte[] {0, 5, 22, 7, 0, 2, 0, 0});
        Files.createDirectories(class_.resolve("__MACOSX/ann"));
        Files.write(class_.resolve("__MACOSX/ann/._page1.png"), new byte[] {0, 5, 22, 7, 0, 2, 0, 0});
        Path out = dir.resolve("out");

        for (String[] args : new String[][] {
            {"compare", "--dir", class_.toString(), "--pages", "1", "--out-dir", out.toString()},
            {"check", class_.resolve("ann").toString(), "--pages", "1"}}) {
            CliRun run = CliRun.of(args);
            assertEquals(ExitCode.OK, run.exitCode(), String.join(" ", args) + ": " + run.out() + run.err());
            assertFalse(run.out().contains("MACOSX") || run.out().contains(".page1") || run.out().contains(".thumbs"),
                    run.out());
        }
        assertEquals(List.of("ann/page1.png"), csvRows(out).stream().skip(1).map(r -> r.substring(0, r.indexOf(',')))
                .toList(), "no __MACOSX submission, no second page 1");
        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--pages", "1", "--out-dir", out.toString());
        assertEquals(1, run.err().split("hidden picture", -1).length - 1, "said once: " + run.err());
        assertTrue(run.err().contains("simpview compare: 4 hidden pictures left out (a name starting with '.', or in a "
                + "__MACOSX folder: a Mac's zip leftovers)"), run.err());
    }

    /** A panel moved or turned whole is named so in the table, on stderr and in the student's own feedback. */
    @Test
    void aPanelTurnedOrMovedWholeIsNamedInEveryResult() throws Exception {
        Path subs = dir.resolve("subs");
        BufferedImage page = page(2);
        BufferedImage over = page(2);
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                over.setRGB(x, y, page.getRGB(x, 749 - y));
            }
        }
        png(subs.resolve("ann/page2.png"), over);
        png(subs.resolve("bob/page2.png"), page);
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "2", "--out-dir", out.toString(),
                "--gradescope", out.resolve("results.json").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        List<String> rows = csvRows(out);
        assertTrue(rows.get(1).startsWith("ann/page2.png,") && rows.get(1).endsWith("; looks upside down\""), rows.get(1));
        assertFalse(rows.get(2).contains("looks"), rows.get(2));
        assertTrue(run.err().contains("ann/page2.png: FAIL ") && run.err().contains("; looks upside down\n"), run.err());
        String results = Files.readString(out.resolve("results.json"));
        assertTrue(results.contains("hint: your panel is simpview's upside down: so turned back, 100.00 %"), results);
        assertEquals(1, results.split("hint:", -1).length - 1, "bob's right page gets none: " + results);
    }

    /** JUnit tells a picture that passes what is worth telling of it (its hint), and says nothing of a plain pass. */
    @Test
    void aPassWithAHintHasItInItsJUnitTestcase() throws Exception {
        Path subs = dir.resolve("subs");
        BufferedImage page = page(2);
        BufferedImage down = page(2);
        for (int y = 51; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                down.setRGB(x, y, page.getRGB(x, y - 1)); // a row down, as row = 650 - y draws it
            }
        }
        png(subs.resolve("ann/page2.png"), down);
        png(subs.resolve("bob/page2.png"), page);
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "2", "--out-dir", out.toString(),
                "--junit", out.resolve("results.xml").toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        String xml = Files.readString(out.resolve("results.xml"));
        assertTrue(xml.matches("(?s).*<testcase name=\"page 2 \\(seed 361\\) \\(ann/page2.png\\)\" classname=\"ann\">"
                + "<system-out>PASS: [^<]*\nhint: your panel is simpview's moved 1 px down: [^<]*</system-out></testcase>.*"),
                xml);
        assertTrue(xml.contains("<testcase name=\"page 2 (seed 361) (bob/page2.png)\" classname=\"bob\"></testcase>"),
                "a plain pass: nothing to say: " + xml);
    }

    @Test
    void aPageSimpviewCannotDrawStopsTheBatchBeforeAnythingIsGraded() throws Exception {
        Path subs = dir.resolve("subs");
        png(subs.resolve("ann/page1.png"), page(1));
        png(subs.resolve("ann/page6.png"), page(1));
        Path course = Files.createDirectories(dir.resolve("course")); // no page6.simp: the teacher's slip
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-8", "--simp-dir", course.toString(),
                "--out-dir", out.toString(), "--gradescope", out.resolve("results.json").toString(), "--junit",
                dir.resolve("results.xml").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("simpview compare: nothing was graded: simpview cannot draw page 6 itself, so "
                + "every picture of it would score 0 whatever it shows:\n  page 6: "), run.err());
        assertTrue(run.err().contains("page6.simp was not found in " + course.toAbsolutePath()), run.err());
        assertTrue(run.err().contains("--simp-dir names the folder of the course's page6.simp to page8.simp, here "
                + course.toAbsolutePath() + ": correct the file, or name the right folder."), run.err());
        assertTrue(run.err().endsWith("No picture was compared and no result file written.\n"), run.err());
        assertFalse(run.err().contains("[1/"), "no picture compared: " + run.err());
        assertFalse(Files.exists(out) || Files.exists(dir.resolve("results.xml")), "no result file");
        assertFalse(run.showsStackTrace(), run.err());

        // A scene with an error: its file, line and column, and the option that names it.
        Files.writeString(course.resolve("page6.simp"), "polygon (1,2\n");
        CliRun wrong = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-8", "--simp-dir",
                course.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, wrong.exitCode(), wrong.err());
        assertTrue(wrong.err().contains("  page 6: " + course.resolve("page6.simp") + ":1:13: "), wrong.err());
        assertFalse(Files.exists(out), "no result file");
        Path scenes = scenes("bar");
        Files.writeString(scenes.resolve("bar.simp"), "polygon (1,2\n");
        render(scenes.resolve("tri.simp"), subs.resolve("ann/tri.png"));
        png(subs.resolve("ann/bar.png"), page(1));
        for (String command : new String[] {"compare --dir " + subs + " --out-dir " + out, "check " + subs.resolve("ann")}) {
            CliRun scene = CliRun.of((command + " --scene " + scenes).split(" "));
            assertEquals(ExitCode.SCENE_ERROR, scene.exitCode(), scene.err());
            assertTrue(scene.err().contains("nothing was graded: simpview cannot draw bar.simp itself"), scene.err());
            assertTrue(scene.err().contains("  bar.simp: " + scenes.resolve("bar.simp") + ":1:13: "), scene.err());
            assertTrue(scene.err().contains("--scene names it: correct it, or name the right scene or folder with --scene."),
                    scene.err());
            assertEquals("", scene.out(), "no table: " + scene.out());
        }
        assertFalse(Files.exists(out), "no result file");
    }

    @Test
    void thePagesSimpviewCannotDrawAreNamedInPageOrderWhateverPicturesNeedThem() throws Exception {
        // ann's page8.png comes before bob's page6.png by name: the message went "page 8 and page 6"
        Path subs = dir.resolve("subs");
        png(subs.resolve("ann/page8.png"), page(1));
        png(subs.resolve("bob/page6.png"), page(1));
        png(subs.resolve("bob/page7.png"), page(1));
        Path course = Files.createDirectories(dir.resolve("course"));
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-8", "--simp-dir", course.toString(),
                "--out-dir", dir.resolve("out").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("simpview compare: nothing was graded: simpview cannot draw page 6, page 7 "
                + "and page 8 itself"), run.err());
        List<String> named = run.err().lines().filter(line -> line.startsWith("  page ")).map(line -> line.substring(
                0, line.indexOf(':'))).toList();
        assertEquals(List.of("  page 6", "  page 7", "  page 8"), named, run.err());
    }

    /**
     * A folder below the one graded that cannot be read (a student's, copied without read access) stopped the
     * batch with "class: cannot be listed", naming neither that folder nor why. (Root reads every folder, so
     * the tests, run as root, tell it from the walk's own exception.)
     */
    @Test
    void aFolderThatCannotBeListedIsNamedWithWhy() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("subs/bob"));
        String bob = subs.toString();
        assertEquals(dir.resolve("subs") + "/bob: cannot be listed (permission denied), so nothing in "
                + dir.resolve("subs") + " was graded", CompareBatch.unlisted(dir.resolve("subs"),
                        new AccessDeniedException(bob)));
        assertEquals(dir.resolve("subs") + ": cannot be listed (input/output error), so nothing in "
                + dir.resolve("subs") + " was graded", CompareBatch.unlisted(dir.resolve("subs"),
                        new IOException("Input/output error")));
        assertEquals(dir.resolve("nope") + ": no such folder", CompareBatch.unlisted(dir.resolve("nope"),
                new NoSuchFileException(dir.resolve("nope").toString())));
    }

    @Test
    void aFolderThatIsNotThereIsAClearError() {
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("nope").toString(), "--pages", "1-8", "--out-dir", out.toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().contains("--dir " + dir.resolve("nope") + ": no such folder"), run.err());
        assertFalse(run.showsStackTrace());
    }

    @Test
    void aFileWhereAFolderGoesIsAUsageErrorNamingTheCommand() throws Exception {
        Path picture = png(dir.resolve("mine.png"), page(1));
        Path nope = dir.resolve("nope");
        Path empty = Files.createDirectories(dir.resolve("empty"));
        String[][] cases = {
            {"compare --dir " + picture + " --pages 1-8 --out-dir " + dir.resolve("o"),
                "simpview: --dir " + picture + " is a file, not a folder (one picture: simpview compare " + picture
                        + " --page N)", "compare"},
            {"check " + picture, "simpview: " + picture + " is a file, not a folder (one picture: simpview compare "
                    + picture + " --page N)", "check"},
            {"check " + nope, "simpview: " + nope + ": no such folder", "check"},
            {"compare " + picture + " --page 6 --scene a.simp", "simpview: give --page N or --scene F.simp, not both",
                "compare"}};
        for (String[] c : cases) {
            CliRun run = CliRun.of(c[0].split(" "));
            assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), c[0] + ": " + run.err());
            assertEquals(c[1], run.err().lines().findFirst().orElse(""), c[0]);
            assertTrue(run.err().contains("See 'simpview " + c[2] + " --help'"), run.err());
            assertFalse(run.showsStackTrace(), run.err());
        }
        CliRun none = CliRun.of("check", empty.toString());
        assertEquals(ExitCode.SCENE_ERROR, none.exitCode(), none.err());
        assertTrue(none.err().contains("simpview check: no pictures (.png, .jpg, .gif, .bmp) found"), none.err());
    }

    /**
     * A page missing beside a picture whose name has no page number at all (a screenshot left as the tool named it)
     * or names the first assignment's page of its number (a1-page1.png where the eight pages are graded): both were
     * skipped, and the MISSING row said only that no picture was found. It names them, on the first page the
     * submission lacks, wherever the row's notes go.
     */
    @Test
    void aMissingPageIsToldOfAScreenshotOrAFirstAssignmentPageBesideIt() throws Exception {
        Path subs = dir.resolve("subs");
        png(subs.resolve("ann/page1.png"), page(1));
        png(subs.resolve("ann/page2.png"), page(2));
        png(subs.resolve("cara/page1.png"), page(1));
        png(subs.resolve("cara/Screenshot 2026-12-01 at 10.00.00.png"), page(2));
        png(subs.resolve("dan/Screenshot (3).png"), page(2));
        png(subs.resolve("gil/a1-page1.png"), page(1));
        png(subs.resolve("gil/page2.png"), page(2));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir", out.toString(),
                "--diffs", "none", "--junit", out.resolve("results.xml").toString());
        String screenshot = "cara/Screenshot 2026-12-01 at 10.00.00.png has no page number in its name: was it meant "
                + "as page 2, which cara lacks? If so, name it page2.png";
        assertTrue(run.out().contains("| cara/ | 2 (seed 361) |  |  |  |  |  |  |  | MISSING |  |  | no picture of page 2 "
                + "(seed 361) in cara was found; " + screenshot + " |"), run.out());
        // lacking both pages: said once, on the first, naming both
        assertTrue(run.out().contains("no picture of page 1 (seed 361) in dan was found; dan/Screenshot (3).png has no "
                + "page number in its name: was it meant as page 1 or page 2, which dan lacks? If so, name it for its "
                + "page, like page1.png |"), run.out());
        assertTrue(run.out().contains("| MISSING |  |  | no picture of page 2 (seed 361) in dan was found |"), run.out());
        String firstAssignment = "gil/a1-page1.png is named as the first assignment's page 1, not graded here (--pages "
                + "names the eight pages): if it is page 1 of the eight pages, name it page1.png";
        assertTrue(run.out().contains("no picture of page 1 (seed 361) in gil was found; " + firstAssignment + " |"),
                run.out());
        assertTrue(Files.readString(out.resolve("results.xml")).contains(screenshot), "JUnit's failure says it too");

        CliRun check = CliRun.of("check", subs.resolve("cara").toString(), "--pages", "1-2");
        assertTrue(check.out().contains("no picture of page 2 (seed 361) found: Screenshot 2026-12-01 at 10.00.00.png "
                + "has no page number in its name: was it meant as page 2, which the folder lacks? If so, name it "
                + "page2.png\n"), check.out());
    }

    /**
     * A page missing beside a picture named like no page (pag2.png) or for a page there is not (page9.png): the
     * MISSING row said only that no picture was found. It names them, wherever the row's notes go.
     */
    @Test
    void aMissingPageIsToldOfThePicturesThatMayHaveBeenMeantAsIt() throws Exception {
        Path subs = dir.resolve("subs");
        png(subs.resolve("ann/page1.png"), page(1));
        png(subs.resolve("ann/page2.png"), page(2));
        png(subs.resolve("bob/page1.png"), page(1));
        png(subs.resolve("bob/pag2.png"), page(2));
        png(subs.resolve("bob/page9.png"), page(2));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir", out.toString(),
                "--junit", out.resolve("results.xml").toString(), "--html", out.toString());
        String told = "bob/pag2.png is named like no page (its number, 2, is not after the word \"page\"): did you "
                + "mean page2.png?; bob/page9.png is named for page 9, and there is no page 9 (the pages are 1 to 8): was it meant "
                + "as page 2, which bob lacks?";
        assertTrue(run.out().contains("| bob/ | 2 (seed 361) |  |  |  |  |  |  |  | MISSING |  |  | no picture of page 2 "
                + "(seed 361) in bob was found; " + told + " |"), run.out());
        assertTrue(Files.readString(out.resolve("results.xml")).contains(told.replace("\"", "&quot;"))
                || Files.readString(out.resolve("results.xml")).contains(told), "JUnit's failure says it too");
        assertTrue(Files.readString(out.resolve("index.html")).contains(told.replace("\"", "&quot;")),
                "and the web report");
        assertFalse(run.out().contains("| ann/ |"), "ann lacks nothing: " + run.out());

        CliRun check = CliRun.of("check", subs.resolve("bob").toString(), "--pages", "1-2");
        assertTrue(check.out().contains("no picture of page 2 (seed 361) found: pag2.png is named like no page"),
                check.out());
        Path json = out.resolve("bob.json");
        CliRun.of("compare", "--dir", subs.resolve("bob").toString(), "--pages", "1-2", "--gradescope", json.toString());
        assertTrue(Files.readString(json).contains("pag2.png is named like no page (its number, 2, is not after the "
                + "word \\\"page\\\"): did you mean page2.png?"), Files.readString(json));
    }

    /** A scene's picture named a slip of its name (pagC.png for pageC.simp) is named in the scene's MISSING row. */
    @Test
    void aMissingSceneIsToldOfAPictureNamedASlipOfIt() throws Exception {
        Path scenes = scenes("bar");
        Path class_ = dir.resolve("class");
        render(scenes.resolve("tri.simp"), class_.resolve("ann/tri.png"));
        render(scenes.resolve("tri.simp"), class_.resolve("bob/tir.png"));
        CliRun run = CliRun.of("compare", "--dir", class_.toString(), "--scene", scenes.toString(), "--out-dir",
                dir.resolve("out").toString());
        assertTrue(run.out().contains("no picture of tri.simp in bob was found; bob/tir.png is named like no scene: did "
                + "you mean tri.png? |"), run.out());
    }

    /**
     * check of a folder given as "ann/." (as "." is) named its pictures ann/./page2.png and ./page2.png: by the
     * folder given, without its "." parts, in the errors and the command to run next.
     */
    @Test
    void aFolderGivenWithDotPartsNamesItsPicturesWithoutThem() throws Exception {
        Path ann = dir.resolve("ann");
        png(ann.resolve("page1.png"), paint(page(1), 100, 100, 500, 500, 0xFF00FF));
        Files.writeString(ann.resolve("page2.png"), "junk");
        CliRun run = CliRun.of("check", ann + "/.");
        assertTrue(run.out().contains(" " + ann.resolve("page2.png") + " is not a picture simpview can read"), run.out());
        assertTrue(run.out().contains("simpview compare " + ann.resolve("page1.png") + " --page 1"), run.out());
        assertFalse(run.out().contains("/./") || run.err().contains("/./"), run.out() + run.err());
    }

    /** A link out of the folder "." names the folder in full: "outside ." named nothing. */
    @Test
    void aLinkOutOfTheFolderDotNamesTheFolderInFull() {
        Path link = Path.of(".").resolve("page3.png");
        FolderListing listing = new FolderListing(List.of(link), 0, List.of(), List.of(),
                Map.of(link, Path.of("/etc/hostname")));
        assertEquals("page3.png is a link to /etc/hostname, which is outside " + Path.of("").toAbsolutePath()
                + ": simpview follows no link out of the folder it grades; put the picture itself in its place",
                listing.linkOut(link, Path.of(".")).orElseThrow());
    }
}
