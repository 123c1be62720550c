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
import simpview.pages.Assignment1;
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
    private CliRun compareRunsAndFails(String command) {
        assertTrue(command.startsWith("simpview compare "), command);
        CliRun alone = runPasted(command);
        assertEquals(ExitCode.SCENE_ERROR, alone.exitCode(), command + "\n" + alone.out() + alone.err());
        assertTrue(alone.out().contains("\nFAIL: "), alone.out());
        assertTrue(nextCommands(alone.out()).get(0).startsWith("simpview inspect --page 4 --at "), alone.out());
        return alone;
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
    /**
     * A picture that fails against simpview's own page and matches a rubric's accepted alternate passes alone by that
     * alternate, as a batch passes it ({@link GradingCommandTest}); and the compare command check prints for one that
     * matches none (an alternate named for another page is not tried) tries the same alternates and fails against
     * simpview's own.
     */
    @Test
    void aPictureAloneTriesItsRulesAlternatesAsItsBatchDoes() throws Exception {
        Path alternates = Files.createDirectories(dir.resolve("alt"));
        brightened(alternates.resolve("page4-brighter.png"), 80);
        brightened(alternates.resolve("page5-other.png"), 120); // names page 5: not one of page 4's
        Path rubric = Files.writeString(dir.resolve("r.json"), "{\"pages\": [{\"match\": \"4\", \"alternates\": \"alt\"}]}");
        Path folder = dir.resolve("graded");
        Path mine = brightened(folder.resolve("page4.png"), 80);
        CliRun alone = CliRun.of("compare", mine.toString(), "--page", "4", "--rubric", rubric.toString());
        assertEquals(ExitCode.OK, alone.exitCode(), alone.out() + alone.err());
        assertTrue(alone.out().startsWith("rubric:  " + rubric + ", its rule \"match\": \"4\"; its accepted alternates, in "
                + alternates + ", are tried when simpview's own fails it\n"), alone.out());
        assertTrue(alone.out().contains("\nPASS: 100.00 % within 8/255 with slack (99.00 % needed)\nnote: matched the "
                + "accepted alternate page4-brighter.png; against simpview's own it fails: "), alone.out());

        // the page 5 alternate's picture, as page 4: the batch fails it, and so does the command it prints
        brightened(folder.resolve("page4.png"), 120);
        CliRun failing = CliRun.of("check", folder.toString(), "--pages", "4", "--rubric", rubric.toString());
        assertEquals(ExitCode.SCENE_ERROR, failing.exitCode(), failing.out() + failing.err());
        String command = nextCommands(failing.out()).get(0);
        CliRun pasted = compareRunsAndFails(command);
        assertTrue(pasted.out().contains("\nnote: it passes against none of the rule's 1 accepted alternate either (in "
                + alternates + ")\n"), pasted.out());
        assertFalse(pasted.out().contains("matched the accepted alternate"), pasted.out());
    }
    /**
     * A first-assignment page is judged alone by the rubric's panel rules, as check judges it, and says which rule
     * judged which panel: its panel 1 (4 % green), which the defaults fail, passes by a rule that needs 95 %; its
     * panel 2 (25 pixels off), which the defaults pass, fails by a rule of at most 10 failing pixels, in check, in the
     * command check prints and in the one a folder dropped on the window prints.
     */
    @Test
    void aFirstAssignmentPageAloneIsJudgedByTheRubricsPanelRules() throws Exception {
        BufferedImage page = Assignment1.render(2, PageContext.defaults());
        for (int y = 100; y < 160; y++) {
            for (int x = 100; x < 160; x++) {
                page.setRGB(x, y, 0x00FF00); // panel 1: 3,600 of its 90,000 pixels
                if (x < 105 && y < 105) {
                    page.setRGB(x + 400, y, 0x00FF00); // panel 2: 25
                }
            }
        }
        Path folder = Files.createDirectories(dir.resolve("a1"));
        Path mine = folder.resolve("a1-page2.png");
        ImageIO.write(page, "png", mine.toFile());
        Path strict = Files.writeString(dir.resolve("strict.json"), "{\"pages\": [{\"match\": \"a1-*-panel1\", "
                + "\"min_share\": 95}, {\"match\": \"a1-page2-panel2\", \"max_failing_pixels\": 10}]}");
        CliRun check = CliRun.of("check", folder.toString(), "--assignment", "1", "--pages", "2", "--rubric",
                strict.toString());
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out() + check.err());
        List<String> commands = nextCommands(check.out());
        assertEquals(1, commands.size(), check.out());
        assertTrue(commands.get(0).contains(" --assignment 1 --page 2 --rubric " + strict + " "), commands.get(0));
        CliRun pasted = runPasted(commands.get(0));
        assertEquals(ExitCode.SCENE_ERROR, pasted.exitCode(), pasted.out() + pasted.err());
        assertTrue(pasted.out().startsWith("rubric:  " + strict + ", panel 1 (DDA): its rule \"match\": \"a1-*-panel1\"\n"
                + "rubric:  " + strict + ", panel 2 (Bresenham): its rule \"match\": \"a1-page2-panel2\"\n"
                + "rubric:  " + strict + ", panels 3 and 4: its defaults, without slack (no rule names a1-page2-panel3 or "
                + "a1-page2-panel4)\n"), pasted.out());
        assertTrue(pasted.out().contains("\n1 DDA                                    96.00 %      96.00 %  95.00 % within "
                + "8/255, 1 px slack\n"), pasted.out());
        assertTrue(pasted.out().contains("\npanel 2 (Bresenham): 25 pixels in 1 patch differ by more than 8/255 even "
                + "with slack"), pasted.out());
        assertFalse(pasted.out().contains("\npanel 1 (DDA): "), "panel 1 passes by its rule: " + pasted.out());
        assertTrue(pasted.out().contains("\nFAIL: every panel must reach what its rule needs"), pasted.out());
        assertTrue(nextCommands(pasted.out()).get(0).startsWith("simpview inspect --assignment 1 --page 2 --at "),
                pasted.out());

        // the folder's own compare.json, as a folder dropped on the window is judged
        Files.copy(strict, folder.resolve("compare.json"));
        List<String> window = nextCommands(CheckCommand.checkFolder(folder, PageContext.defaults()));
        assertEquals(commands.get(0).replace(strict.toString(), folder.resolve("compare.json").toString()),
                window.get(0));
    }
}
