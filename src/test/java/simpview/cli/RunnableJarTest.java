package simpview.cli;

import simpview.testing.Images;
import simpview.window.WindowClass;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneMonitor;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.nio.charset.StandardCharsets;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * build/libs/simpview.jar (the build makes it before the tests), run with
 * {@code java -jar} in an empty folder as a user runs it: it carries its
 * own scenes, --simp-dir still chooses the course's folder, and a line
 * given the way {@code gradle run -PappArgs} gives it keeps quoted paths
 * with spaces whole.
 */
public class RunnableJarTest {

    private static final long LIMIT_SECONDS = 60;
    private static Path jar;

    @TempDir
    Path dir;

    @BeforeAll
    static void findJar() {
        String path = System.getProperty("simpview.runnableJar");
        assertNotNull(path, "simpview.runnableJar is not set: run the tests through Gradle, which builds the jar first");
        jar = Path.of(path);
        assertTrue(Files.isRegularFile(jar), "no runnable jar at " + jar);
    }

    private record Run(int exitCode, String out, String err) {
    }

    private Run java(List<String> jvmOptions, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true"));
        command.addAll(jvmOptions);
        command.addAll(List.of("-jar", jar.toString()));
        command.addAll(List.of(args));
        Path out = dir.resolve("stdout.txt");
        Path err = dir.resolve("stderr.txt");
        Process process = new ProcessBuilder(command).directory(dir.toFile())
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!process.waitFor(LIMIT_SECONDS, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError(String.join(" ", command) + " did not end within " + LIMIT_SECONDS + " s");
        }
        return new Run(process.exitValue(), Files.readString(out), Files.readString(err));
    }

    @Test
    void theJarDrawsItsOwnScenePageFromAnEmptyFolder() throws Exception {
        assertFalse(Files.exists(dir.resolve("simp")));
        Path png = dir.resolve("page5.png");
        Run run = java(List.of(), "render", "--page", "5", "--out", png.toString());
        assertEquals(0, run.exitCode(), run.err());
        assertEquals("", run.err());
        Path ownScenes = Path.of(System.getProperty("simpview.projectDir", ".")).resolve("simp");
        PageContext here = new PageContext(PageContext.DEFAULT_SEED, ownScenes, ownScenes, SceneMonitor.NONE);
        assertEquals(0, Images.differingPixels(new PageRenderer().renderImage(5, here), ImageIO.read(png.toFile())));
    }

    @Test
    void helpNamesTheSceneFolderTheJarUnpacked() throws Exception {
        Run run = java(List.of(), "--help");
        assertEquals(0, run.exitCode(), run.err());
        String line = run.out().lines().filter(l -> l.startsWith("Scene folder: ")).findFirst().orElse("");
        assertTrue(line.contains("simpview-scenes"), "the unpacked folder, not ./simp: " + run.out());
        assertFalse(line.contains(dir.toString()), line);
    }

    @Test
    void simpDirStillChoosesWhereTheCoursePagesAreRead() throws Exception {
        Path course = Files.createDirectory(dir.resolve("my course"));
        Run run = java(List.of(), "render", "--page", "6", "--simp-dir", course.toString(),
                "--out", dir.resolve("p6.png").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains("page6.simp was not found in " + course.toAbsolutePath()), run.err());
    }

    /** java -jar opens the X toolkit to simpview (WindowClass names its X11 windows), and only that. */
    @Test
    void theManifestOpensTheX11ToolkitForTheWindowsClassName() throws Exception {
        try (JarFile file = new JarFile(jar.toFile())) {
            Attributes main = file.getManifest().getMainAttributes();
            assertEquals("java.desktop/sun.awt.X11", main.getValue("Add-Opens"));
            assertEquals("simpview.cli.Main", main.getValue("Main-Class"));
        }
    }

    /**
     * The jar carries picocli's and Gson's classes, whose own jars carry no licence: it carries their licence's
     * text and the notice naming them at the versions the build takes, and no other library's classes (one added
     * to the build without its notice fails here).
     */
    @Test
    void theJarCarriesTheLicenceOfEachLibraryInIt() throws Exception {
        String build = Files.readString(Path.of(System.getProperty("simpview.projectDir"), "build.gradle"));
        Set<String> libraries = new TreeSet<>();
        try (JarFile file = new JarFile(jar.toFile())) {
            assertNotNull(file.getEntry("META-INF/licenses/Apache-2.0.txt"), "the Apache License's text");
            String notice = new String(file.getInputStream(file.getEntry("META-INF/licenses/THIRD-PARTY.md"))
                    .readAllBytes(), StandardCharsets.UTF_8);
            file.stream().map(JarEntry::getName).filter(name -> name.endsWith(".class") && !name.contains("/versions/"))
                    .map(name -> name.startsWith("com/google/gson/") ? "gson" : name.substring(0, name.indexOf('/') + 1))
                    .forEach(libraries::add);
            assertEquals(List.of("gson", "picocli/", "simpview/"), List.copyOf(libraries),
                    "the code the jar carries: simpview's, picocli's and Gson's alone");
            for (String[] library : new String[][] {{"picocli", "picocliVersion"}, {"Gson", "gsonVersion"}}) {
                Matcher version = Pattern.compile(library[1] + " = '([^']+)'").matcher(build);
                assertTrue(version.find(), library[1] + " in build.gradle");
                assertTrue(notice.contains("| " + library[0] + " (") && notice.contains("| " + version.group(1) + " |"),
                        library[0] + " " + version.group(1) + " named in licenses/THIRD-PARTY.md:\n" + notice);
            }
        }
    }

    @Test
    void anAppArgsLineKeepsQuotedPathsWithSpacesWhole() throws Exception {
        Path folder = Files.createDirectory(dir.resolve("two  spaces and more"));
        Path scene = Files.writeString(folder.resolve("a scene.simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path png = folder.resolve("the picture.png");
        Run run = java(List.of("-D" + Main.APP_ARGS + "=render  --scene '" + scene + "' --out \"" + png + "\""));
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(Files.size(png) > 0, "nothing written at " + png);
    }
}
