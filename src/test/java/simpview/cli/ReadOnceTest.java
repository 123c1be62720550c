package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * One {@code render} reads each file of a scene once (issue 19): a real
 * render process runs under strace, which names every file the process
 * opens. Deciding lit or depth-cued, finding the files to watch, reading the
 * models and drawing all come from that one reading.
 */
class ReadOnceTest {

    private static final Path STRACE = Path.of("/usr/bin/strace");

    @TempDir
    Path dir;

    @Test
    void eachFileOfASceneWithIncludesAndAnObjIsOpenedOnceByOneRender() throws Exception {
        assumeTrue(Files.isExecutable(STRACE) || "true".equals(System.getenv("CI")),
                "strace is not installed (.ci/setup installs it): the opens cannot be counted");
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Path leaf = Files.writeString(scenes.resolve("leaf.simp"), "polygon (-1 -1 -3) (1 -1 -3) (0 1 -3)\n");
        Path middle = Files.writeString(scenes.resolve("middle.simp"), "{\nfile \"leaf\"\n}\nfile leaf\n");
        Path model = Files.writeString(scenes.resolve("model.obj"), "v -1 -1 -4\nv 1 -1 -4\nv 0 1 -4\nf 1 2 3\n");
        Path top = Files.writeString(scenes.resolve("top.simp"), String.join("\n",
                "camera -1 -1 1 1 -1 -100", "ambient 1 1 1", "file \"middle\"", "obj \"model\"", "obj model", ""));
        Path out = dir.resolve("top.png");
        Path log = dir.resolve("strace.log");
        // -ff: a log per thread, so that no call is split over two lines by another thread's.
        List<String> command = new ArrayList<>(List.of(STRACE.toString(), "-ff", "-qq", "-e", "trace=open,openat",
                "-o", log.toString(), javaCommand(), "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                Main.class.getName(), "render", "--scene", top.toString(), "--out", out.toString()));
        Process render = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("render.out").toFile()).start();
        assertTrue(render.waitFor(60, TimeUnit.SECONDS), "render under strace ended");
        assertEquals(0, render.exitValue(), Files.readString(dir.resolve("render.out")));
        assertTrue(Files.size(out) > 0);
        Map<Path, Integer> opens = successfulOpens(dir, log.getFileName().toString());
        for (Path file : List.of(top, middle, leaf, model)) {
            assertEquals(1, opens.getOrDefault(file.toRealPath(), 0),
                    file.getFileName() + " opened once (leaf.simp is included twice, model.obj drawn twice)");
        }
    }

    private static String javaCommand() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    /**
     * How often each path was opened successfully, from the lines
     * {@code openat(AT_FDCWD, "/p", ...) = 3} of every thread's log
     * ({@code log.PID}).
     */
    private static Map<Path, Integer> successfulOpens(Path dir, String log) throws IOException {
        Pattern open = Pattern.compile("open(?:at)?\\((?:[^,]*, )?\"([^\"]+)\".*\\) = (-?\\d+)");
        Map<Path, Integer> counts = new HashMap<>();
        List<Path> logs;
        try (var files = Files.list(dir)) {
            logs = files.filter(f -> f.getFileName().toString().startsWith(log + ".")).toList();
        }
        assertTrue(!logs.isEmpty(), "strace wrote its logs");
        for (Path threadLog : logs) {
            for (String line : Files.readAllLines(threadLog)) {
                Matcher m = open.matcher(line);
                if (m.find() && Integer.parseInt(m.group(2)) >= 0) {
                    counts.merge(Path.of(m.group(1)).normalize(), 1, Integer::sum);
                }
            }
        }
        return counts;
    }
}
