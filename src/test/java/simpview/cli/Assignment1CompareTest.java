package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.testing.CourseFiles;

/** {@code compare --assignment 1}: the page found in a picture, and shares panel by panel. */
class Assignment1CompareTest {

    @TempDir
    Path dir;

    @Test
    void ourOwnPageAgreesEverywhere() {
        Path page = dir.resolve("a1-page3.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "3", "--seed", "5", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "3", "--seed", "5");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(run.out().contains("page:    top-left at x 0, y 0"), run.out());
        assertTrue(run.out().contains("2 Bresenham                             100.00 %     100.00 %"), run.out());
        // Another seed's lines do not agree.
        CliRun other = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "3", "--seed", "6");
        assertEquals(ExitCode.SCENE_ERROR, other.exitCode());
        assertTrue(other.out().contains("FAIL"), other.out());
    }

    @Test
    void thePolygonPagesNameEachPanelsScene() {
        Path page = dir.resolve("a1-page5.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "5", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "5");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        int k = 0;
        for (String scene : new String[] {"starburst", "mesh", "perturbed mesh", "random triangles"}) {
            k++;
            String line = k + " " + scene;
            assertTrue(run.out().lines().anyMatch(l -> l.startsWith(line + "  ") && l.endsWith("100.00 %     100.00 %")),
                    run.out());
        }
    }

    @Test
    void theCoursesCaptureIsFoundAndJudgedPanelByPanel() {
        Path picture = CourseFiles.require("reference/images/a1/page2.png");
        CliRun run = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "2");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(run.out().contains("page:    top-left at x 1, y 31"), run.out());
        assertTrue(run.out().contains("4 antialiased                           100.00 %     100.00 %"), run.out());
        // SPEC's integer Bresenham is not the course's program's: its panels 2 and 3 fall short.
        String page1 = CourseFiles.require("reference/images/a1/page1.png").toString();
        CliRun bySpec = CliRun.of("compare", page1, "--assignment", "1", "--page", "1");
        assertTrue(bySpec.out().contains("2 Bresenham                              96.62 %      96.62 %"), bySpec.out());
        assertEquals(ExitCode.SCENE_ERROR, bySpec.exitCode(), bySpec.out());
        CliRun starburst = CliRun.of("compare", page1, "--assignment", "1", "--page", "1", "--a1-rule", "course");
        assertTrue(starburst.out().contains("Starburst, by the course's pictures' rule"), starburst.out());
        assertTrue(starburst.out().contains("2 Bresenham                              99.98 %      99.98 %"), starburst.out());
        assertEquals(ExitCode.OK, starburst.exitCode(), "every panel reaches 99 % within 8/255");
        for (CliRun course : new CliRun[] {run, bySpec, starburst}) {
            assertFalse(course.out().contains("hint:"), "no move, turn or swap explains a course's panel: " + course.out());
        }
        CliRun wrong = CliRun.of("compare", page1, "--assignment", "1", "--page", "1", "--a1-rule", "mine");
        assertEquals(ExitCode.USAGE_ERROR, wrong.exitCode());
        assertTrue(wrong.err().contains("--a1-rule must be spec or course, not mine"), wrong.err());
    }

    /**
     * --metric blur measures the blurred panels. On the course's page 1 the
     * antialiased panel's share within 8/255 goes down (99.02 to 98.75 %):
     * the blur spreads each differing pixel over its neighbours rather than
     * forgiving the course's antialiasing (docs/grading.md).
     */
    @Test
    void theBlurMetricMeasuresTheBlurredPanels() {
        String picture = CourseFiles.require("reference/images/a1/page1.png").toString();
        CliRun exact = CliRun.of("compare", picture, "--assignment", "1", "--page", "1");
        CliRun blur = CliRun.of("compare", picture, "--assignment", "1", "--page", "1", "--metric", "blur");
        assertTrue(blur.out().contains("metric:  both pictures' panels blurred (3x3) before they are compared"), blur.out());
        assertTrue(exact.out().contains("4 antialiased                            98.64 %      99.02 %"), exact.out());
        assertTrue(blur.out().contains("4 antialiased                            92.95 %      98.75 %"), blur.out());
        String self = dir.resolve("a1-page2.png").toString();
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "2", "--out", self).exitCode());
        CliRun same = CliRun.of("compare", self, "--assignment", "1", "--page", "2", "--metric", "blur");
        assertEquals(ExitCode.OK, same.exitCode(), same.out() + same.err());
        assertTrue(same.out().contains("4 antialiased                           100.00 %     100.00 %"), same.out());
    }

    @Test
    void aPictureWithoutTheFourPanelsIsRefusedClearly() {
        Path page = dir.resolve("page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "1", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains("no page of 4 panels of 300x300 found in " + page), run.err());
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "6").exitCode());
    }

    /** A batch of the eight pages does not take a1-page2.png for page 2: it compares it as the first assignment's. */
    @Test
    void aBatchOfTheEightPagesComparesAFirstAssignmentPageAsOne() throws Exception {
        Path subs = java.nio.file.Files.createDirectories(dir.resolve("subs"));
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "2",
                "--out", subs.resolve("a1-page2.png").toString()).exitCode());
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-8", "--out-dir", dir.resolve("report").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "--pages 1-8 asks for the eight pages: " + run.err());
        assertTrue(run.out().contains("| a1-page2.png | A1 page 2 panel 4 (antialiased) | 100.00 |"), run.out());
        assertTrue(run.out().contains("4 rows (1 picture): 4 pass, 0 fail, 0 could not be compared, 0 skipped; 8 pages "
                + "asked for without a picture"), run.out());
    }
}
