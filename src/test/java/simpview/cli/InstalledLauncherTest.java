package simpview.cli;

import simpview.testing.Images;
import simpview.window.WindowClass;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.function.Consumer;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneMonitor;
import java.io.File;

/**
 * The start script of an installed simpview ({@code gradle installDist},
 * which the build runs before the tests), run in a folder of its own as a
 * user runs it: it prints only what simpview prints, and the installed copy
 * finds its own scenes. On Windows the same runs go through {@code simpview.bat}
 * (by {@code cmd /c}), and of the Unix script only its text is read there.
 */
public class InstalledLauncherTest {

    private static final long LIMIT_SECONDS = 60;
    private static final boolean WINDOWS = System.getProperty("os.name", "").startsWith("Windows");
    private static Path launcher;

    @TempDir
    Path dir;

    @BeforeAll
    static void findLauncher() {
        String home = System.getProperty("simpview.installDir");
        assertNotNull(home, "simpview.installDir is not set: run the tests through Gradle, which installs simpview first");
        launcher = Path.of(home, "bin", WINDOWS ? "simpview.bat" : "simpview");
        assertTrue(Files.isRegularFile(launcher) && (WINDOWS || Files.isExecutable(launcher)),
                "no start script at " + launcher);
    }

    private record Run(int exitCode, String out, String err) {
    }

    private Run run(String... args) throws IOException, InterruptedException {
        return run(environment -> { }, args);
    }

    /** The start script with {@code args}, its environment changed first by {@code change}. */
    private Run run(Consumer<Map<String, String>> change, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(WINDOWS ? List.of("cmd", "/c", launcher.toString())
                : List.of(launcher.toString()));
        command.addAll(List.of(args));
        Path out = dir.resolve("stdout.txt");
        Path err = dir.resolve("stderr.txt");
        ProcessBuilder builder = new ProcessBuilder(command).directory(dir.toFile());
        change.accept(builder.environment());
        Process process = builder.redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!process.waitFor(LIMIT_SECONDS, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError(String.join(" ", command) + " did not end within " + LIMIT_SECONDS + " s");
        }
        return new Run(process.exitValue(), Files.readString(out), Files.readString(err));
    }

    @Test
    void versionIsAllItPrints() throws Exception {
        Run run = run("--version");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().startsWith("simpview "), run.out());
        assertEquals("", run.err(), "the launcher printed on stderr");
    }

    @Test
    void theInstalledCopyDrawsItsOwnScenePage() throws Exception {
        Path png = dir.resolve("page4.png");
        Run run = run("render", "--page", "4", "--out", png.toString());
        assertEquals(0, run.exitCode(), run.err());
        assertEquals("", run.err(), "the launcher printed on stderr");
        // The same scene file, read here from the source tree and there from the installation.
        Path ownScenes = Path.of(System.getProperty("simpview.projectDir", ".")).resolve("simp");
        PageContext here = new PageContext(PageContext.DEFAULT_SEED, ownScenes, ownScenes, SceneMonitor.NONE);
        assertEquals(0, Images.differingPixels(new PageRenderer().renderImage(4, here), ImageIO.read(png.toFile())));
    }

    /** The installed copy carries picocli's and Gson's licence beside the jars that hold them (licenses/THIRD-PARTY.md). */
    @Test
    void theInstalledCopyCarriesItsLibrariesLicence() throws IOException {
        Path home = Path.of(System.getProperty("simpview.installDir"));
        assertTrue(Files.readString(home.resolve("licenses/Apache-2.0.txt")).contains("Version 2.0, January 2004"));
        String notice = Files.readString(home.resolve("licenses/THIRD-PARTY.md"));
        try (Stream<Path> jars = Files.list(home.resolve("lib"))) {
            for (String jar : jars.map(p -> p.getFileName().toString()).filter(name -> !name.startsWith("simpview"))
                    .toList()) {
                String library = jar.substring(0, jar.lastIndexOf('-'));
                String version = jar.substring(jar.lastIndexOf('-') + 1, jar.length() - ".jar".length());
                assertTrue(notice.contains(":" + library + "`) | " + version + " |"), jar + " named in the notice");
            }
        }
    }

    /**
     * The Unix script opens the X toolkit to simpview (WindowClass names its
     * X11 windows), except on macOS, which runs the same script and whose
     * JVM would warn about the missing package: checked by running it with a
     * stand-in {@code java} that prints its arguments, and a stand-in
     * {@code uname} for Linux and one for macOS (so the test says the same on
     * a Mac). The Windows script never opens it; on Windows, where no shell
     * runs the Unix script, only that is checked.
     */
    @Test
    void theUnixScriptOpensTheX11ToolkitExceptOnMacOs() throws Exception {
        if (!WINDOWS) {
            String opens = "--add-opens=java.desktop/sun.awt.X11=ALL-UNNAMED";
            Path javaHome = Files.createDirectories(dir.resolve("jdk/bin"));
            stand(javaHome.resolve("java"), "for a in \"$@\"; do echo \"$a\"; done");
            Path linux = Files.createDirectories(dir.resolve("linux"));
            stand(linux.resolve("uname"), "echo Linux");
            Path mac = Files.createDirectories(dir.resolve("mac"));
            stand(mac.resolve("uname"), "echo Darwin");
            List<String> onLinux = arguments(javaHome.getParent(), linux);
            List<String> onMac = arguments(javaHome.getParent(), mac);
            assertTrue(onLinux.contains(opens), "the script run as on Linux passes " + onLinux);
            assertTrue(onLinux.contains("-Dsimpview.simpDir=" + launcher.getParent().getParent().resolve("simp")),
                    onLinux.toString());
            assertFalse(onMac.contains(opens), "the script run as on macOS passes " + onMac);
            assertTrue(onMac.stream().anyMatch(a -> a.startsWith("-Dsimpview.simpDir=")), onMac.toString());
        }
        String windows = Files.readString(launcher.resolveSibling("simpview.bat"));
        assertTrue(windows.lines().anyMatch(l -> l.startsWith("set DEFAULT_JVM_OPTS=\"-Dsimpview.simpDir=")),
                "the Windows script keeps its other option");
        assertFalse(windows.contains("sun.awt.X11"), "the Windows script opens the X toolkit");
    }

    /** A shell script at {@code file} that runs {@code body}. */
    private static void stand(Path file, String body) throws IOException {
        Files.writeString(file, "#!/bin/sh\n" + body + "\n");
        assertTrue(file.toFile().setExecutable(true));
    }

    /** What the start script hands the java of {@code javaHome}, with {@code pathFirst} before PATH. */
    private List<String> arguments(Path javaHome, Path pathFirst) throws IOException, InterruptedException {
        Run run = run(environment -> {
            environment.put("JAVA_HOME", javaHome.toString());
            environment.remove("JAVA_OPTS");
            environment.remove("SIMPVIEW_OPTS");
            environment.put("PATH", pathFirst + File.pathSeparator + System.getenv("PATH"));
        }, "--version");
        assertEquals("", run.err(), "the start script printed on stderr");
        return run.out().lines().toList();
    }

    @Test
    void aSceneErrorIsItsMessageAlone() throws Exception {
        Path bad = Files.writeString(dir.resolve("bad.simp"), "rotate W 5\n");
        Run run = run("render", "--scene", bad.toString(), "--out", dir.resolve("bad.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertEquals(List.of(bad + ":1:8: expected an axis X, Y or Z (upper case), found 'W'", "    rotate W 5", "           ^"),
                run.err().lines().toList());
        assertEquals("", run.out());
    }
}
