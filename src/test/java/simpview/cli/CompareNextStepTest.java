package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;

/**
 * A picture that fails is told the one pixel to look at first and the
 * {@code simpview inspect} command that explains it, with the options that
 * drew simpview's picture; the command runs as printed and looks at that
 * pixel.
 */
class CompareNextStepTest {

    @TempDir
    Path dir;

    /** Page 4 with an 80x80 square of its panel (x 250-329, y 470-549) made brighter. */
    private Path brightened(Path file) throws Exception {
        BufferedImage page = page(4);
        for (int y = 150; y < 230; y++) {
            for (int x = 300; x < 380; x++) {
                int rgb = page.getRGB(x, y);
                int lighter = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    lighter |= Math.min(255, (rgb >> shift & 0xFF) + 60) << shift;
                }
                page.setRGB(x, y, lighter);
            }
        }
        ImageIO.write(page, "png", file.toFile());
        return file;
    }

    /** The line starting {@code start} in {@code out}. */
    private static String line(String out, String start) {
        return out.lines().filter(l -> l.startsWith(start)).findFirst().orElseThrow(() -> new AssertionError(out));
    }

    @Test
    void aFailingPageIsToldThePixelToInspectAndTheCommandRunsAsPrinted() throws Exception {
        CliRun run = CliRun.of("compare", brightened(dir.resolve("mine.png")).toString(), "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        String look = line(run.out(), "look:    x ");
        assertTrue(look.contains(" differs most in patch 1: yours ("), look);
        assertTrue(look.contains("yours is brighter at 100.00 % and darker at 0.00 %"), look);
        String[] at = look.substring("look:    x ".length()).split(" differs")[0].split(", y ");
        int x = Integer.parseInt(at[0]);
        int y = Integer.parseInt(at[1]);
        assertTrue(x >= 250 && x <= 329 && y >= 470 && y <= 549, look);
        String next = line(run.out(), "next:    ");
        String command = "simpview inspect --page 4 --at " + x + "," + y + " --explain";
        assertEquals("next:    " + command, next);
        assertTrue(run.out().contains("\n         how simpview made that pixel, term by term:\n" + next + "\n"), run.out());
        List<String> words = ArgumentLine.split(command);
        CliRun inspect = CliRun.of(words.subList(1, words.size()).toArray(new String[0]));
        assertEquals(ExitCode.OK, inspect.exitCode(), inspect.err());
        assertFalse(inspect.showsStackTrace(), inspect.err());
    }

    /** A scene in a folder whose name has a space and a quote: the command quotes it, and runs. */
    @Test
    void aSceneIsNamedInTheCommandSoThatAShellReadsItBack() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("my scenes'"));
        Path scene = folder.resolve("page4.simp");
        Files.copy(Path.of("simp", "page4.simp"), scene);
        Files.copy(Path.of("simp", "cube.simp"), folder.resolve("cube.simp")); // page4.simp includes it
        CliRun run = CliRun.of("compare", brightened(dir.resolve("mine.png")).toString(), "--scene", scene.toString(),
                "--near-color", "1,1,1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        String next = line(run.out(), "next:    ");
        assertTrue(next.startsWith("next:    simpview inspect --scene '" + folder.toString().replace("'", "'\\''")
                + "/page4.simp' --near-color 1,1,1 --at "), next);
        String command = next.substring("next:    ".length());
        List<String> words = ArgumentLine.split(command);
        assertEquals(scene.toString(), words.get(3));
        CliRun inspect = CliRun.of(words.subList(1, words.size()).toArray(new String[0]));
        assertEquals(ExitCode.OK, inspect.exitCode(), inspect.err());
    }

    /** Pages 1 to 3 are drawn by the program from random values: inspect does not draw them, so none is suggested. */
    @Test
    void aRandomPageIsToldThePixelButNoInspectCommand() throws Exception {
        BufferedImage page = page(2);
        for (int y = 150; y < 230; y++) {
            for (int x = 300; x < 380; x++) {
                page.setRGB(x, y, 0x00FF00);
            }
        }
        Path mine = dir.resolve("two.png");
        ImageIO.write(page, "png", mine.toFile());
        CliRun run = CliRun.of("compare", mine.toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nlook:    x "), run.out());
        assertFalse(run.out().contains("next:"), run.out());
    }

    /**
     * {@code check} ends with the command that compares each failing picture alone, with the options it was given;
     * run as printed, that comparison names the pixel to look at and how to inspect it.
     */
    @Test
    void checkTellsEachFailingPictureTheCommandThatComparesItAlone() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("mine"));
        brightened(folder.resolve("page4.png"));
        ImageIO.write(page(5), "png", folder.resolve("page5.png").toFile());
        CliRun run = CliRun.of("check", folder.toString(), "--pages", "4-5", "--min", "98.5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        String command = "simpview compare " + folder.resolve("page4.png") + " --page 4 --min 98.5 --diff page4-diff.png";
        assertTrue(run.out().contains("\n      page4.png: the pixel to look at first, and how simpview made it:\nnext: "
                + command + "\n"), run.out());
        assertFalse(run.out().contains("page5.png: the pixel"), run.out());
        List<String> words = ArgumentLine.split(command.replace("page4-diff.png", dir.resolve("d.png").toString()));
        CliRun alone = CliRun.of(words.subList(1, words.size()).toArray(new String[0]));
        assertEquals(ExitCode.SCENE_ERROR, alone.exitCode(), alone.err());
        assertTrue(alone.out().contains("FAIL: 98.48 % within 8/255 with slack (98.50 % needed)"), alone.out());
        assertTrue(alone.out().contains("\nnext:    simpview inspect --page 4 --at "), alone.out());
    }

    /** The first assignment's page 2 with a green square (image columns and rows 100 to 159) in its panel 1. */
    private Path firstAssignmentTampered(Path file) throws Exception {
        BufferedImage page = Assignment1.render(2, PageContext.defaults());
        for (int y = 100; y < 160; y++) {
            for (int x = 100; x < 160; x++) {
                page.setRGB(x, y, 0x00FF00);
            }
        }
        Files.createDirectories(file.getParent());
        ImageIO.write(page, "png", file.toFile());
        return file;
    }

    /**
     * A page of the first assignment that fails is told, in its failing panel, the {@code inspect --assignment 1}
     * command of the pixel that differs most, in page coordinates; it runs as printed and looks at that pixel.
     */
    @Test
    void aFailingFirstAssignmentPageIsToldThePixelToInspect() throws Exception {
        Path mine = firstAssignmentTampered(dir.resolve("a1-page2.png"));
        CliRun run = CliRun.of("compare", mine.toString(), "--assignment", "1", "--page", "2", "--seed", "7");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        String next = line(run.out(), "next:    ");
        assertTrue(next.startsWith("next:    simpview inspect --assignment 1 --page 2 --seed 7 --at "), next);
        assertTrue(run.out().contains("\n         the lines that wrote the page's pixel, or wrote beside it:\n" + next),
                run.out());
        assertEquals(1, run.out().lines().filter(l -> l.startsWith("next:")).count(), "one panel fails: " + run.out());
        String command = next.substring("next:    ".length());
        String[] at = command.split(" --at ")[1].split(" ")[0].split(",");
        int x = Integer.parseInt(at[0]);
        int y = Integer.parseInt(at[1]);
        assertTrue(x >= 100 && x < 160 && y > 749 - 160 && y <= 749 - 100, command);
        List<String> words = ArgumentLine.split(command);
        CliRun inspect = CliRun.of(words.subList(1, words.size()).toArray(new String[0]));
        assertEquals(ExitCode.OK, inspect.exitCode(), inspect.err());
        assertTrue(inspect.out().contains("panel 1"), inspect.out());
    }

    /**
     * check --assignment 1 and the window's folder check end with the command that compares a failing page of the
     * first assignment alone, once for the page; run as printed, it names the pixel to inspect.
     */
    @Test
    void checkTellsAFailingFirstAssignmentPageTheCommandThatComparesItAlone() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("a1"));
        firstAssignmentTampered(folder.resolve("a1-page2.png"));
        ImageIO.write(Assignment1.render(3, PageContext.defaults()), "png", folder.resolve("a1-page3.png").toFile());
        CliRun run = CliRun.of("check", folder.toString(), "--assignment", "1", "--pages", "2-3", "--min", "99.5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        String command = "simpview compare " + folder.resolve("a1-page2.png") + " --assignment 1 --page 2 --min 99.5"
                + " --diff a1-page2-diff.png";
        String said = "\n      a1-page2.png: the pixel to look at first, in the panel that fails most, and how simpview "
                + "made it:\nnext: " + command + "\n";
        assertTrue(run.out().contains(said), run.out());
        assertEquals(1, run.out().lines().filter(l -> l.startsWith("next:")).count(), run.out());
        List<String> words = ArgumentLine.split(command.replace("a1-page2-diff.png", dir.resolve("d.png").toString()));
        CliRun alone = CliRun.of(words.subList(1, words.size()).toArray(new String[0]));
        assertEquals(ExitCode.SCENE_ERROR, alone.exitCode(), alone.err());
        assertTrue(alone.out().contains("\nnext:    simpview inspect --assignment 1 --page 2 --at "), alone.out());

        String window = CheckCommand.checkFolder(folder, PageContext.defaults());
        assertTrue(window.contains("\nnext: simpview compare " + folder.resolve("a1-page2.png")
                + " --assignment 1 --page 2 --diff a1-page2-diff.png\n"), window);
    }
}
