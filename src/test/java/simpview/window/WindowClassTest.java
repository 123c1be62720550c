package simpview.window;

import org.junit.jupiter.api.parallel.Isolated;

import simpview.cli.Main;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.Toolkit;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Under Xvfb: the X server's WM_CLASS of simpview's window, read with xprop
 * as a dock reads it, is "simpview" when it is started as users start it
 * (the start script, java -jar), and without the X toolkit's opening the
 * window still opens, silently, under the JDK's own name.
 */
@Isolated
public class WindowClassTest {

    private static final long WINDOW_WAIT_MS = 30_000;

    @TempDir
    Path dir;

    @BeforeEach
    void needsAnX11Display() {
        Displays.assumeUsable();
        String toolkit = Toolkit.getDefaultToolkit().getClass().getName();
        assumeTrue(toolkit.equals(WindowClass.X_TOOLKIT), "not X11 (the toolkit is " + toolkit
                + "): WM_CLASS is an X11 property");
        for (String tool : List.of("xprop", "xwininfo")) {
            if (!onPath(tool)) {
                fail(tool + " is missing: install Debian's x11-utils (apt-get install x11-utils, or run .ci/setup)");
            }
        }
    }

    private static boolean onPath(String tool) {
        for (String folder : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (!folder.isEmpty() && Files.isExecutable(Path.of(folder, tool))) {
                return true;
            }
        }
        return false;
    }

    /** A scene whose name no other window's title holds, so its window can be told from the rest. */
    private Path probeScene() throws IOException {
        String name = "wmclass-probe-" + ProcessHandle.current().pid() + "-" + System.nanoTime() + ".simp";
        return Files.writeString(dir.resolve(name), "polygon (-50, -50, -150) (50, -50, -150) (0, 50, -150)\n");
    }

    private static String java() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    @Test
    void theStartScriptsWindowIsClassedSimpview() throws Exception {
        Path launcher = Path.of(System.getProperty("simpview.installDir", "build/install/simpview"), "bin", "simpview");
        assertTrue(Files.isExecutable(launcher), "no start script at " + launcher);
        Path scene = probeScene();
        assertSimpview(windowClassOf(List.of(launcher.toString(), scene.toString()), scene));
    }

    @Test
    void theRunnableJarsWindowIsClassedSimpview() throws Exception {
        Path jar = Path.of(System.getProperty("simpview.runnableJar", "build/libs/simpview.jar"));
        assertTrue(Files.isRegularFile(jar), "no runnable jar at " + jar);
        Path scene = probeScene();
        assertSimpview(windowClassOf(List.of(java(), "-jar", jar.toString(), scene.toString()), scene));
    }

    @Test
    void withoutTheOpeningTheWindowOpensSilentlyUnderTheJdksName() throws Exception {
        Path jar = Path.of(System.getProperty("simpview.runnableJar", "build/libs/simpview.jar"));
        Path scene = probeScene();
        Path err = dir.resolve("stderr.txt");
        String wmClass = windowClassOf(List.of(java(), "-cp", jar.toString(), "simpview.cli.Main", scene.toString()),
                scene, err);
        assertTrue(wmClass.contains("\"simpview-cli-Main\""), wmClass);
        assertEquals("", Files.readString(err), "nothing on stderr, never a stack trace");
    }

    @Test
    void inThisJvmAFrameMadeAfterApplyIsClassedSimpview() throws Exception {
        assertTrue(WindowClass.apply(), "the test JVM is given --add-opens java.desktop/sun.awt.X11 by the build");
        String title = "wmclass-probe-frame-" + System.nanoTime();
        AtomicReference<JFrame> frame = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            frame.set(new JFrame(title));
            frame.get().setSize(200, 100);
            frame.get().setVisible(true);
        });
        try {
            assertSimpview(xprop(awaitWindow(title, null)));
        } finally {
            SwingUtilities.invokeAndWait(() -> frame.get().dispose());
        }
    }

    private static void assertSimpview(String wmClass) {
        assertTrue(wmClass.startsWith("WM_CLASS(STRING) = "), wmClass);
        assertTrue(wmClass.contains("\"simpview\""), wmClass);
        assertFalse(wmClass.contains("Main"), wmClass);
    }

    private String windowClassOf(List<String> command, Path scene) throws Exception {
        return windowClassOf(command, scene, dir.resolve("stderr.txt"));
    }

    /** Starts {@code command}, waits for its window on the scene, reads its WM_CLASS, ends the program. */
    private String windowClassOf(List<String> command, Path scene, Path err) throws Exception {
        Process program = new ProcessBuilder(command).directory(dir.toFile())
                .redirectOutput(dir.resolve("stdout.txt").toFile()).redirectError(err.toFile()).start();
        try {
            return xprop(awaitWindow(scene.getFileName().toString(), program));
        } finally {
            program.destroy();
            if (!program.waitFor(10, TimeUnit.SECONDS)) {
                program.destroyForcibly();
            }
        }
    }

    /** The id of the top-level window whose title holds {@code name}, once the X server has it. */
    private String awaitWindow(String name, Process program) throws Exception {
        Pattern line = Pattern.compile("(?m)^\\s*(0x[0-9a-fA-F]+) \"[^\"\\n]*" + Pattern.quote(name));
        long deadline = System.currentTimeMillis() + WINDOW_WAIT_MS;
        String lastTree = "";
        while (System.currentTimeMillis() < deadline) {
            ToolRun tree = run("xwininfo", "-root", "-tree");
            lastTree = tree.out();
            Matcher m = line.matcher(tree.out());
            if (tree.exit() == 0 && m.find()) {
                return m.group(1);
            }
            // A window that closes while xwininfo walks the tree (a starting JVM opens and
            // closes a few of its own) makes it fail with "Bad Window": the tree changed
            // under it, so it is asked again; any other failure is the test's failure.
            if (tree.exit() != 0 && !tree.out().contains("Can't query window tree")) {
                fail("xwininfo -root -tree: " + tree.out());
            }
            if (program != null && !program.isAlive()) {
                fail("the program ended (exit " + program.exitValue() + ") before its window showed: "
                        + Files.readString(dir.resolve("stderr.txt")));
            }
            Thread.sleep(100);
        }
        throw new AssertionError("no window titled with " + name + " within " + WINDOW_WAIT_MS + " ms; the last tree: "
                + lastTree);
    }

    private String xprop(String windowId) throws Exception {
        return tool("xprop", "-id", windowId, "WM_CLASS").trim();
    }

    /** What an X tool prints; it must succeed. */
    private static String tool(String... command) throws Exception {
        ToolRun run = run(command);
        assertEquals(0, run.exit(), String.join(" ", command) + ": " + run.out());
        return run.out();
    }

    private record ToolRun(int exit, String out) { }

    /** Runs an X tool to its end: its exit code and what it printed on both streams. */
    private static ToolRun run(String... command) throws Exception {
        Process p = new ProcessBuilder(new ArrayList<>(List.of(command))).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(20, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            fail(String.join(" ", command) + " did not end");
        }
        return new ToolRun(p.exitValue(), out);
    }
}
