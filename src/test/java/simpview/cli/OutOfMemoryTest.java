package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Java's memory running out ends a command with one line that says what ran
 * out, where, and how to give Java more; never a stack trace.
 */
class OutOfMemoryTest {

    private static final String GIVE_MORE = "MB here): give Java more, e.g. JAVA_OPTS=-Xmx2g before the simpview start"
            + " script, or java -Xmx2g -jar simpview.jar";

    @TempDir
    Path dir;

    /**
     * A model of 1,500,000 vertices (12 MB of text), whose positions alone
     * take 36 MB, in a JVM of 32 MB: the model's file and line, the scene's
     * line that read it, exit code 1.
     */
    @Test
    void aModelTooBigForTheHeapNamesItsFileAndLine() throws Exception {
        try (BufferedWriter model = Files.newBufferedWriter(dir.resolve("big.obj"), StandardCharsets.US_ASCII)) {
            for (int k = 0; k < 1_500_000; k++) {
                model.write("v 1 2 3\n");
            }
        }
        Path scene = Files.writeString(dir.resolve("big.simp"), "camera -1 -1 1 1 -1 -100\nobj \"big\"\n");
        Path printed = dir.resolve("printed.txt");
        Process render = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx32m", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "render", "--scene", scene.toString(), "--out", dir.resolve("x.png").toString()))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(printed.toFile()).start();
        boolean ended = render.waitFor(30, TimeUnit.SECONDS);
        if (!ended) {
            render.destroyForcibly();
        }
        assertTrue(ended, "render ended within 30 s");
        String text = Files.readString(printed);
        assertEquals(1, render.exitValue(), text);
        assertFalse(text.contains("\tat ") || text.contains("Exception in thread"), "no stack trace: " + text);
        assertEquals(1, text.lines().count(), "one line: " + text);
        assertTrue(text.startsWith(dir.resolve("big.obj") + ":"), text);
        assertTrue(text.contains(", included from big.simp:2: out of memory reading this model, at "), text);
        assertTrue(text.contains(" vertices and 0 faces so far (Java may use at most "), text);
        assertTrue(text.strip().endsWith(GIVE_MORE), text);
        assertFalse(Files.exists(dir.resolve("x.png")), "no picture written");
    }

    /** Anywhere else (here the window's start), the command says so in the same words, without a file. */
    @Test
    void anywhereElseTheCommandSaysSoInOneLine() {
        CliRun run = CliRun.with(() -> {
            throw new OutOfMemoryError("Java heap space");
        });
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertFalse(run.showsStackTrace(), run.err());
        assertTrue(run.err().startsWith("simpview: out of memory running this command (Java may use at most "),
                run.err());
        assertTrue(run.err().endsWith(GIVE_MORE + System.lineSeparator()), run.err());
        assertEquals(1, run.err().lines().count(), run.err());
    }
}
