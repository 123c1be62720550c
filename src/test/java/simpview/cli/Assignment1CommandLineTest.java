package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;

/** {@code render --assignment 1}: the first assignment's pages from the command line. */
class Assignment1CommandLineTest {

    @TempDir
    Path dir;

    private static int[] pixels(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    @Test
    void onePageWithItsSeed() throws Exception {
        Path out = dir.resolve("a1-page3.png");
        CliRun run = CliRun.of("render", "--assignment", "1", "--page", "3", "--seed", "7", "--out", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertArrayEquals(pixels(Assignment1.render(3, PageContext.defaults().withSeed(7))),
                pixels(ImageIO.read(out.toFile())));
    }

    @Test
    void allFivePages() throws Exception {
        CliRun run = CliRun.of("render", "--assignment", "1", "--all", "--out-dir", dir.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        for (int n = 1; n <= 5; n++) {
            assertTrue(Files.isRegularFile(dir.resolve("a1-page" + n + ".png")), "a1-page" + n + ".png");
        }
        assertEquals(5, Files.list(dir).count());
    }

    @Test
    void aPageTheFirstAssignmentDoesNotHaveIsAUsageError() {
        CliRun run = CliRun.of("render", "--assignment", "1", "--page", "6", "--out", dir.resolve("x.png").toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().contains("--page must be 1 to 5 for the first assignment, not 6"), run.err());
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("render", "--assignment", "3", "--page", "1", "--out", "x.png").exitCode());
    }

    /** Every command that draws the pages says in its help which pages --seed changes, the first assignment's too. */
    @Test
    void theSeedsHelpNamesTheFirstAssignmentsSeededPages() {
        for (String[] help : new String[][] {{"--help"}, {"render", "--help"}, {"compare", "--help"}, {"check", "--help"},
            {"inspect", "--help"}}) {
            String text = CliRun.of(help).out().replaceAll("\\s+", " ");
            assertTrue(text.contains("--seed=S seed of the random pages: 1 to 3 of the eight, 3 to 5 of the first "
                    + "assignment's (default: 361)"), String.join(" ", help) + ": " + text);
        }
    }

    /** --page alone stays the second assignment's page. */
    @Test
    void pageAloneIsStillTheSecondAssignments() throws Exception {
        Path out = dir.resolve("p1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "1", "--out", out.toString()).exitCode());
        BufferedImage image = ImageIO.read(out.toFile());
        // A2's page has one 650x650 panel: its centre is inside it; A1's page has a white gutter there.
        assertEquals(0xFFFFFF, Assignment1.render(1, PageContext.defaults()).getRGB(375, 200) & 0xFFFFFF);
        assertTrue((image.getRGB(375, 200) & 0xFFFFFF) != 0xFFFFFF, "A2's page 1: (375, 200) is inside its one panel");
    }
}
