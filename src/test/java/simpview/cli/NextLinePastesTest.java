package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;

/**
 * A {@code next:} line is one command after its label, as a student pastes
 * it into a shell: cut off the label, split as a shell splits it, and run
 * through simpview's own command line, it parses and runs (a failing
 * picture's compare fails its verdict, exit 1, and says so; an inspect exits
 * 0). Here a lit scene's, and check's under a rubric (the eight pages', the
 * first assignment's and check's own are run so in
 * {@link CompareNextStepTest}): the rubric goes with the command check
 * prints, so the picture alone gets the check's verdict.
 */
class NextLinePastesTest {

    @TempDir
    Path dir;

    /** Page 4 with a square of its panel, {@code side} pixels wide from image column and row 300, made brighter. */
    private static Path brightened(Path file, int side) throws Exception {
        BufferedImage page = page(4);
        for (int y = 300; y < 300 + side; y++) {
            for (int x = 300; x < 300 + side; x++) {
                int rgb = page.getRGB(x, y);
                int lighter = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    lighter |= Math.min(255, (rgb >> shift & 0xFF) + 60) << shift;
                }
                page.setRGB(x, y, lighter);
            }
        }
        Files.createDirectories(file.getParent());
        ImageIO.write(page, "png", file.toFile());
        return file;
    }

    /** The commands of the output's next: lines: each line's text after "next:", which must be all of one command. */
    private static List<String> nextCommands(String out) {
        List<String> commands = new ArrayList<>();
        out.lines().filter(l -> l.startsWith("next:")).forEach(l -> commands.add(l.substring("next:".length()).strip()));
        assertFalse(commands.isEmpty(), "no next: line in\n" + out);
        return commands;
    }

    /**
     * The command run as a shell would hand it to simpview, in process; a --diff it writes goes to the test's folder
     * (the word after --diff replaced), not to where the tests run.
     */
    private CliRun runPasted(String command) {
        List<String> words = new ArrayList<>(ArgumentLine.split(command));
        assertEquals("simpview", words.get(0), command);
        int diff = words.indexOf("--diff");
        if (diff >= 0) {
            words.set(diff + 1, dir.resolve("pasted-" + words.get(diff + 1)).toString());
        }
        CliRun run = CliRun.of(words.subList(1, words.size()).toArray(new String[0]));
        assertFalse(run.showsStackTrace(), run.err());
        assertTrue(run.exitCode() != ExitCode.USAGE_ERROR, command + "\n" + run.err());
        return run;
    }

    /** An inspect command of a next: line runs whole and explains its pixel. */
    private void inspectRuns(String command) {
        assertTrue(command.startsWith("simpview inspect "), command);
        CliRun inspect = runPasted(command);
        assertEquals(ExitCode.OK, inspect.exitCode(), command + "\n" + inspect.err());
    }

    /**
     * A compare command of a next: line runs whole, fails as its batch said, and gives an inspect line of its own
     * (run as {@link CompareNextStepTest} runs it).
     */
    private void compareRunsAndFails(String command) {
        assertTrue(command.startsWith("simpview compare "), command);
        CliRun alone = runPasted(command);
        assertEquals(ExitCode.SCENE_ERROR, alone.exitCode(), command + "\n" + alone.out() + alone.err());
        assertTrue(alone.out().contains("\nFAIL: "), alone.out());
        assertTrue(nextCommands(alone.out()).get(0).startsWith("simpview inspect --page 4 --at "), alone.out());
    }

    @Test
    void aLitScenesNextLinePastesWhole() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("lit scenes"));
        Path scene = Files.writeString(scenes.resolve("lit.simp"), "camera -1 -1 1 1 -1 -100\nambient 0.2 0.2 0.2\n"
                + "{\ntranslate 0 3 0\nlight 1 1 1 1 0\n}\nsurface 0.8 0.3 0.2\nphong\n"
                + "polygon (-3, -3, -5) (3, -3, -5) (0, 3, -5)\n");
        BufferedImage black = page(4);
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                black.setRGB(x, y, 0);
            }
        }
        Path mine = dir.resolve("lit.png");
        ImageIO.write(black, "png", mine.toFile());
        CliRun run = CliRun.of("compare", mine.toString(), "--scene", scene.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        List<String> commands = nextCommands(run.out());
        assertTrue(commands.get(0).contains(" --scene '" + scene + "' "), commands.get(0));
        commands.forEach(this::inspectRuns);
    }

    /**
     * A picture the default rule passes (a 10x10 square differs: 99.97 %) and a rubric's pixel limit fails: the
     * check judged by the rubric fails it, and the compare command it prints, run whole, fails it too (without the
     * rubric it would pass it: {@link #onePictureIsJudgedByItsPagesRule}).
     */
    @Test
    void aRubricsVerdictGoesWithTheCommandCheckPrints() throws Exception {
        Path folder = dir.resolve("graded");
        brightened(folder.resolve("page4.png"), 10);
        Path rubric = Files.writeString(dir.resolve("strict.json"),
                "{\"pages\": [{\"match\": \"4\", \"max_failing_pixels\": 20}]}");
        CliRun check = CliRun.of("check", folder.toString(), "--pages", "4", "--rubric", rubric.toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out() + check.err());
        List<String> commands = nextCommands(check.out());
        assertEquals(1, commands.size(), check.out());
        assertTrue(commands.get(0).contains(" --rubric " + rubric + " "), commands.get(0));
        compareRunsAndFails(commands.get(0));

        // the folder's own compare.json, as a folder dropped on the window is judged
        Files.copy(rubric, folder.resolve("compare.json"));
        List<String> window = nextCommands(CheckCommand.checkFolder(folder, PageContext.defaults()));
        assertEquals(commands.get(0).replace(rubric.toString(), folder.resolve("compare.json").toString()),
                window.get(0), "the command check printed, with the folder's rubric: run above");
    }

    /** One picture judged by the rubric's rule for its page; --rubric no longer needs --dir. */
    @Test
    void onePictureIsJudgedByItsPagesRule() throws Exception {
        Path mine = brightened(dir.resolve("mine.png"), 10);
        Path rubric = Files.writeString(dir.resolve("r.json"),
                "{\"defaults\": {\"min_share\": 99.99}, \"pages\": [{\"match\": \"5\", \"min_share\": 10}]}");
        CliRun run = CliRun.of("compare", mine.toString(), "--page", "4", "--rubric", rubric.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().startsWith("rubric:  " + rubric + ", its defaults (no rule names page4)\n"), run.out());
        assertTrue(run.out().contains("\nFAIL: 99.97 % within 8/255 with slack (99.99 % needed)\n"), run.out());
        assertEquals(ExitCode.OK, CliRun.of("compare", mine.toString(), "--page", "4").exitCode());
    }
}
