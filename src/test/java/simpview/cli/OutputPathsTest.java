package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/** No command writes over a file it reads (a student's picture, a scene, a rubric): a usage error, the file kept. */
class OutputPathsTest {

    private static final String TRIANGLE = "polygon (-50,-50,-10) (50,-50,-10) (0,50,-100)\n";

    @TempDir
    Path dir;

    private Path page(Path file, int number) throws Exception {
        Files.createDirectories(file.getParent());
        ImageIO.write(new PageRenderer().renderImage(number, PageContext.defaults()), "png", file.toFile());
        return file;
    }

    /** The run was refused with {@code message} as its first line, and {@code kept} is as it was. */
    private static void refused(CliRun run, String message, Path kept, byte[] before) throws IOException {
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.out() + run.err());
        assertEquals("simpview: " + message, run.err().lines().findFirst().orElse(""), run.err());
        assertFalse(run.showsStackTrace(), run.err());
        assertArrayEquals(before, Files.readAllBytes(kept), kept + " is kept");
    }

    @Test
    void aDiffOverThePictureComparedIsRefused() throws Exception {
        Path mine = page(dir.resolve("mine.png"), 3);
        byte[] before = Files.readAllBytes(mine);
        refused(CliRun.of("compare", mine.toString(), "--page", "3", "--diff", mine.toString()),
                "--diff: " + mine + " is the picture to compare; writing there would overwrite it", mine, before);
        // by another name of the same file
        Path roundabout = dir.resolve("sub/../mine.png");
        refused(CliRun.of("compare", mine.toString(), "--page", "3", "--diff", roundabout.toString()),
                "--diff: " + roundabout + " is the picture to compare; writing there would overwrite it", mine, before);
    }

    @Test
    void aDiffNotNamedPngIsRefusedAsRendersOut() throws Exception {
        Path mine = page(dir.resolve("mine.png"), 3);
        Path jpg = dir.resolve("diff.jpg");
        CliRun run = CliRun.of("compare", mine.toString(), "--page", "3", "--diff", jpg.toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertEquals("simpview: --diff " + jpg + ": simpview writes PNG files only; name it .png",
                run.err().lines().findFirst().orElse(""));
        assertFalse(Files.exists(jpg));
        CliRun render = CliRun.of("render", "--page", "3", "--out", jpg.toString());
        assertEquals("simpview: --out " + jpg + ": simpview writes PNG files only; name it .png",
                render.err().lines().findFirst().orElse(""));
        assertEquals(ExitCode.OK, CliRun.of("compare", mine.toString(), "--page", "3", "--diff",
                dir.resolve("diff").toString()).exitCode(), "a name without an extension is a PNG's, as for render");
    }

    @Test
    void aDashNamesNoFileButStandardOutputOnlyForPrimitives() throws Exception {
        // '-' is standard output for --primitives; elsewhere it was a file named '-' in the working folder
        Path mine = page(dir.resolve("mine.png"), 3);
        Path dash = Path.of("-");
        String why = ": simpview writes it to a file, not to standard output ('-' is standard output for "
                + "--primitives only): name a file, or /dev/stdout to pipe it";
        refusedWithoutWriting(CliRun.of("render", "--page", "3", "--out", "-"), "--out -" + why, dash);
        refusedWithoutWriting(CliRun.of("compare", mine.toString(), "--page", "3", "--diff", "-"),
                "--diff -" + why, dash);
        refusedWithoutWriting(CliRun.of("compare", "--dir", dir.toString(), "--pages", "3", "--junit", "-"),
                "--junit -" + why, dash);
        refusedWithoutWriting(CliRun.of("compare", "--dir", dir.toString(), "--pages", "3", "--gradescope", "-"),
                "--gradescope -" + why, dash);
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "3", "--primitives", "-").exitCode());
    }

    /** The run was refused with {@code message} as its first line, and wrote no {@code file}. */
    private static void refusedWithoutWriting(CliRun run, String message, Path file) throws IOException {
        boolean written = Files.deleteIfExists(file);
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.out() + run.err());
        assertEquals("simpview: " + message, run.err().lines().findFirst().orElse(""), run.err());
        assertFalse(written, file + " is not written");
    }

    @Test
    void renderWritesNoPictureOverTheSceneItDraws() throws Exception {
        // a scene may be named without .simp, and a picture without .png
        Path scene = Files.writeString(dir.resolve("tri"), TRIANGLE);
        byte[] before = Files.readAllBytes(scene);
        refused(CliRun.of("render", "--scene", scene.toString(), "--out", scene.toString()),
                "--out: " + scene + " is the scene; writing there would overwrite it", scene, before);
        refused(CliRun.of("render", "--contact-sheet", "--out", scene.toString(), scene.toString()),
                "--out: " + scene + " is a scene to draw; writing there would overwrite it", scene, before);
        // tri's picture, tri.png, is the other scene
        Path other = Files.writeString(dir.resolve("tri.png"), TRIANGLE);
        refused(CliRun.of("render", "--scenes", scene.toString(), other.toString(), "--out-dir", dir.toString()),
                "--out-dir: " + other + " is a scene to draw; writing there would overwrite it", other,
                Files.readAllBytes(other));
    }

    @Test
    void aBatchWritesNoReportOverAPictureOrTheScene() throws Exception {
        Path subs = dir.resolve("subs");
        Path picture = page(subs.resolve("alice/page1.png"), 1);
        byte[] before = Files.readAllBytes(picture);
        refused(CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--junit", picture.toString()),
                "--junit: " + picture + " is a picture to compare; writing there would overwrite it", picture, before);
        Path scene = Files.writeString(dir.resolve("tri.simp"), TRIANGLE);
        refused(CliRun.of("compare", "--dir", subs.toString(), "--scene", scene.toString(), "--gradescope",
                scene.toString()), "--gradescope: " + scene + " is the scene; writing there would overwrite it", scene,
                Files.readAllBytes(scene));
    }
}
