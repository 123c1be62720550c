package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import simpview.surface.PageCanvas;
import simpview.testing.Fifos;

/**
 * {@code render --scenes}: one picture per scene, and never two scenes' pictures at one path;
 * {@code render --out} and {@code --primitives} into a FIFO: its reader gets the file, the FIFO stays.
 */
class RenderCommandTest {

    @TempDir
    Path dir;

    /** A scene of one triangle over the page's centre, at depth z: depth-cued, each z its own grey. */
    private Path scene(String name, int z) throws IOException {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        return Files.writeString(file, "polygon (-80,-80," + z + ") (80,-80," + z + ") (0,80," + z + ")\n");
    }

    private static int centre(Path picture) throws IOException {
        BufferedImage image = ImageIO.read(picture.toFile());
        return image.getRGB(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2) & 0xFFFFFF;
    }

    private static List<String> names(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void scenesOfOneNameFromTwoFoldersAreNamedByTheirFolders() throws Exception {
        Path red = scene("mix/b.simp", -10);
        Path green = scene("mix2/b.simp", -150);
        scene("mix/c.simp", -50);
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", red.toString(), green.toString(), dir.resolve("mix").toString(),
                "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        // mix/b.simp, named twice (itself and in its folder), is drawn once
        assertEquals(List.of("c.png", "mix-b.png", "mix2-b.png"), names(out));
        assertEquals(centre(render(red)), centre(out.resolve("mix-b.png")));
        assertEquals(centre(render(green)), centre(out.resolve("mix2-b.png")));
        assertFalse(centre(out.resolve("mix-b.png")) == centre(out.resolve("mix2-b.png")), "two scenes, two pictures");
    }

    /**
     * render --scenes . named a scene that fails ./bad.simp: a folder given with "." parts ("scenes/.", as ".")
     * names its scenes without them, in the errors and in the contact sheet's "left out"; the good one is written.
     */
    @Test
    void aFolderGivenWithDotPartsNamesItsScenesWithoutThem() throws Exception {
        scene("scenes/good.simp", -10);
        Files.writeString(dir.resolve("scenes/bad.simp"), "line (0,0,-10\n");
        String folder = dir.resolve("scenes") + "/.";
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", folder, "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("bad.png not written: " + dir.resolve("scenes/bad.simp") + ":1:"), run.err());
        assertEquals(List.of("good.png"), names(out));
        CliRun sheet = CliRun.of("render", "--contact-sheet", folder, "--out", dir.resolve("sheet.png").toString());
        assertTrue(sheet.err().startsWith(dir.resolve("scenes/bad.simp") + " left out: " + dir.resolve("scenes/bad.simp")
                + ":1:"), sheet.err());
    }

    /**
     * A model or a scene named on the command line that is a loop of symbolic links says so: the model "file not
     * found", the scene "no scene loop.simp in" its folder, where ls shows the file. Skipped where links cannot be
     * made.
     */
    @Test
    void aLoopOfSymbolicLinksIsNamedAsOne() throws Exception {
        try {
            Files.createSymbolicLink(dir.resolve("self.obj"), Path.of("self.obj"));
            Files.createSymbolicLink(dir.resolve("loop.simp"), Path.of("loop.simp"));
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            Assumptions.abort("no symbolic links here: " + e);
        }
        Path scene = Files.writeString(dir.resolve("model.simp"), "# a lit scene\nobj \"self\"\n");
        CliRun run = CliRun.of("render", "--scene", scene.toString(), "--out", dir.resolve("model.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith(scene + ":2:5: self.obj is a loop of symbolic links (self.obj → self.obj); "
                + "looked for " + dir.resolve("self.obj")), run.err());
        CliRun loop = CliRun.of("render", "--scenes", dir.resolve("loop.simp").toString(), "--out-dir",
                dir.resolve("out").toString());
        assertTrue(loop.err().startsWith("simpview: no scene " + dir.resolve("loop.simp") + ": it is a loop of symbolic "
                + "links (loop.simp → loop.simp)\n"), loop.err());
    }

    /**
     * A folder of scenes that holds a link named .simp leading to no file renders the others and says of that one
     * why it is not drawn, with exit 1: it was passed over without a word. Skipped where links cannot be made.
     */
    @Test
    void aFoldersSceneThatIsALoopOfLinksIsNotPassedOverSilently() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("folder"));
        try {
            Files.createSymbolicLink(scenes.resolve("b.simp"), Path.of("c.simp"));
            Files.createSymbolicLink(scenes.resolve("c.simp"), Path.of("b.simp"));
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            Assumptions.abort("no symbolic links here: " + e);
        }
        Files.writeString(scenes.resolve("a.simp"), "polygon (0,0,-10) (50,0,-10) (0,50,-10)\n");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", scenes.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertEquals(List.of("a.png"), names(out));
        assertTrue(run.err().contains("b.png not written: " + scenes.resolve("b.simp") + ": "), run.err());
        assertTrue(run.err().contains("is a loop of symbolic links (b.simp → c.simp → b.simp)"), run.err());
        assertTrue(run.err().contains("is a loop of symbolic links (c.simp → b.simp → c.simp)"), run.err());
    }

    @Test
    void scenesOfOneNameAsLettersOfEitherCaseAreNamedByTheirFoldersToo() throws Exception {
        Path upper = scene("a3/Cube.simp", -10);
        Path lower = scene("a4/cube.simp", -150);
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", upper.toString(), lower.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertEquals(List.of("a3-Cube.png", "a4-cube.png"), names(out));
    }

    @Test
    void scenesWhoseFoldersShareANameTooAreRefused() throws Exception {
        Path one = scene("x/mix/b.simp", -10);
        Path two = scene("y/mix/b.simp", -150);
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", one.toString(), two.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertEquals("simpview: the scenes " + one + " and " + two + " would both be written to "
                + out.resolve("mix-b.png") + "; render them into different --out-dir folders",
                run.err().lines().findFirst().orElse(""));
        assertFalse(Files.exists(out));
    }

    /**
     * {@code render house.simp --out house.png}, no option saying what to render: one file is drawn as --scene
     * draws it, several or a folder as --scenes draws them; with nothing to render, the choices are named.
     */
    @Test
    void sceneFilesAloneSayWhatToRender() throws Exception {
        Path near = scene("a/near.simp", -10);
        Path far = scene("b/far.simp", -150);
        Path picture = dir.resolve("near.png");
        CliRun one = CliRun.of("render", near.toString(), "--out", picture.toString());
        assertEquals(ExitCode.OK, one.exitCode(), one.err());
        CliRun asScene = CliRun.of("render", "--scene", near.toString(), "--out", dir.resolve("same.png").toString());
        assertEquals(ExitCode.OK, asScene.exitCode(), asScene.err());
        assertTrue(Arrays.equals(Files.readAllBytes(picture), Files.readAllBytes(dir.resolve("same.png"))));
        Path out = dir.resolve("out");
        CliRun several = CliRun.of("render", near.toString(), dir.resolve("b").toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.OK, several.exitCode(), several.err());
        assertEquals(List.of("far.png", "near.png"), names(out));
        assertEquals(centre(picture), centre(out.resolve("near.png")));
        CliRun unsaid = CliRun.of("render", far.toString());
        assertEquals(ExitCode.USAGE_ERROR, unsaid.exitCode(), unsaid.err());
        assertTrue(unsaid.err().startsWith("simpview: missing --out F.png (or --out-dir D)"), unsaid.err());
        CliRun two = CliRun.of("render", near.toString(), far.toString());
        assertTrue(two.err().startsWith("simpview: several scenes, or a folder, are drawn one picture per scene, "
                + "NAME.png: give --out-dir D"), two.err());
        CliRun nothing = CliRun.of("render", "--out", picture.toString());
        assertEquals(ExitCode.USAGE_ERROR, nothing.exitCode(), nothing.err());
        assertTrue(nothing.err().startsWith("simpview: say what to render: --page N, --all, --scene F.simp, --scenes "
                + "F|DIR... or --contact-sheet (or give a scene file: simpview render house.simp --out house.png)"),
                nothing.err());
        assertFalse(one.showsStackTrace() || several.showsStackTrace() || nothing.showsStackTrace());
    }

    @Test
    void theHelpSaysHowScenesOfOneNameAreNamed() {
        CliRun run = CliRun.of("render", "--help");
        assertTrue(run.out().replaceAll("\\s+", " ").contains("scenes of one name from different folders as "
                + "FOLDER-NAME.png (course-simp-a3-cube.png)"), run.out());
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aPageWrittenIntoAFifoReachesItsReaderAndTheFifoStays() throws Exception {
        Path regular = dir.resolve("regular.png");
        CliRun run = CliRun.of("render", "--assignment", "1", "--page", "2", "--out", regular.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        Path fifo = Fifos.make(dir.resolve("f.png"));
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        run = CliRun.of("render", "--assignment", "1", "--page", "2", "--out", fifo.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
        byte[] got = Fifos.read(read, fifo);
        assertArrayEquals(Files.readAllBytes(regular), got);
        assertEquals(List.of("f.png", "regular.png"), names(dir));
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void primitivesWrittenIntoAFifoReachItsReader() throws Exception {
        CliRun listed = CliRun.of("render", "--assignment", "1", "--page", "1", "--primitives", "-");
        assertEquals(ExitCode.OK, listed.exitCode(), listed.err());
        Path fifo = Fifos.make(dir.resolve("lines"));
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        CliRun run = CliRun.of("render", "--assignment", "1", "--page", "1", "--primitives", fifo.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
        assertEquals(listed.out(), new String(Fifos.read(read, fifo), StandardCharsets.UTF_8));
    }

    /** The scene as render --scene draws it alone. */
    private Path render(Path scene) {
        Path picture = dir.resolve("alone").resolve(scene.getParent().getFileName() + ".png");
        CliRun run = CliRun.of("render", "--scene", scene.toString(), "--out", picture.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        return picture;
    }

    /**
     * A render that fails before it writes (a scene with a mistake, a usage error) opens and closes a FIFO named
     * by --out, so that its reader sees the end instead of waiting for ever; with no reader there the run still
     * ends; a regular file named by --out keeps what it held.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aFailedRenderGivesTheReaderOfItsFifoTheEndAndKeepsARegularFile() throws Exception {
        Path broken = Files.writeString(dir.resolve("broken.simp"), "polygon (0, 0, -1) (1, 0, -1) (1, 1)\n");
        Path fifo = Fifos.make(dir.resolve("f.png"));
        CliRun alone = CliRun.of("render", "--scene", broken.toString(), "--out", fifo.toString());
        assertEquals(ExitCode.SCENE_ERROR, alone.exitCode(), alone.err());

        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        CliRun run = CliRun.of("render", "--scene", broken.toString(), "--out", fifo.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith(broken + ":1:"), run.err());
        assertArrayEquals(new byte[0], Fifos.read(read, fifo));
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");

        read = Fifos.readAll(fifo);
        CliRun usage = CliRun.of("render", "--page", "9", "--out", fifo.toString());
        assertEquals(ExitCode.USAGE_ERROR, usage.exitCode(), usage.err());
        assertArrayEquals(new byte[0], Fifos.read(read, fifo));

        Path regular = Files.writeString(dir.resolve("drawn.png"), "drawn before");
        CliRun kept = CliRun.of("render", "--scene", broken.toString(), "--out", regular.toString());
        assertEquals(ExitCode.SCENE_ERROR, kept.exitCode(), kept.err());
        assertEquals("drawn before", Files.readString(regular));
        assertEquals(List.of("broken.simp", "drawn.png", "f.png"), names(dir));
    }

    /**
     * A line picocli cannot parse never reaches render, whichever word is wrong and wherever it stands: a
     * mistyped option after --out, a value that is no number before it, --out=F, --out in a file of words
     * (@words.txt), --primitives, the command's own name mistyped. The reader of each FIFO the line names as an output still sees the end.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aLineThatCannotBeParsedGivesTheReaderOfItsFifoTheEnd() throws Exception {
        Path fifo = Fifos.make(dir.resolve("f.png"));
        String f = fifo.toString();
        endSeenAfterAUsageError(fifo, "render", "--page", "1", "--out", f, "--sede", "3");
        endSeenAfterAUsageError(fifo, "render", "--page", "1", "--seed", "three", "--out", f);
        endSeenAfterAUsageError(fifo, "render", "--page", "1", "--out=" + f, "--sede=3");
        endSeenAfterAUsageError(fifo, "rendr", "--page", "1", "--out", f);
        Path words = Files.writeString(dir.resolve("words.txt"), "--page 1\n--out " + f + " --sede 3\n");
        endSeenAfterAUsageError(fifo, "render", "@" + words);
        Path listing = Fifos.make(dir.resolve("lines.txt"));
        endSeenAfterAUsageError(listing, "render", "--page", "1", "--primitives", listing.toString(), "--sede", "3");
    }

    /**
     * A line picocli cannot parse releases the FIFOs in --out-dir that its words say render would have written
     * there: a page of --all, --page N's (the first assignment's a1-pageN.png), --scene F's picture; and, once
     * the line parses, a usage error of render's own (--out-dir and --out both given) releases them alike.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aLineThatCannotBeParsedGivesTheReadersOfTheFifosInItsOutDirTheEnd() throws Exception {
        Path out = Files.createDirectories(dir.resolve("pages"));
        Path third = Fifos.make(out.resolve("page3.png"));
        endSeenAfterAUsageError(third, "render", "--all", "--out-dir", out.toString(), "--sede", "3");
        endSeenAfterAUsageError(third, "render", "--page=3", "--seed", "three", "--out-dir=" + out);
        Path first = Fifos.make(out.resolve("a1-page2.png"));
        endSeenAfterAUsageError(first, "render", "--assignment", "1", "--page", "2", "--out-dir", out.toString(),
                "--sede", "3");
        Path house = Fifos.make(out.resolve("house.png"));
        endSeenAfterAUsageError(house, "render", "--scene", dir.resolve("house.simp").toString(), "--out-dir",
                out.toString(), "--sede", "3");
        endSeenAfterAUsageError(third, "render", "--page", "3", "--out", dir.resolve("f.png").toString(),
                "--out-dir", out.toString());
    }

    /** {@code line} is a usage error, and the reader of {@code fifo} sees the end of the file, which stays a FIFO. */
    static void endSeenAfterAUsageError(Path fifo, String... line) throws Exception {
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        CliRun run = CliRun.of(line);
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), String.join(" ", line) + ": " + run.err());
        assertTrue(run.err().startsWith("simpview: "), run.err());
        assertArrayEquals(new byte[0], Fifos.read(read, fifo), String.join(" ", line));
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
    }

    /**
     * render --all writes one picture per page: pages that fail (the course's scenes not there: 6 to 8) are not
     * written, and the readers of their FIFOs see the end; the pages before them reach theirs.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void pagesThatFailAmongAllGiveTheReadersOfTheirFifosTheEnd() throws Exception {
        Path out = Files.createDirectories(dir.resolve("pages"));
        Path empty = Files.createDirectories(dir.resolve("no-course-scenes"));
        List<CompletableFuture<byte[]>> reads = new ArrayList<>();
        for (int n = 1; n <= 8; n++) {
            reads.add(Fifos.readAll(Fifos.make(out.resolve("page" + n + ".png"))));
        }
        CliRun run = CliRun.of("render", "--all", "--simp-dir", empty.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("page 6 not written: "), run.err());
        for (int n = 1; n <= 8; n++) {
            Path fifo = out.resolve("page" + n + ".png");
            byte[] got = Fifos.read(reads.get(n - 1), fifo);
            if (n <= 5) {
                assertEquals(PageCanvas.SIZE, ImageIO.read(new ByteArrayInputStream(got)).getWidth(),
                        "page " + n);
            } else {
                assertArrayEquals(new byte[0], got, "page " + n);
            }
            assertTrue(Fifos.isFifo(fifo), "the FIFO of page " + n + " was replaced by a file");
        }
    }

    /**
     * A write that fails midway ends render --all (the other pages would fail alike): the pages after it are not
     * written, and the readers of their FIFOs see the end.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aWriteThatFailsMidwayGivesTheReadersOfTheFifosAfterItTheEnd() throws Exception {
        Path out = Files.createDirectories(dir.resolve("a1"));
        Files.createDirectories(out.resolve("a1-page2.png")); // a folder where page 2 goes: its write fails
        CompletableFuture<byte[]> first = Fifos.readAll(Fifos.make(out.resolve("a1-page1.png")));
        List<CompletableFuture<byte[]>> later = new ArrayList<>();
        for (int n = 3; n <= 5; n++) {
            later.add(Fifos.readAll(Fifos.make(out.resolve("a1-page" + n + ".png"))));
        }
        CliRun run = CliRun.of("render", "--assignment", "1", "--all", "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().contains("it is a folder"), run.err());
        assertTrue(Fifos.read(first, out.resolve("a1-page1.png")).length > 0, "page 1 was written");
        for (int n = 3; n <= 5; n++) {
            Path fifo = out.resolve("a1-page" + n + ".png");
            assertArrayEquals(new byte[0], Fifos.read(later.get(n - 3), fifo), "page " + n);
            assertTrue(Fifos.isFifo(fifo), "the FIFO of page " + n + " was replaced by a file");
        }
    }
}
