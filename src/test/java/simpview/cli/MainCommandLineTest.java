package simpview.cli;

import simpview.testing.DrawnScenes;
import simpview.testing.Images;
import simpview.scene.simp.SceneDrawer;
import simpview.window.TestScenes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.Assignment2;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.PageCanvas;
import java.util.Arrays;

public class MainCommandLineTest {

    @TempDir
    Path dir;

    @Test
    void helpAndVersionExitZero() {
        CliRun help = CliRun.of("--help");
        assertEquals(ExitCode.OK, help.exitCode());
        assertTrue(help.out().contains("Usage: simpview"), help.out());
        CliRun renderHelp = CliRun.of("render", "--help");
        assertEquals(ExitCode.OK, renderHelp.exitCode());
        assertTrue(renderHelp.out().contains("--near-color"), renderHelp.out());
        CliRun version = CliRun.of("--version");
        assertEquals(ExitCode.OK, version.exitCode());
        assertTrue(version.out().startsWith("simpview "), version.out());
    }

    /**
     * The window's options given before a command (simpview --seed 5 render ...) were the window's, so the command
     * drew with its defaults and said nothing: page 1 of seed 361, or page 6 looked for away from --simp-dir D.
     */
    @Test
    void theWindowsOptionsBeforeACommandAreAUsageErrorSayingWhereTheyGo() throws Exception {
        Path out = dir.resolve("page1.png");
        CliRun seeded = CliRun.of("--seed", "5", "render", "--page", "1", "--out", out.toString());
        assertEquals(ExitCode.USAGE_ERROR, seeded.exitCode(), seeded.err());
        assertEquals(List.of("simpview: --seed is given before 'render', where it is the window's option and render "
                + "does not read it: give --seed after 'render' (simpview render --seed ...)",
                "See 'simpview render --help' for how to use it."), seeded.err().lines().toList());
        assertFalse(Files.exists(out), "nothing drawn with the seed left out");
        CliRun two = CliRun.of("--threads", "2", "--simp-dir", dir.toString(), "inspect", "--page", "6", "--at", "1,1");
        assertEquals(ExitCode.USAGE_ERROR, two.exitCode(), two.err());
        assertEquals("simpview: --threads and --simp-dir are given before 'inspect', where they are the window's "
                + "options and inspect does not read them: give --simp-dir after 'inspect' (simpview inspect "
                + "--simp-dir ...); inspect has no --threads", two.err().lines().findFirst().orElse(""), two.err());
        assertEquals(ExitCode.OK, CliRun.of("render", "--seed", "5", "--page", "1", "--out", out.toString())
                .exitCode(), "after the command, as its own");
        assertEquals(ExitCode.OK, CliRun.of("--help", "render").exitCode(), "help is help wherever it stands");
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 3})
    void pageOutputEqualsHeadlessRenderPixelForPixel(int page) throws Exception {
        Path out = dir.resolve("page.png");
        CliRun run = CliRun.of("render", "--page", String.valueOf(page), "--seed", "7", "--out", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        BufferedImage expected = new PageRenderer().renderImage(page, PageContext.defaults().withSeed(7));
        assertEquals(0, Images.differingPixels(expected, ImageIO.read(out.toFile())));
    }

    @Test
    void seedChangesTheRandomPages() throws Exception {
        Path a = dir.resolve("a.png");
        Path b = dir.resolve("b.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "2", "--out", a.toString()).exitCode());
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "2", "--seed", "8", "--out", b.toString()).exitCode());
        assertTrue(Images.differingPixels(ImageIO.read(a.toFile()), ImageIO.read(b.toFile())) > 1000);
    }

    @Test
    void allWritesEightFilesWhenEveryPageRenders() throws Exception {
        TestScenes.requireCourseSimpDir();
        PageContext context = TestScenes.courseContext();
        Path outDir = dir.resolve("pages");
        CliRun run = CliRun.of("render", "--all", "--simp-dir", TestScenes.courseSimpDir().toString(),
                "--out-dir", outDir.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        for (int n = 1; n <= Assignment2.COUNT; n++) {
            BufferedImage written = ImageIO.read(outDir.resolve("page" + n + ".png").toFile());
            BufferedImage expected = new PageRenderer().renderImage(n, context);
            assertEquals(0, Images.differingPixels(expected, written), "page " + n);
        }
    }

    /** --simp-dir naming the course's page6.simp itself, not its folder: said so, and which folder to name. */
    @Test
    void aSimpDirThatIsAFileIsToldToNameItsFolder() throws IOException {
        Path course = Files.createDirectories(dir.resolve("course"));
        Path page6 = Files.writeString(course.resolve("page6.simp"), "line (0,0,0) (10,10,0)\n");
        CliRun run = CliRun.of("render", "--page", "6", "--simp-dir", page6.toString(), "--out",
                dir.resolve("page6.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().contains("page6.simp was not found in " + page6.toAbsolutePath() + ", which is a file, "
                + "not a folder: name its folder, " + course.toAbsolutePath() + ", with --simp-dir DIR"), run.err());
    }

    @Test
    void allReportsMissingCourseFilesAndStillWritesTheOtherPages() {
        Path empty = dir.resolve("no-course-files");
        Path outDir = dir.resolve("pages");
        CliRun run = CliRun.of("render", "--all", "--simp-dir", empty.toString(), "--out-dir", outDir.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        for (int n = 1; n <= 3; n++) {
            assertTrue(Files.isRegularFile(outDir.resolve("page" + n + ".png")), "page " + n + " written");
        }
        for (int n = 6; n <= 8; n++) {
            assertFalse(Files.exists(outDir.resolve("page" + n + ".png")), "page " + n + " has no scene");
            assertTrue(run.err().contains("page" + n + ".simp was not found in " + empty.toAbsolutePath()), run.err());
        }
        assertFalse(run.showsStackTrace(), run.err());
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "render",
        "render --page 3",
        "render --page 0 --out x.png",
        "render --page 9 --out x.png",
        "render --page two --out x.png",
        "render --all --out x.png",
        "render --all --page 2 --out-dir d",
        "render --page 2 --out x.png --out-dir d",
        "render --contact-sheet --out-dir d",
        "render --page 2 --near-color 0,1,0 --out x.png",
        "render --scene a.simp --seed 3 --out x.png",
        "render --scene a.simp --near-color 1,2 --out x.png",
        "render --scene a.simp --far-color 0,0,nan --out x.png",
        "--frobnicate",
        "render --page 1 --out x.png extra",
        "render --page 1 --out x.jpg",
        "render --scene a.simp --own-colors --near-color 0,1,0 --out x.png",
        "render --page 4 --own-colors --out x.png"})
    void badArgumentsAreUsageErrors(String line) {
        CliRun run = CliRun.of(line.split(" "));
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().contains("--help' for how to use it."), "points at --help: " + run.err());
        assertFalse(run.err().contains("Usage:"), "the whole help is not printed: " + run.err());
        assertTrue(run.err().lines().count() <= 4, "the problem and one line: " + run.err());
        assertFalse(run.showsStackTrace(), run.err());
    }

    /** The parser's own words (groups by their synopsis, Java's types, argument indexes) are put in a student's. */
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "render --page 3 --page 4 --out-dir o | simpview: give only one of --page, --all, --scene, --scenes or "
                + "--contact-sheet: found --page=3 and --page=4",
        "render --page 3 --all --out-dir o | simpview: give only one of --page or --all",
        "render --all --threads abc --out-dir o | simpview: Invalid value for option '--threads': 'abc' is not a "
                + "whole number",
        "--seed x | simpview: Invalid value for option '--seed': 'x' is not a whole number",
        // a whole number too large for the option is out of range, not "not a whole number"
        "render --assignment 1 --page 3 --seed 9223372036854775808 --out o.png | simpview: Invalid value for option "
                + "'--seed': '9223372036854775808' is out of range: give a whole number from -9223372036854775808 to "
                + "9223372036854775807",
        "compare x.png --page 2 --seed -9223372036854775809 | simpview: Invalid value for option '--seed': "
                + "'-9223372036854775809' is out of range: give a whole number from -9223372036854775808 to "
                + "9223372036854775807",
        // an option with a range of its own is told it, as a value inside an int but outside the range is
        "render --all --threads 99999999999 --out-dir o | simpview: Invalid value for option '--threads': "
                + "'99999999999' is out of range: --threads must be 1 to 64",
        "compare x.png --page=2147483648 | simpview: Invalid value for option '--page': '2147483648' is out of range: "
                + "--page must be 1 to 8 (1 to 5 for the first assignment)",
        "render --page=-2147483649 --out o.png | simpview: Invalid value for option '--page': '-2147483649' is out of "
                + "range: --page must be 1 to 8 (1 to 5 for the first assignment)",
        "compare x.png --page 2 --assignment 99999999999 | simpview: Invalid value for option '--assignment': "
                + "'99999999999' is out of range: --assignment must be 1 or 2",
        "inspect --page 1 --pixel 1,1 --primitive 99999999999 | simpview: Invalid value for option '--primitive': "
                + "'99999999999' is out of range: far larger than any value it takes",
        "check a b | simpview: 'b': one argument more than simpview check takes",
        "check a b c | simpview: 'b', 'c': more arguments than simpview check takes"})
    void theParsersWordsArePutPlainly(String line, String said) {
        CliRun run = CliRun.of(line.trim().split(" "));
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertEquals(said.trim(), run.err().lines().findFirst().orElse(""));
    }

    @Test
    void aUsageErrorOfRenderPointsAtRenderHelpAndSuggestsTheNearestOption() {
        CliRun run = CliRun.of("render", "--pge", "3", "--out", "x.png");
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().contains("See 'simpview render --help'"), run.err());
        assertTrue(run.err().contains("--page"), "suggests --page: " + run.err());
    }

    @Test
    void outAsJpegSaysPngOnly() {
        CliRun run = CliRun.of("render", "--page", "1", "--out", dir.resolve("x.jpg").toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().contains("PNG files only"), run.err());
        assertFalse(Files.exists(dir.resolve("x.jpg")));
    }

    @Test
    void ownColorsDrawTheVertexColoursWithoutTheCue() throws IOException {
        Path scene = Files.writeString(dir.resolve("red.simp"),
                "polygon (-50, -50, -150) (1, 0, 0) (50, -50, -150) (1, 0, 0) (0, 50, -150) (1, 0, 0)\n");
        Path own = dir.resolve("own.png");
        Path cued = dir.resolve("cued.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scene.toString(), "--own-colors", "--out", own.toString()).exitCode());
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scene.toString(), "--out", cued.toString()).exitCode());
        int centre = PageCanvas.SIZE / 2;
        assertEquals(0xFF0000, ImageIO.read(own.toFile()).getRGB(centre, centre) & 0xFFFFFF, "own red");
        // Cued from white at z = 0 to black at z = -200: z = -150 is a quarter of the way, 64.
        assertEquals(0x404040, ImageIO.read(cued.toFile()).getRGB(centre, centre) & 0xFFFFFF, "cued grey");
    }

    @Test
    void emptyOutputNamesAreUsageErrors() {
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("render", "--page", "1", "--out", "").exitCode());
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("render", "--all", "--out-dir", "").exitCode());
    }

    @Test
    void badSceneGivesExitOneWithFileLineAndColumn() throws IOException {
        Path scene = Files.writeString(dir.resolve("bad.simp"), "# a bad scene\nline (0, 0, 0) (10, 10, -5)\nfrobnicate 1 2\n");
        CliRun run = CliRun.of("render", "--scene", scene.toString(), "--out", dir.resolve("bad.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertFalse(run.showsStackTrace(), run.err());
        assertTrue(run.err().contains("bad.simp"), run.err());
        assertTrue(run.err().contains(scene + ":3:1"), "file:line:col in " + run.err());
    }

    @Test
    void missingSceneGivesExitOneNamingTheFile() {
        Path missing = dir.resolve("nowhere.simp");
        CliRun run = CliRun.of("render", "--scene", missing.toString(), "--out", dir.resolve("x.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains("file not found: " + missing.toAbsolutePath().normalize()), run.err());
        assertFalse(Files.exists(dir.resolve("x.png")));
        assertFalse(run.showsStackTrace(), run.err());
    }

    @Test
    void sceneOptionDrawsACourseSceneLikeItsPage() throws Exception {
        Path course = TestScenes.requireCourseSimpDir();
        Path out = dir.resolve("scene.png");
        CliRun run = CliRun.of("render", "--scene", course.resolve("page6.simp").toString(), "--out", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        BufferedImage page = new PageRenderer().renderImage(6, TestScenes.courseContext());
        assertEquals(0, Images.differingPixels(page, ImageIO.read(out.toFile())));
    }

    @Test
    void aFolderGivenAsSceneIsAClearSceneError() {
        CliRun run = CliRun.of("render", "--scene", dir.toString(), "--out", dir.resolve("x.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains("not a file but a folder: " + dir.toAbsolutePath().normalize()), run.err());
    }

    @Test
    void unwritableOutputIsAClearMessageAndExitOne() throws IOException {
        Path aFile = Files.writeString(dir.resolve("plain-file"), "not a folder");
        CliRun run = CliRun.of("render", "--page", "1", "--out", aFile.resolve("page.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().startsWith("simpview: cannot write " + aFile.resolve("page.png")), run.err());
        assertFalse(run.showsStackTrace(), run.err());

        CliRun intoFolder = CliRun.of("render", "--page", "1", "--out", dir.toString());
        assertEquals(ExitCode.SCENE_ERROR, intoFolder.exitCode());
        assertTrue(intoFolder.err().contains("cannot write " + dir), intoFolder.err());
    }

    @Test
    void aBareWordThatNamesNoSceneIsNoWindowsScene() {
        CliRun run = CliRun.with(() -> true, "window");
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("simpview: no command or scene file 'window' (nor window.simp): the commands "
                + "are "), run.err());
        assertTrue(run.err().contains("render") && run.err().contains(" and "), run.err());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "comapre mine.png | no command or scene file 'comapre' | compare",
        "rendr --all --out-dir x | Unknown options: '--all', '--out-dir' | render",
        "chekc | no command or scene file 'chekc' | check",
        "--seed 7 comapre | no command or scene file 'comapre' | compare"})
    void aSlipInTheCommandsNameSaysWhichWasMeant(String line, String problem, String meant) {
        CliRun run = CliRun.with(() -> true, line.split(" "));
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        List<String> lines = run.err().lines().toList();
        assertEquals("simpview: " + problem, lines.get(0), run.err());
        String slip = Arrays.stream(line.split(" ")).filter(w -> !w.startsWith("-") && !w.equals("7"))
                .findFirst().orElseThrow();
        assertEquals("Did you mean 'simpview " + meant + "' for '" + slip + "'?", lines.get(1), run.err());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "render --all --out x.png | --all writes eight files: use --out-dir D, not --out",
        "render --assignment 1 --all --out x.png | --all writes five files (a1-page1.png ... a1-page5.png): use --out-dir "
                + "D, not --out",
        "render --all | --all needs --out-dir D",
        "render --page 2 | missing --out F.png (or --out-dir D)",
        "render --scene a.simp --out x.png --out-dir d | give --out F.png or --out-dir D, not both",
        "render --contact-sheet --out-dir d | --contact-sheet writes one file: use --out F.png, not --out-dir",
        "render --contact-sheet | missing --out F.png",
        "render --scenes a.simp | --scenes draws one picture per scene, NAME.png: give --out-dir D",
        "render --scenes a.simp --out x.png | --scenes writes one picture per scene: give --out-dir D, not --out"})
    void aMisplacedOutputSaysWhereItGoes(String line, String message) {
        CliRun run = CliRun.of(line.split(" "));
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertEquals("simpview: " + message, run.err().lines().findFirst().orElse(""), run.err());
    }

    @Test
    void aPageOrASceneGivenAFolderIsWrittenThereUnderItsName() throws Exception {
        Path folder = dir.resolve("pictures");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "2", "--seed", "7", "--out-dir", folder.toString())
                .exitCode());
        BufferedImage expected = new PageRenderer().renderImage(2, PageContext.defaults().withSeed(7));
        assertEquals(0, Images.differingPixels(expected, ImageIO.read(folder.resolve("page2.png").toFile())));
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "3", "--out-dir",
                folder.toString()).exitCode());
        assertTrue(Files.isRegularFile(folder.resolve("a1-page3.png")));
        Path scene = Files.writeString(dir.resolve("tri.simp"), "polygon (-50,-50,-10) (50,-50,-10) (0,50,-100)\n");
        CliRun run = CliRun.of("render", "--scene", scene.toString(), "--out-dir", folder.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        try (var files = Files.list(folder)) {
            assertEquals(List.of("a1-page3.png", "page2.png", "tri.png"),
                    files.map(f -> f.getFileName().toString()).sorted().toList());
        }
    }

    @Test
    void outputFoldersAreMadeWhenMissing() throws IOException {
        Path out = dir.resolve("a/b/page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "1", "--out", out.toString()).exitCode());
        BufferedImage image = ImageIO.read(out.toFile());
        assertNotNull(image);
        assertEquals(PageCanvas.SIZE, image.getWidth());
    }

    @Test
    void withoutADisplayTheWindowCommandHintsAtRender() {
        CliRun run = CliRun.with(() -> true);
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertEquals(1, run.err().strip().lines().count(), run.err());
        assertTrue(run.err().contains("simpview render"), run.err());
    }

    @Test
    void contactSheetTilesThePagesThatRender() throws Exception {
        Path out = dir.resolve("sheet.png");
        CliRun run = CliRun.of("render", "--contact-sheet", "--simp-dir", dir.toString(), "--out", out.toString());
        // Pages 6 to 8 have no files in an empty folder: named on stderr, left out, exit 1.
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains("page 6 left out"), run.err());
        BufferedImage sheet = ImageIO.read(out.toFile());
        BufferedImage page1 = ContactSheet.halved(new PageRenderer().renderImage(1, PageContext.defaults()));
        BufferedImage tile = sheet.getSubimage(ContactSheet.GAP, ContactSheet.GAP, ContactSheet.TILE, ContactSheet.TILE);
        assertEquals(0, Images.differingPixels(page1, tile));
    }

    @Test
    void aContactSheetOfScenesTilesThemInTheOrderGiven() throws Exception {
        Path lit = Files.writeString(dir.resolve("lit.simp"), "ambient 1 1 1\nsurface 0 0 1\n"
                + "polygon (-50, -50, -100) (50, -50, -100) (0, 50, -100)\n");
        Path cued = Files.writeString(dir.resolve("cued.simp"), "polygon (-50, -50, -50) (50, -50, -50) (0, 50, -50)\n");
        Path out = dir.resolve("scenes.png");
        CliRun run = CliRun.of("render", "--contact-sheet", "--out", out.toString(), lit.toString(), cued.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        BufferedImage sheet = ImageIO.read(out.toFile());
        assertEquals(ContactSheet.GAP + 2 * (ContactSheet.TILE + ContactSheet.GAP), sheet.getWidth());
        int cell = ContactSheet.TILE + ContactSheet.GAP;
        for (int k = 0; k < 2; k++) {
            PageCanvas canvas = new PageCanvas();
            DrawnScenes.draw(k == 0 ? lit : cued, canvas);
            BufferedImage tile = sheet.getSubimage(ContactSheet.GAP + k * cell, ContactSheet.GAP, ContactSheet.TILE,
                    ContactSheet.TILE);
            assertEquals(0, Images.differingPixels(ContactSheet.halved(canvas.image()), tile), "tile " + k);
        }
        // The lit scene is blue (kd * Ia), the depth-cued one 3/4 white at z = -50: round(0.75 * 255) = 191.
        assertEquals(0x0000FF, sheet.getRGB(ContactSheet.GAP + 187, ContactSheet.GAP + 187) & 0xFFFFFF);
        assertEquals(0xBFBFBF, sheet.getRGB(ContactSheet.GAP + cell + 187, ContactSheet.GAP + 187) & 0xFFFFFF);
    }

    @Test
    void aSceneThatFailsIsLeftOutOfTheSheetAndNamed() throws Exception {
        Path good = Files.writeString(dir.resolve("good.simp"), "ambient 1 1 1\n");
        Path bad = Files.writeString(dir.resolve("bad.simp"), "rotate W 5\n");
        Path out = dir.resolve("scenes.png");
        Path missing = dir.resolve("missing.simp");
        CliRun run = CliRun.of("render", "--contact-sheet", "--out", out.toString(), bad.toString(), good.toString(),
                missing.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().startsWith(bad + " left out: "), run.err());
        assertTrue(run.err().contains(missing + " left out: "), run.err());
        assertEquals(ContactSheet.GAP + ContactSheet.TILE + ContactSheet.GAP, ImageIO.read(out.toFile()).getWidth());
        Path none = dir.resolve("none.png");
        CliRun all = CliRun.of("render", "--contact-sheet", "--out", none.toString(), bad.toString());
        assertEquals(ExitCode.SCENE_ERROR, all.exitCode());
        assertTrue(all.err().endsWith(none + " not written: no scene rendered" + System.lineSeparator()), all.err());
        assertFalse(Files.exists(none));
    }

    @Test
    void aFolderOnTheSheetIsItsScenesInNaturalOrder() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("scenes"));
        // page1 at z = -50, page2 at -100, page10 at -150: 3/4, 1/2 and 1/4 white
        String[] names = {"page10", "page2", "page1"};
        int[] depths = {150, 100, 50};
        for (int k = 0; k < names.length; k++) {
            Files.writeString(folder.resolve(names[k] + ".simp"), String.format(
                    "polygon (-50, -50, -%1$d) (50, -50, -%1$d) (0, 50, -%1$d)%n", depths[k]));
        }
        Files.writeString(folder.resolve("notes.txt"), "not a scene");
        Path out = dir.resolve("sheet.png");
        CliRun run = CliRun.of("render", "--contact-sheet", "--out", out.toString(), folder.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        int cell = ContactSheet.TILE + ContactSheet.GAP;
        BufferedImage sheet = ImageIO.read(out.toFile());
        assertEquals(ContactSheet.GAP + 3 * cell, sheet.getWidth());
        int[] greys = new int[3];
        for (int k = 0; k < 3; k++) {
            greys[k] = sheet.getRGB(ContactSheet.GAP + k * cell + 187, ContactSheet.GAP + 187) & 0xFF;
        }
        assertTrue(greys[0] == 0xBF && greys[1] < greys[0] && greys[2] < greys[1] && greys[2] > 0,
                "page1, page2, page10, ever farther: " + Arrays.toString(greys));
        CliRun empty = CliRun.of("render", "--contact-sheet", "--out", out.toString(),
                Files.createDirectories(dir.resolve("nothing")).toString());
        assertEquals(ExitCode.USAGE_ERROR, empty.exitCode(), empty.err());
    }

    @Test
    void sceneFilesGoWithTheContactSheetOnly() {
        CliRun run = CliRun.of("render", "--page", "2", "--out", dir.resolve("p.png").toString(), "x.simp");
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().startsWith("simpview: x.simp: a scene file is drawn on its own (simpview render F.simp "
                + "--out F.png) or tiled with --contact-sheet, not with --page"), run.err());
        assertFalse(Files.exists(dir.resolve("p.png")));
    }

    @Test
    void depthCueColoursOnALitSceneAreAUsageErrorNamingTheLitCommand() throws Exception {
        Files.writeString(dir.resolve("part.simp"), "# lit\nambient 1 1 1\n");
        Path lit = Files.writeString(dir.resolve("lit.simp"), "file \"part\"\npolygon (0 0 -5) (1 0 -5) (0 1 -5)\n");
        Path out = dir.resolve("lit.png");
        for (String option : new String[] {"--near-color", "--far-color"}) {
            CliRun run = CliRun.of("render", "--scene", lit.toString(), option, "1,0,0", "--out", out.toString());
            assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), option);
            assertTrue(run.err().startsWith("simpview: --near-color and --far-color are for depth-cued scenes, and lit.simp"
                    + " is lit (part.simp:2 ambient)"), run.err());
            assertFalse(Files.exists(out));
        }
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", lit.toString(), "--out", out.toString()).exitCode());
        Path cued = Files.writeString(dir.resolve("cued.simp"), "polygon (0 0 -5) (1 0 -5) (0 1 -5)\n");
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", cued.toString(), "--near-color", "1,0,0", "--out",
                out.toString()).exitCode());
    }
}
