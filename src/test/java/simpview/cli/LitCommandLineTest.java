package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line with lit scenes: scene lists and folders, and depth-cue options that do not apply. */
public class LitCommandLineTest {

    @TempDir
    Path dir;

    private Path scene(String name, String... lines) throws IOException {
        Path file = dir.resolve(name + ".simp");
        Files.writeString(file, String.join("\n", lines));
        return file;
    }

    @Test
    void renderWritesEverySceneOfAFolderNamedAfterIt() throws IOException {
        scene("b-lit", "ambient 1 1 1", "polygon (-50 -50 -100) (50 -50 -100) (0 50 -100)");
        scene("a-cued", "polygon (-50 -50 -100) (50 -50 -100) (0 50 -100)");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", dir.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        try (var files = Files.list(out)) {
            assertEquals(List.of("a-cued.png", "b-lit.png"), files.map(f -> f.getFileName().toString()).sorted().toList());
        }
        assertEquals(0xFFFFFF, ImageIO.read(out.resolve("b-lit.png").toFile()).getRGB(375, 375) & 0xFFFFFF,
                "the lit scene: kd (white) times ambient (white)");
    }

    /** A scene that fails is named by the picture it does not write, its error after; the others are written. */
    @Test
    void aSceneThatFailsNamesThePictureNotWritten() throws IOException {
        scene("good", "polygon (-50 -50 -100) (50 -50 -100) (0 50 -100)");
        Path bad = scene("bad", "polygon (1 2");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", dir.toString(), "--out-dir", out.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("bad.png not written: " + bad + ":1:"), run.err());
        assertTrue(Files.isRegularFile(out.resolve("good.png")));
        assertFalse(Files.exists(out.resolve("bad.png")));
    }

    @Test
    void aSceneListKeepsItsOrderAndTakesNamesWithoutSimp() throws IOException {
        scene("one", "ambient 1 1 1");
        scene("two", "line (0 0 -1) (1 1 -1)");
        Path out = dir.resolve("out");
        CliRun run = CliRun.of("render", "--scenes", dir.resolve("two").toString(), dir.resolve("one.simp").toString(),
                "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(Files.exists(out.resolve("one.png")) && Files.exists(out.resolve("two.png")));
    }

    @Test
    void depthCueColoursForALitSceneAreAUsageErrorNamingTheCommand() throws IOException {
        Path lit = scene("lit", "# a comment", "camera -1 -1 1 1 -1 -100");
        CliRun run = CliRun.of("render", "--scene", lit.toString(), "--near-color", "0,1,0", "--out",
                dir.resolve("x.png").toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().contains("lit.simp is lit (lit.simp:2 camera)"), run.err());
        CliRun compare = CliRun.of("compare", dir.resolve("x.png").toString(), "--scene", lit.toString(),
                "--far-color", "0,0,1");
        assertEquals(ExitCode.USAGE_ERROR, compare.exitCode());
        assertTrue(compare.err().contains("lit.simp:2 camera"), compare.err());
        CliRun own = CliRun.of("render", "--scene", lit.toString(), "--own-colors", "--out", dir.resolve("y.png").toString());
        assertEquals(ExitCode.USAGE_ERROR, own.exitCode());
        assertTrue(own.err().contains("--own-colors is for depth-cued scenes, and lit.simp is lit (lit.simp:2 camera)"),
                own.err());
        assertTrue(!Files.exists(dir.resolve("y.png")), "nothing written");
        CliRun scenes = CliRun.of("render", "--scenes", lit.toString(), "--own-colors", "--out-dir", dir.toString());
        assertEquals(ExitCode.USAGE_ERROR, scenes.exitCode());
        assertTrue(scenes.err().contains("--own-colors goes with --scene only"), scenes.err());
    }

    @Test
    void anErrorInAModelNamesTheLinesThatReadIt() throws IOException {
        Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 5\n");
        scene("figure", "# the model", "obj \"bad\"");
        Path page = scene("page", "ambient 1 1 1", "{", "  file \"figure\"", "}");
        CliRun run = CliRun.of("render", "--scene", page.toString(), "--out", dir.resolve("x.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().startsWith(dir.resolve("bad.obj") + ":3:7, included from figure.simp:2, included from "
                + "page.simp:3: vertex index 5 names nothing"), run.err());
        Path alone = scene("alone", "ambient 1 1 1", "obj \"bad\"");
        CliRun direct = CliRun.of("render", "--scene", alone.toString(), "--out", dir.resolve("x.png").toString());
        assertTrue(direct.err().startsWith(dir.resolve("bad.obj") + ":3:7, included from alone.simp:2: "),
                direct.err());
        assertTrue(!run.showsStackTrace() && !Files.exists(dir.resolve("x.png")), run.err());
    }

    @Test
    void aListThatNamesNoSceneIsAUsageError() {
        CliRun run = CliRun.of("render", "--scenes", dir.resolve("nothing").toString(), "--out-dir", dir.toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode());
        assertTrue(run.err().contains("no scene"), run.err());
    }
}
