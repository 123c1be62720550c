package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.testing.GoldenCase;
import simpview.testing.Images;

/** {@code --threads N} on the commands that draw: the same picture at any N, and a clear usage error out of range. */
class ThreadsOptionTest {

    @TempDir
    Path dir;

    @Test
    void renderDrawsTheSamePictureOnOneAndOnSevenThreads() throws Exception {
        Path scene = GoldenCase.ownSimpDir().resolve("page5.simp");
        Path one = dir.resolve("one.png");
        Path seven = dir.resolve("seven.png");
        CliRun a = CliRun.of("render", "--scene", scene.toString(), "--threads", "1", "--out", one.toString());
        CliRun b = CliRun.of("render", "--scene", scene.toString(), "--threads", "7", "--out", seven.toString());
        assertEquals(ExitCode.OK, a.exitCode(), a.err());
        assertEquals(ExitCode.OK, b.exitCode(), b.err());
        assertEquals(0, Images.differingPixels(ImageIO.read(one.toFile()), ImageIO.read(seven.toFile())));
    }

    @Test
    void compareTakesThreadsToo() throws Exception {
        Path page = dir.resolve("page4.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "4", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--page", "4", "--threads", "2");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
    }

    @Test
    void aCountOutOfRangeIsAUsageError() {
        for (String n : new String[] {"0", "-3", "65"}) {
            CliRun run = CliRun.of("render", "--page", "1", "--threads", n, "--out", dir.resolve("x.png").toString());
            assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), n);
            assertTrue(run.err().contains("--threads must be 1 to 64, not " + n), run.err());
        }
    }
}
