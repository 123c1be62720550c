package simpview.cli;

import static simpview.testing.Images.writePng;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.A1Layout;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.testing.CourseFiles;

/**
 * {@code compare --dir} and {@code check} compare the first assignment's pages
 * found in a folder panel by panel: one row per panel in every result format.
 */
class FirstAssignmentBatchTest {

    @TempDir
    Path dir;

    private static BufferedImage page(int number) {
        return Assignment1.render(number, PageContext.defaults());
    }

    /** The page with a 40x40 block of panel k painted magenta (1,600 of its 90,000 pixels). */
    private static BufferedImage spoiled(int number, int panel) {
        BufferedImage image = page(number);
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 40; x++) {
                image.setRGB(A1Layout.left(panel) + 100 + x, A1Layout.top(panel) + 100 + y, 0xFF00FF);
            }
        }
        return image;
    }

    /** The page as a window capture: at (1, 31) of a larger grey picture. */
    private static BufferedImage captured(BufferedImage page) {
        BufferedImage window = new BufferedImage(page.getWidth() + 12, page.getHeight() + 40, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < window.getHeight(); y++) {
            for (int x = 0; x < window.getWidth(); x++) {
                window.setRGB(x, y, 0xC0C0C0);
            }
        }
        window.getGraphics().drawImage(page, 1, 31, null);
        return window;
    }

    private static String line(String text, String containing) {
        return text.lines().filter(l -> l.contains(containing)).findFirst().orElse("(no line with " + containing + ")");
    }

    @Test
    void namesAndFoldersOfTheFirstAssignmentAreKnown() {
        for (String name : List.of("a1-page2.png", "a1page2.png", "A1_Page_2.png", "assignment1-page2.png",
                "a1/page2.png", "alice/A1/page2_starburst.png", "assignment-1/page2.png")) {
            assertTrue(FirstAssignmentGrading.namesFirstAssignment(name), name);
        }
        for (String name : List.of("page2.png", "alice/page2.png", "a2/page2.png", "a12/page2.png", "page12.png")) {
            assertFalse(FirstAssignmentGrading.namesFirstAssignment(name), name);
        }
    }

    @Test
    void eachPanelIsARowInEveryResultFormat() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("alice/a1-page2.png"), spoiled(2, 3));
        writePng(subs.resolve("bob/a1/page2.png"), captured(page(2)));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--assignment", "1", "--pages", "2", "--out-dir",
                out.toString(), "--diffs", "failing", "--gradescope", out.resolve("results.json").toString(),
                "--junit", out.resolve("results.xml").toString(), "--html", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "alice's panel 3 fails: " + run.err());
        assertTrue(run.err().contains("alice/a1-page2.png: FAIL: 3 of 4 panels pass; lowest 98.22 % (A1 page 2 panel 3 "
                + "(alternating DDA / Bresenham))"), run.err());

        List<String> csv = Files.readAllLines(out.resolve("compare.csv"));
        // a heading and the two pictures' eight panels: nothing is missing
        assertEquals(1 + 8, csv.size(), String.join("\n", csv));
        for (int k = 1; k <= 4; k++) {
            String alice = csv.get(k);
            String bob = csv.get(4 + k);
            assertTrue(alice.startsWith("alice/a1-page2.png,A1 page 2 panel " + k + " ("), alice);
            assertTrue(bob.startsWith("bob/a1/page2.png,A1 page 2 panel " + k + " ("), bob);
            assertTrue(bob.contains(",100.00,PASS,"), bob);
            assertTrue(bob.contains("page at x 1, y 31 of the picture"), bob);
            // 1,600 of 90,000 pixels: 98.22 % (rounded down)
            assertTrue(alice.contains(k == 3 ? ",98.22,FAIL," : ",100.00,PASS,"), alice);
        }
        assertTrue(Files.readString(out.resolve("compare.md")).contains("8 rows (2 pictures): 7 pass, 1 fail"));
        assertTrue(Files.exists(out.resolve("diffs/alice_a1-page2-panel3-diff.png")));
        BufferedImage diff = ImageIO.read(out.resolve("diffs/alice_a1-page2-panel3-diff.png").toFile());
        assertEquals(3 * 300 + 20, diff.getWidth());
        assertEquals(300, diff.getHeight());

        JsonObject results = JsonParser.parseString(Files.readString(out.resolve("results.json"))).getAsJsonObject();
        JsonArray tests = results.getAsJsonArray("tests");
        // the eight panels
        assertEquals(8, tests.size());
        assertEquals(8, tests.asList().stream().filter(t -> t.getAsJsonObject().get("name").getAsString()
                .startsWith("A1 page 2 panel ")).count());
        // results.json is one submission's: of the two pictures of A1 page 2, both named it plainly, alice's (the
        // first by name) counts there (3 of its 4 panels pass), bob's is worth nothing
        assertEquals(3.0, results.get("score").getAsDouble());
        assertEquals(4, tests.asList().stream().filter(t -> t.getAsJsonObject().get("max_score").getAsDouble() == 0).count());
        JsonObject failing = tests.get(2).getAsJsonObject();
        assertEquals("A1 page 2 panel 3 (alternating DDA / Bresenham) (alice/a1-page2.png)", failing.get("name").getAsString());
        assertTrue(failing.get("output").getAsString().startsWith(
                "FAIL: 98.22 % of panel pixels within 8/255 without slack (99.00 % needed)"), failing.get("output").getAsString());
        assertTrue(failing.get("output").getAsString().contains("x 100-139, y 160-199 (40x40): 1,600 pixels"),
                "the block in the panel's own coordinates, y up: " + failing.get("output").getAsString());

        String xml = Files.readString(out.resolve("results.xml"));
        assertEquals(8, xml.split("<testcase name=\"A1 page 2 panel ", -1).length - 1, xml);
        assertEquals(1, xml.split("type=\"below the minimum\"", -1).length - 1, xml);
        assertTrue(xml.contains("<testcase name=\"A1 page 2 panel 4 (antialiased) (bob/a1/page2.png)\" classname=\"bob\">"
                + "</testcase>"), xml);

        String html = Files.readString(out.resolve("index.html"));
        assertTrue(html.contains("width=\"920\" height=\"300\""), "the panel's diff image at 1:1");
        assertEquals(8, html.split("<section class=\"detail\"", -1).length - 1, "a view of every panel");
    }

    @Test
    void aRubricRuleForTheAntialiasedPanelsJudgesThemByFlipAndLeavesTheOthersExact() throws Exception {
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs);
        Files.copy(CourseFiles.require("reference/images/a1/page1.png"), subs.resolve("a1-page1.png"));
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"defaults\": {\"min_share\": 99.5},"
                + " \"pages\": [{\"match\": \"a1-*-panel4\", \"metric\": \"flip\", \"deviation\": 0}]}");
        CliRun exact = CliRun.of("check", subs.toString(), "--min", "99.5");
        assertTrue(line(exact.out(), "panel 4 (antialiased)").matches(".*FAIL +99\\.02 %.*"), exact.out());
        // page 1 alone asked for: without --pages, the folder of first-assignment pages would be asked for all five
        CliRun flip = CliRun.of("check", subs.toString(), "--rubric", rubric.toString(), "--a1-rule", "course",
                "--assignment", "1", "--pages", "1");
        // the course's antialiasing, FLIP forgives: 99.94 % of the panel at most 0.13
        assertTrue(line(flip.out(), "panel 4 (antialiased)").matches(".*PASS +99\\.94 %.*"), flip.out());
        // the other panels stay exact and without slack (FLIP would give the DDA panel 99.81 %)
        assertTrue(line(flip.out(), "panel 1 (DDA)").matches(".*PASS +99\\.97 %.*"), flip.out());
        assertTrue(line(flip.out(), "panel 2 (Bresenham)").matches(".*PASS +99\\.97 %.*"), flip.out());
        assertEquals(ExitCode.OK, flip.exitCode());

        Path picture = subs.resolve("a1-page1.png");
        CliRun strict = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "1", "--metric", "flip",
                "--flip-threshold", "0.02");
        assertTrue(strict.out().contains("FLIP <= 0.020"), strict.out());
        assertTrue(line(strict.out(), "4 antialiased").matches("4 antialiased +98\\.64 % +9[0-8]\\.[0-9]{2} %"),
                "a threshold near 0 forgives little: " + strict.out());
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "1",
                "--flip-threshold", "0.2").exitCode(), "a threshold without the metric");
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("check", subs.toString(), "--flip-threshold", "1.5").exitCode());
    }

    @Test
    void aPictureNamedLikeOneOfTheEightPagesThatHoldsAFirstAssignmentPageIsComparedAsOne() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("page2.png"), captured(page(2)));
        writePng(subs.resolve("page3.png"), new PageRenderer().renderImage(3, PageContext.defaults()));
        // --pages asks for the eight pages' pages 2 and 3: page2.png is one of those, and scores 0 saying why
        CliRun asked = CliRun.of("check", subs.toString(), "--pages", "2-3");
        assertEquals(ExitCode.SCENE_ERROR, asked.exitCode(), asked.out());
        assertTrue(line(asked.out(), "page2.png").matches("page2\\.png +page 2 \\(seed 361\\) +ERROR +it holds a page "
                + "of the first assignment \\(four framed 300x300 panels\\), not page 2 of the eight pages that --pages "
                + "names \\(--assignment 1 grades the first assignment's pages\\)"), asked.out());
        assertFalse(asked.out().contains("no picture of page 2"), "page2.png is a picture of it: " + asked.out());
        assertFalse(asked.out().contains("A1 page 2"), asked.out());
        // without --pages, the page it holds is what it is compared with
        CliRun check = CliRun.of("check", subs.toString());
        for (int k = 1; k <= 4; k++) {
            assertTrue(line(check.out(), "A1 page 2 panel " + k).matches("page2\\.png +A1 page 2 panel .* PASS +100\\.00 % +none"),
                    check.out());
        }
        assertTrue(line(check.out(), "page3.png").matches("page3\\.png +page 3 \\(seed 361\\) +PASS +100\\.00 % +none"),
                "one of the eight pages stays one: " + check.out());
        assertTrue(check.out().contains("no picture of page 2 (seed 361) found"), check.out());
    }

    @Test
    void withAssignment1ItsPagesAreAskedForAndAMissingOneCostsItsFourPanels() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("alice/a1-page1.png"), page(1));
        writePng(subs.resolve("alice/a1-page2.png"), page(2));
        writePng(subs.resolve("alice/a1-page3.png"), Assignment1.render(3, PageContext.defaults().withSeed(7)));
        writePng(subs.resolve("bob/a1-page1.png"), page(1));
        writePng(subs.resolve("bob/page3.png"), captured(Assignment1.render(3, PageContext.defaults().withSeed(7))));
        Path rubric = dir.resolve("compare.json");
        Files.writeString(rubric, "{\"pages\": [{\"match\": \"a1-*-panel4\", \"points\": 2}]}");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--assignment", "1", "--pages", "1-3", "--seed", "7",
                "--rubric", rubric.toString(), "--out-dir", out.toString(), "--diffs", "none",
                "--junit", out.resolve("results.xml").toString(), "--html", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob has no A1 page 2: " + run.out() + run.err());
        assertFalse(run.err().contains("note:"), run.err());

        List<String> csv = Files.readAllLines(out.resolve("compare.csv"));
        // a heading, five pictures of four panels (bob's page3.png is the first assignment's page 3), one MISSING row
        assertEquals(1 + 5 * 4 + 1, csv.size(), String.join("\n", csv));
        assertTrue(csv.stream().noneMatch(r -> r.contains(",FAIL,")), "seed 7, as drawn: " + String.join("\n", csv));
        assertTrue(csv.stream().anyMatch(r -> r.startsWith("bob/page3.png,A1 page 3 (seed 7) panel 1 (DDA),")),
                String.join("\n", csv));
        assertEquals("bob/,A1 page 2,,,,,,,,MISSING,,,no picture of A1 page 2 in bob was found", csv.get(csv.size() - 1));

        String xml = Files.readString(out.resolve("results.xml"));
        assertTrue(xml.contains("<testcase name=\"A1 page 2 (no picture)\" classname=\"bob\"><failure message=\"no "
                + "picture of A1 page 2 found\" type=\"missing\">"), xml);
        String html = Files.readString(out.resolve("index.html"));
        // the page is worth its panels' points: 1 + 1 + 1 + 2
        assertTrue(html.contains("<td>A1 page 2</td><td>MISSING</td>"), html);
        assertTrue(html.contains(">0 / 5</td>"), html);

        Path bob = dir.resolve("bob.json");
        CliRun alone = CliRun.of("compare", "--dir", subs.resolve("bob").toString(), "--assignment", "1", "--pages", "1-3",
                "--seed", "7", "--rubric", rubric.toString(), "--gradescope", bob.toString());
        assertEquals(ExitCode.SCENE_ERROR, alone.exitCode(), alone.err());
        JsonObject results = JsonParser.parseString(Files.readString(bob)).getAsJsonObject();
        JsonArray tests = results.getAsJsonArray("tests");
        assertEquals(4 + 4 + 1, tests.size(), "two pages of four panels and the page not handed in: " + tests);
        JsonObject missing = tests.get(8).getAsJsonObject();
        assertEquals("A1 page 2 (no picture)", missing.get("name").getAsString());
        assertEquals(0.0, missing.get("score").getAsDouble());
        assertEquals(5.0, missing.get("max_score").getAsDouble(), "what its four panels would have scored");
        assertTrue(missing.get("output").getAsString().contains("e.g. a1-page2.png"), missing.toString());
        assertEquals(10.0, results.get("score").getAsDouble());
        assertEquals(15.0, tests.asList().stream().mapToDouble(t -> t.getAsJsonObject().get("max_score").getAsDouble())
                .sum(), "three pages of 5 points");

        CliRun check = CliRun.of("check", subs.resolve("bob").toString(), "--assignment", "1", "--seed", "7");
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out());
        for (String lacking : List.of("A1 page 2", "A1 page 4 (seed 7)", "A1 page 5 (seed 7)")) {
            assertTrue(check.out().contains("\nno picture of " + lacking + " found (name it like a1-page"),
                    "pages 1 to 5 asked for: " + check.out());
        }
        assertTrue(check.out().endsWith("8 of 8 panels pass (2 pages of the first assignment); 3 pages without a "
                + "picture\n"),
                check.out());
        assertEquals(ExitCode.OK, CliRun.of("check", subs.resolve("bob").toString(), "--assignment", "1", "--pages", "1,3",
                "--seed", "7").exitCode());
    }

    @Test
    void aFirstAssignmentPictureThatCannotBeComparedCostsItsWholePageOnce() throws Exception {
        Path bob = dir.resolve("bob");
        writePng(bob.resolve("a1-page1 copy.png"), page(1));
        Files.write(bob.resolve("a1-page1.png"), new byte[] {1, 2, 3}); // named the page alone: it counts, broken
        Files.write(bob.resolve("a1-page2.png"), new byte[] {1, 2, 3});
        Path json = dir.resolve("results.json");
        CliRun run = CliRun.of("compare", "--dir", bob.toString(), "--assignment", "1", "--pages", "1-2",
                "--gradescope", json.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        JsonArray tests = JsonParser.parseString(Files.readString(json)).getAsJsonObject().getAsJsonArray("tests");
        assertEquals(1 + 4 + 1, tests.size(), tests.toString());
        for (var test : tests) {
            JsonObject one = test.getAsJsonObject();
            String name = one.get("name").getAsString();
            double max = one.get("max_score").getAsDouble();
            if (name.endsWith("(a1-page1 copy.png)")) {
                assertEquals(0, max, "a1-page1.png counts for the page, not its copy's panels: " + one);
            } else {
                assertTrue(name.equals("A1 page 1 (a1-page1.png)") || name.equals("A1 page 2 (a1-page2.png)"), name);
                assertEquals(4, max, "a page that cannot be compared scores 0 of its four panels' points: " + one);
            }
        }
    }

    /**
     * check's last line counts every picture handed in, one that could not be checked among those that do not
     * pass and said as such: four right pages and one saved at 700x700 are 4 of 5 pictures, not "0 of 1 pictures
     * pass" beside 16 panels that all pass; the eight pages' pictures are counted the same way.
     */
    @Test
    void checksLastLineCountsAPictureThatCouldNotBeCheckedAsOneOfThoseHandedIn() throws Exception {
        Path mine = dir.resolve("mine");
        for (int p = 1; p <= 4; p++) {
            writePng(mine.resolve("a1-page" + p + ".png"), page(p));
        }
        BufferedImage small = new BufferedImage(700, 700, BufferedImage.TYPE_INT_RGB);
        small.getGraphics().drawImage(page(5), 0, 0, 700, 700, null);
        writePng(mine.resolve("a1-page5.png"), small);
        CliRun check = CliRun.of("check", mine.toString(), "--assignment", "1");
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out());
        assertTrue(check.out().endsWith("\n4 of 5 pictures pass; 16 of 16 panels pass (4 pages of the first "
                + "assignment); 1 picture could not be checked (said above)\n"), check.out());

        Path eight = dir.resolve("eight");
        writePng(eight.resolve("page4.png"), new PageRenderer().renderImage(4, PageContext.defaults()));
        writePng(eight.resolve("page5.png"), small);
        CliRun pages = CliRun.of("check", eight.toString(), "--pages", "4-5");
        assertEquals(ExitCode.SCENE_ERROR, pages.exitCode(), pages.out());
        assertTrue(pages.out().endsWith("\n1 of 2 pictures pass; 1 picture could not be checked (said above)\n"),
                pages.out());
    }

    @Test
    void whereTheEightPagesAreAskedForAFirstAssignmentPageIsNeitherGradedNorAskedOfOthers() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("alice/a1-page2.png"), page(2));
        writePng(subs.resolve("bob/page1.png"), new PageRenderer().renderImage(1, PageContext.defaults()));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", out.toString(),
                "--diffs", "none", "--gradescope", out.resolve("results.json").toString());
        List<String> rows = Files.readAllLines(out.resolve("compare.csv"));
        assertEquals(List.of("alice/,1 (seed 361),,,,,,,,MISSING,,,no picture of page 1 (seed 361) in alice was found"),
                rows.stream().filter(r -> r.contains(",MISSING,")).toList(), "bob is not asked for alice's A1 page 2");
        assertTrue(rows.stream().anyMatch(r -> r.startsWith("alice/a1-page2.png,") && r.contains(",SKIPPED,")),
                String.join("\n", rows));
        assertFalse(Files.readString(out.resolve("results.json")).contains("A1 page"), "worth nothing, so no test");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
    }

    @Test
    void assignment1KeepsTheCoursesRuleAndRefusesScenesAndPagesBeyondFive() throws Exception {
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs);
        Files.copy(CourseFiles.require("reference/images/a1/page1.png"), subs.resolve("a1-page1.png"));
        CliRun course = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "1", "--a1-rule", "course");
        assertEquals(ExitCode.OK, course.exitCode(), "the course's page 1 by the course's rule: " + course.out());
        assertEquals(ExitCode.SCENE_ERROR, CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "1")
                .exitCode(), "by SPEC's rule its Bresenham panel fails");

        String[][] refused = {
            {"compare", "--dir", subs.toString(), "--assignment", "1", "--scene", subs.toString(), "--out-dir", "x"},
            {"compare", "--dir", subs.toString(), "--assignment", "1", "--pages", "1-8", "--out-dir", "x"},
            {"check", subs.toString(), "--assignment", "1", "--scene", subs.toString()},
            {"check", subs.toString(), "--assignment", "1", "--pages", "6"},
            {"check", subs.toString(), "--assignment", "3"}};
        for (String[] args : refused) {
            CliRun run = CliRun.of(args);
            assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), String.join(" ", args) + "\n" + run.err());
            assertFalse(run.showsStackTrace(), run.err());
        }
        assertTrue(CliRun.of(refused[1]).err().contains("--pages 1-8: the first assignment has pages 1 to 5"));
        assertTrue(CliRun.of(refused[0]).err().contains("--assignment 1 grades the first assignment's pages, not scenes"));
    }

    @Test
    void pagesOverAFolderOfFirstAssignmentPagesSaysSoOnceAndGradesAsBefore() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("alice/a1-page1.png"), page(1));
        writePng(subs.resolve("bob/a1-page1.png"), page(1));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-5", "--out-dir", out.toString(),
                "--diffs", "none");
        String note = "note: every picture is a page of the first assignment, but --pages names the eight pages";
        assertEquals(1, run.err().split(note, -1).length - 1, run.err());
        assertTrue(run.err().contains("give --assignment 1"), run.err());
        // the grading is as --pages says: each of the eight pages' pages 1 to 5 is missing for each student
        assertEquals(2 * 5, Files.readAllLines(out.resolve("compare.csv")).stream().filter(r -> r.contains(",MISSING,"))
                .count());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());

        CliRun check = CliRun.of("check", subs.resolve("alice").toString(), "--pages", "1");
        assertTrue(check.err().contains(note), check.err());
        assertFalse(CliRun.of("check", subs.resolve("alice").toString()).err().contains("note:"),
                "without --pages nothing of the eight pages is asked for");
        writePng(subs.resolve("bob/page2.png"), new PageRenderer().renderImage(2, PageContext.defaults()));
        CliRun mixed = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-5", "--out-dir", out.toString(),
                "--diffs", "none");
        assertFalse(mixed.err().contains("note:"), "a page of the eight is handed in: " + mixed.err());
    }

    /**
     * check of a folder whose every picture holds a first-assignment page (named page1.png ... as render names the
     * eight pages') asks for the first assignment's pages 1 to 5, as --assignment 1 does, not for the eight pages.
     */
    @Test
    void checkOfAFolderOfFirstAssignmentPagesAsksForThoseAsAssignment1Does() throws Exception {
        Path mine = dir.resolve("mine");
        for (int n = 1; n <= Assignment1.COUNT; n++) {
            writePng(mine.resolve("page" + n + ".png"), page(n));
        }
        CliRun check = CliRun.of("check", mine.toString());
        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertFalse(check.out().contains("no picture of"), check.out());
        assertTrue(check.err().contains("simpview check: every picture in " + mine + " is a page of the first "
                + "assignment, so its pages 1 to 5 are asked for, as --assignment 1 asks for them, and not the eight "
                + "pages (--pages RANGE asks for those)\n"), check.err());
        // simpview's own scenes (pages 4 and 5 of the eight) not found, as from an IDE started in another folder:
        // the eight pages are not what these pictures are compared with, so nothing stops
        CliRun elsewhere = CliRun.withOwnScenes(dir.resolve("no-such-folder"), "check", mine.toString());
        assertEquals(ExitCode.OK, elsewhere.exitCode(), elsewhere.out() + elsewhere.err());
        assertTrue(elsewhere.out().contains("A1 page 5"), elsewhere.out());
        writePng(mine.resolve("page4.png"), new PageRenderer().renderImage(4, PageContext.defaults()));
        CliRun eighth = CliRun.withOwnScenes(dir.resolve("no-such-folder"), "check", mine.toString());
        assertEquals(ExitCode.SCENE_ERROR, eighth.exitCode(), eighth.out() + eighth.err());
        assertTrue(eighth.err().contains("nothing was graded: simpview cannot draw page 4 itself"), eighth.err());
        writePng(mine.resolve("page4.png"), page(4));
        Files.delete(mine.resolve("page5.png"));
        Files.writeString(mine.resolve("page5.webp"), "not read");
        CliRun four = CliRun.of("check", mine.toString());
        assertEquals(ExitCode.SCENE_ERROR, four.exitCode(), four.out());
        assertTrue(four.out().contains("\nno picture of A1 page 5 (seed 361) found: page5.webp is named like it, but is "
                + "in a format simpview does not read"), four.out());
        assertEquals(1, four.out().split("no picture of", -1).length - 1, "only A1 page 5 is missing: " + four.out());

        // beside a scene of the folder and its picture, a first-assignment page names none of the eight pages either
        Path mixed = dir.resolve("mixed");
        writePng(mixed.resolve("page1.png"), page(1));
        Path scene = Files.writeString(mixed.resolve("tri.simp"), "polygon (-50,-50,-10) (50,-50,-10) (0,50,-100)\n");
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scene.toString(), "--out",
                mixed.resolve("tri.png").toString()).exitCode());
        CliRun both = CliRun.of("check", mixed.toString());
        assertEquals(ExitCode.OK, both.exitCode(), both.out() + both.err());
        assertFalse(both.out().contains("no picture of"), both.out());
        assertTrue(both.out().endsWith("\n2 of 2 pictures pass; 4 of 4 panels pass (1 page of the first assignment)\n"),
                "every picture counted whole, the first assignment's page also by its panels: " + both.out());
        assertFalse(both.err().contains("every picture in"), "not every picture is a first-assignment page: " + both.err());
    }

    /** The table's heading says the slack the rows were judged with: none for the first assignment's panels. */
    @Test
    void theTablesHeadingSaysThePanelsAreJudgedWithoutSlack() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("a1-page1.png"), page(1));
        Path out = dir.resolve("out");
        CliRun.of("check", mine.toString(), "--out-dir", out.toString());
        assertTrue(Files.readString(out.resolve("compare.md")).startsWith("Shares of panel pixels in percent; the result "
                + "is on the judged share: within 8/255 with no slack, 99.00 % needed.\n"),
                Files.readString(out.resolve("compare.md")));
        writePng(mine.resolve("page2.png"), new PageRenderer().renderImage(2, PageContext.defaults()));
        CliRun.of("check", mine.toString(), "--out-dir", out.toString()); // without --pages both are graded
        assertTrue(Files.readString(out.resolve("compare.md")).startsWith("Shares of panel pixels in percent; the "
                + "result is on the judged share: within 8/255 with one pixel of slack (the first assignment's panels: "
                + "no slack), 99.00 % needed.\n"), Files.readString(out.resolve("compare.md")));
        Files.delete(mine.resolve("a1-page1.png"));
        CliRun eight = CliRun.of("compare", "--dir", mine.toString(), "--pages", "2", "--out-dir", out.toString());
        assertTrue(eight.out().startsWith("Shares of panel pixels in percent; the result is on the judged share: within "
                + "8/255 with one pixel of slack, 99.00 % needed.\n"), eight.out());
    }

    @Test
    void checkPassesAFolderOfRightFirstAssignmentPages() throws Exception {
        Path subs = dir.resolve("mine");
        for (int n = 1; n <= Assignment1.COUNT; n++) {
            writePng(subs.resolve("a1-page" + n + ".png"), page(n));
        }
        // without --pages a folder of the first assignment's pages is asked for its five pages, not the eight pages
        CliRun check = CliRun.of("check", subs.toString());
        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertTrue(check.out().endsWith("20 of 20 panels pass (5 pages of the first assignment)\n"), check.out());
        writePng(subs.resolve("a1-page7.png"), page(2));
        CliRun seven = CliRun.of("check", subs.toString());
        assertTrue(seven.err().contains("a1-page7.png: SKIPPED: the first assignment has pages 1 to 5, not 7"), seven.err());
    }
}
