package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A scene file that never ends and has no line end (a link to a device that
 * streams bytes for ever) gets a clear error naming it within a few
 * seconds, at a 64 MB heap, as the top file and as an included one: nothing
 * reads it before the reader, which does not read a device.
 */
class EndlessFileTest {

    private static final Path ZEROS = Path.of("/dev/zero");

    @TempDir
    Path dir;

    @Test
    void aTopFileThatNeverEndsIsAnErrorNamingIt() throws Exception {
        Path endless = link("endless.simp");
        String err = renderAt64Megabytes(endless, 1);
        assertTrue(err.contains(endless.toAbsolutePath().normalize().toString()), err);
        assertTrue(err.contains("not a regular file"), err);
    }

    @Test
    void anIncludedFileThatNeverEndsIsAnErrorAtTheIncludingLine() throws Exception {
        link("endless.simp");
        Path top = Files.writeString(dir.resolve("top.simp"), "# includes a device\nfile \"endless\"\n");
        String err = renderAt64Megabytes(top, 1);
        assertTrue(err.contains("top.simp:2:"), err);
        assertTrue(err.contains("endless.simp"), err);
        assertTrue(err.contains("not a regular file"), err);
    }

    private Path link(String name) throws Exception {
        assumeTrue(Files.exists(ZEROS) || "true".equals(System.getenv("CI")), "no /dev/zero on this system");
        return Files.createSymbolicLink(dir.resolve(name), ZEROS);
    }

    /** Runs {@code render --scene} in a JVM of 64 MB; returns what it printed once it ended with {@code code}. */
    private String renderAt64Megabytes(Path scene, int code) throws Exception {
        Path out = dir.resolve("out.txt");
        Process render = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx64m", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "render", "--scene", scene.toString(), "--out", dir.resolve("x.png").toString()))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(out.toFile()).start();
        boolean ended = render.waitFor(20, TimeUnit.SECONDS);
        if (!ended) {
            render.destroyForcibly();
        }
        assertTrue(ended, "render ended within 20 s");
        String printed = Files.readString(out);
        assertEquals(code, render.exitValue(), printed);
        assertFalse(printed.contains("\tat "), "no stack trace: " + printed);
        return printed;
    }
}
