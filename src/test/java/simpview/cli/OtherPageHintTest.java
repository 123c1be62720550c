package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.surface.PageCanvas;
import simpview.testing.CourseFiles;

/**
 * A picture that fails against the page its file is named for, but passes as another page of the same assignment,
 * is told so ("looks like page 4: is the file named for the wrong page?"), in every place a hint goes; its verdict
 * stays the named page's. A picture that fails for any other reason, or passes as no page but a plain one, is not.
 */
class OtherPageHintTest {

    /** What every such hint asks, in the report, the table, JUnit, results.json and the web report alike. */
    private static final String ASKED = "is the file named for the wrong page?";

    @TempDir
    Path dir;

    private static BufferedImage page(int number, PageContext context) throws Exception {
        return new PageRenderer().renderImage(number, context);
    }

    private static BufferedImage page(int number) throws Exception {
        return page(number, PageContext.defaults());
    }

    private Path png(String name, BufferedImage image) throws Exception {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    @Test
    void pageFourNamedPageFiveFailsAndIsToldItIsPageFour() throws Exception {
        Path picture = png("page5.png", page(4));
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "still graded as page 5: " + run.out());
        assertTrue(run.out().contains("FAIL: 30.25 % within 8/255 with slack (99.00 % needed)\n"), run.out());
        assertTrue(run.out().contains("hint: your picture passes as simpview's page 4, 100.00 % by the same rule, not "
                + "as page 5: is the file named for the wrong page? It is graded as page 5, the page its name names.\n"),
                run.out());
        assertEquals(1, run.out().split("hint:", -1).length - 1, run.out());
    }

    @Test
    void aSeededPageNamedForAnotherSeededPageNamesItWithItsSeed() throws Exception {
        Path picture = png("page3.png", page(2));
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "3");
        assertTrue(run.out().contains("hint: your picture passes as simpview's page 2 (seed 361), 100.00 % by the same "
                + "rule, not as page 3 (seed 361): " + ASKED), run.out());
    }

    /** Page 2 of another seed is no page of seed 361: it passes as none of them, and is told nothing. */
    @Test
    void aPageOfAnotherSeedIsNotCalledAnotherPage() throws Exception {
        Path picture = png("page1.png", page(2, PageContext.defaults().withSeed(7)));
        for (String named : new String[] {"1", "2", "3"}) {
            CliRun run = CliRun.of("compare", picture.toString(), "--page", named);
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
            assertFalse(run.out().contains(ASKED), "page " + named + ": " + run.out());
        }
    }

    /** A page with a shape of its own that fails fails for that, not for its name. */
    @Test
    void aPictureThatFailsForAnotherReasonGetsNoSuchHint() throws Exception {
        BufferedImage wrong = page(5);
        for (int y = 100; y < 400; y++) {
            for (int x = 100; x < 400; x++) {
                wrong.setRGB(x, y, 0x00FFFF);
            }
        }
        CliRun run = CliRun.of("compare", png("page5.png", wrong).toString(), "--page", "5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertFalse(run.out().contains("hint:"), run.out());
    }

    /**
     * A page so plain that an empty panel passes as it (page 1's thin lines, with --min 93) is no page to be told:
     * an empty picture, which passes as page 1 by that rule, is not told it is page 1.
     */
    @Test
    void aPagePlainEnoughForAnEmptyPanelToPassIsNeverNamed() throws Exception {
        BufferedImage empty = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < PageCanvas.SIZE; y++) {
            for (int x = 0; x < PageCanvas.SIZE; x++) {
                boolean panel = x >= 50 && x < 700 && y >= 50 && y < 700;
                empty.setRGB(x, y, panel ? PageCanvas.BACKGROUND : 0xFFFFFF);
            }
        }
        Path picture = png("page2.png", empty);
        CliRun asOne = CliRun.of("compare", picture.toString(), "--page", "1", "--min", "93");
        assertEquals(ExitCode.OK, asOne.exitCode(), "an empty panel passes as page 1 by this rule: " + asOne.out());
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "2", "--min", "93");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertFalse(run.out().contains(ASKED), "page 1 is too plain to be named: " + run.out());
    }

    @Test
    void aFirstAssignmentPageNamedForAnotherIsToldWhichItIs() throws Exception {
        Path picture = png("a1-page5.png", Assignment1.render(4, PageContext.defaults()));
        CliRun run = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("FAIL: every panel must reach 99.00 %"), run.out());
        assertTrue(run.out().contains("hint: your picture passes as simpview's A1 page 4 (seed 361), 100.00 % by the "
                + "same rule, not as A1 page 5 (seed 361): " + ASKED), run.out());
        assertEquals(1, run.out().split("hint:", -1).length - 1, "one hint, of the page: " + run.out());
    }

    @Test
    void checkTellsTheStudentInItsTable() throws Exception {
        png("mine/page4.png", page(4));
        png("mine/page5.png", page(4));
        CliRun run = CliRun.of("check", dir.resolve("mine").toString(), "--pages", "4-5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("hint: page5.png (page 5): your picture passes as simpview's page 4, 100.00 % by "
                + "the same rule, not as page 5: " + ASKED), run.out());
        assertFalse(run.out().contains("page4.png (page 4): your picture"), "the right page gets none: " + run.out());
    }

    /** The table's note column, the progress line, JUnit, results.json and the web report each tell it. */
    @Test
    void aBatchTellsItInEveryResult() throws Exception {
        png("subs/ann/page4.png", page(4));
        png("subs/ann/page5.png", page(4));
        png("subs/bob/page5.png", page(5));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("subs").toString(), "--pages", "4-5", "--out-dir",
                out.toString(), "--junit", out.resolve("results.xml").toString(), "--gradescope",
                out.resolve("results.json").toString(), "--html", out.resolve("html").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        List<String> rows = Files.readAllLines(out.resolve("compare.csv"));
        String ann5 = rows.stream().filter(r -> r.startsWith("ann/page5.png,")).findFirst().orElseThrow();
        assertTrue(ann5.contains(",FAIL,") && ann5.endsWith("; looks like page 4: " + ASKED + "\""), ann5);
        assertEquals(1, rows.stream().filter(r -> r.contains(ASKED)).count(), "ann's page 4 and bob's page 5: " + rows);
        assertTrue(run.err().contains("ann/page5.png: FAIL 30.25 %; looks like page 4: " + ASKED + "\n"), run.err());
        String whole = "hint: your picture passes as simpview's page 4, 100.00 % by the same rule, not as page 5: "
                + ASKED + " It is graded as page 5, the page its name names.";
        String xml = Files.readString(out.resolve("results.xml"));
        assertTrue(xml.contains(whole), xml);
        String json = Files.readString(out.resolve("results.json"));
        assertTrue(json.contains(whole), json);
        String html = Files.readString(out.resolve("html/index.html"));
        assertTrue(html.contains(whole.replace("'", "&#39;")) || html.contains(whole), html);
    }

    @Test
    void aFirstAssignmentBatchTellsEachPanelsRow() throws Exception {
        png("subs/a1-page4.png", Assignment1.render(5, PageContext.defaults()));
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("subs").toString(), "--assignment", "1", "--pages", "4",
                "--out-dir", out.toString(), "--diffs", "none");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        List<String> panels = Files.readAllLines(out.resolve("compare.csv")).stream()
                .filter(r -> r.startsWith("a1-page4.png,")).toList();
        assertEquals(4, panels.size(), panels.toString());
        assertTrue(panels.stream().allMatch(r -> r.contains("looks like A1 page 5 (seed 361): " + ASKED)), panels.toString());
        assertEquals(1, run.err().split(ASKED, -1).length - 1, "one progress line, the hint once: " + run.err());
    }

    /** The course's pages 6 to 8 are candidates when their files are there, and simply not when they are not. */
    @Test
    void theCoursesPagesAreCandidatesOnlyWhenTheyCanBeDrawn() throws Exception {
        Path course = CourseFiles.requireSimpDir();
        Path seven = png("page7.png", page(6, PageContext.defaults().withSimpDir(course)));
        CliRun run = CliRun.of("compare", seven.toString(), "--page", "7", "--simp-dir", course.toString());
        assertTrue(run.out().contains("hint: your picture passes as simpview's page 6, 100.00 % by the same rule, not "
                + "as page 7: " + ASKED), run.out());
        Path noCourse = Files.createDirectories(dir.resolve("no-course"));
        CliRun without = CliRun.of("compare", png("page5.png", page(4)).toString(), "--page", "5", "--simp-dir",
                noCourse.toString());
        assertEquals(ExitCode.SCENE_ERROR, without.exitCode(), without.err());
        assertTrue(without.out().contains("passes as simpview's page 4"), without.out());
        assertTrue(without.err().isEmpty(), "pages 6 to 8 not drawn, and nothing said of them: " + without.err());
    }
}
