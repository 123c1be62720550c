package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.URI;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.compare.ComparisonReport;
import simpview.compare.PngFiles;
import simpview.scene.SceneException;
import simpview.testing.Images;

/**
 * README.md's "Using simpview from Java", kept true: its ```java blocks (the
 * imports, then one static method each) are compiled as one class against
 * build/libs/simpview.jar, as the README tells a user to, and each method
 * is run and held to the command it says it does as: the same pixels, the
 * same verdict, the same text.
 */
public class ReadmeJavaExamplesTest {

    private static final String SECTION = "## Using simpview from Java";
    private static final Pattern JAVA_BLOCK = Pattern.compile("(?m)^```java\\n(.*?)^```$", Pattern.DOTALL);
    private static final String CLASS_NAME = "ReadmeExamples";
    /** A user's program around pageFromTheJar: java -cp simpview.jar:. DrawFromTheJar page4.png page5.png. */
    private static final String LAUNCHER = "DrawFromTheJar";
    private static final String LAUNCHER_SOURCE = "import java.io.File;\n"
            + "import javax.imageio.ImageIO;\n"
            + "final class " + LAUNCHER + " {\n"
            + "    public static void main(String[] args) throws Exception {\n"
            + "        ImageIO.write(" + CLASS_NAME + ".pageFromTheJar(4), \"png\", new File(args[0]));\n"
            + "        ImageIO.write(" + CLASS_NAME + ".pageFromTheJar(5), \"png\", new File(args[1]));\n"
            + "    }\n"
            + "}\n";

    private static Path project;
    private static String section;
    /** The examples' first block: their imports. */
    private static String imports;
    private static Class<?> examples;
    /** build/libs/simpview.jar, which the examples are compiled against. */
    private static String jar;

    @TempDir
    static Path compiled;

    @TempDir
    Path dir;

    @BeforeAll
    static void compileTheExamples() throws Exception {
        project = Path.of(System.getProperty("simpview.projectDir", "."));
        String readme = Files.readString(project.resolve("README.md"));
        int start = readme.indexOf("\n" + SECTION + "\n");
        assertTrue(start >= 0, "README.md has the section " + SECTION);
        int end = readme.indexOf("\n## ", start + 1);
        section = readme.substring(start, end < 0 ? readme.length() : end);
        List<String> blocks = new ArrayList<>();
        Matcher m = JAVA_BLOCK.matcher(section);
        while (m.find()) {
            blocks.add(m.group(1));
        }
        assertEquals(6, blocks.size(), "the imports and five examples: " + blocks);
        imports = blocks.get(0);
        String source = imports + "\nfinal class " + CLASS_NAME + " {\n\n"
                + String.join("\n", blocks.subList(1, blocks.size())) + "}\n";
        jar = System.getProperty("simpview.runnableJar");
        assertNotNull(jar, "simpview.runnableJar is not set: run the tests through Gradle, which builds the jar first");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertNotNull(javac, "this Java has no compiler: the tests run on a JDK");
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        JavaFileObject file = new SimpleJavaFileObject(URI.create("string:///" + CLASS_NAME + ".java"),
                JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return source;
            }
        };
        JavaFileObject launcher = new SimpleJavaFileObject(URI.create("string:///" + LAUNCHER + ".java"),
                JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return LAUNCHER_SOURCE;
            }
        };
        List<String> options = List.of("-classpath", jar, "-d", compiled.toString(), "--release", "17",
                "-Xlint:all", "-proc:none");
        boolean compiledWell = javac.getTask(null, null, diagnostics, options, null, List.of(file, launcher)).call();
        List<String> said = new ArrayList<>();
        for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
            said.add(d.getKind() + " at line " + d.getLineNumber() + ": " + d.getMessage(Locale.ROOT));
        }
        if (!compiledWell || !said.isEmpty()) {
            fail("README.md's Java examples do not compile cleanly against " + jar + ":\n"
                    + String.join("\n", said) + "\n\n" + source);
        }
        URLClassLoader loader = new URLClassLoader(new URL[] {compiled.toUri().toURL()},
                ReadmeJavaExamplesTest.class.getClassLoader());
        examples = loader.loadClass(CLASS_NAME);
    }

    /** Runs the README's method {@code name}; what it throws is thrown on as it is. */
    private static Object call(String name, Object... args) throws Exception {
        for (Method method : examples.getDeclaredMethods()) {
            if (method.getName().equals(name)) {
                method.setAccessible(true);
                try {
                    return method.invoke(null, args);
                } catch (InvocationTargetException e) {
                    if (e.getCause() instanceof Exception thrown) {
                        throw thrown;
                    }
                    throw e;
                }
            }
        }
        throw new AssertionError("README.md's Java examples have no method " + name);
    }

    private static Path own(String name) {
        return project.resolve("simp").resolve(name);
    }

    private static BufferedImage read(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        assertNotNull(image, "no picture in " + png);
        return image;
    }

    @Test
    void renderSceneDrawsLitAndDepthCuedScenesAsRenderSceneDoes() throws Exception {
        Path lit = dir.resolve("lit-shading.png");
        call("renderScene", own("lit-shading.simp"), lit, 2);
        BufferedImage golden = read(project.resolve("src/test/resources/golden/own-lit-shading.png"));
        assertEquals(0, Images.differingPixels(golden, read(lit)));

        Path cued = dir.resolve("cube.png");
        call("renderScene", own("cube.simp"), cued, 3);
        Path byCommand = dir.resolve("cube-by-render.png");
        CliRun run = CliRun.of("render", "--scene", own("cube.simp").toString(), "--threads", "1",
                "--out", byCommand.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertEquals(0, Images.differingPixels(read(byCommand), read(cued)));
    }

    @Test
    void renderSceneThrowsTheSceneErrorAtItsPlaceAndWritesNothing() throws Exception {
        Path scene = Files.writeString(dir.resolve("broken.simp"), "polygon (0, 0, -1) (1, 0, -1) (1, 1)\n");
        Path png = dir.resolve("broken.png");
        try {
            call("renderScene", scene, png, 2);
            fail("a broken scene drew");
        } catch (SceneException e) {
            assertEquals(1, e.line());
            assertTrue(e.getMessage().startsWith(scene + ":1:" + e.column() + ": "), e.getMessage());
            assertEquals(CliRun.of("render", "--scene", scene.toString(), "--out", png.toString()).err().strip(),
                    e.getMessage().strip());
        }
        assertFalse(Files.exists(png));
    }

    @Test
    void pageIsThePageRenderPageWrites() throws Exception {
        for (int n : new int[] {2, 4}) {
            BufferedImage page = (BufferedImage) call("page", n, project.resolve("simp"));
            Path byCommand = dir.resolve("page" + n + ".png");
            CliRun run = CliRun.withOwnScenes(project.resolve("simp"), "render", "--page", String.valueOf(n),
                    "--out", byCommand.toString());
            assertEquals(ExitCode.OK, run.exitCode(), run.err());
            assertEquals(0, Images.differingPixels(read(byCommand), page), "page " + n);
        }
    }

    /**
     * pageFromTheJar run as a user's program runs it, {@code java -cp simpview.jar:.}, simpview.jar the only
     * simpview on the classpath (the other tests call the examples with the tests' own simpview, its classes in
     * a folder): pages 4 and 5 drawn from the jar's scenes, no folder named, are those drawn from simp/, and once
     * the program ends nothing of the unpacking is left in its temporary folder.
     */
    @Test
    void pageFromTheJarDrawsPagesFourAndFiveWithNoFolderNamedAndLeavesNothing() throws Exception {
        Path temporary = Files.createDirectory(dir.resolve("tmp"));
        Path page4 = dir.resolve("page4.png");
        Path page5 = dir.resolve("page5.png");
        List<String> command = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-Djava.io.tmpdir=" + temporary,
                "-cp", jar + File.pathSeparator + compiled, LAUNCHER, page4.toString(), page5.toString());
        Path err = dir.resolve("stderr.txt");
        Process process = new ProcessBuilder(command).directory(dir.toFile())
                .redirectOutput(dir.resolve("stdout.txt").toFile()).redirectError(err.toFile()).start();
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            fail(String.join(" ", command) + " did not end within 60 s");
        }
        assertEquals(0, process.exitValue(), Files.readString(err));
        assertEquals(0, Images.differingPixels((BufferedImage) call("page", 4, project.resolve("simp")), read(page4)));
        assertEquals(0, Images.differingPixels((BufferedImage) call("page", 5, project.resolve("simp")), read(page5)));
        try (Stream<Path> left = Files.list(temporary)) {
            assertEquals(List.of(), left.toList(), "left in the temporary folder");
        }
    }

    @Test
    void compareWithPageGivesCompareVerdictAndReport() throws Exception {
        BufferedImage page = (BufferedImage) call("page", 2, project.resolve("simp"));
        Path right = dir.resolve("right.png");
        PngFiles.write(page, right);
        ComparisonReport passing = (ComparisonReport) call("compareWithPage", right, 2, project.resolve("simp"));
        assertTrue(passing.passes(), passing.text());
        assertEquals(1.0, passing.verdictShare());

        for (int y = 300; y < 400; y++) {
            for (int x = 300; x < 380; x++) {
                page.setRGB(x, y, 0xFF00FF);
            }
        }
        Path wrong = dir.resolve("wrong.png");
        PngFiles.write(page, wrong);
        ComparisonReport report = (ComparisonReport) call("compareWithPage", wrong, 2, project.resolve("simp"));
        assertFalse(report.passes(), report.text());
        CliRun run = CliRun.withOwnScenes(project.resolve("simp"), "compare", wrong.toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        // the same report, but for the words naming simpview's page on its first line
        assertEquals(wrong + " against simpview's page 2", report.text().lines().findFirst().orElseThrow());
        assertEquals(withoutFirstLine(run.out()), withoutFirstLine(report.text()));
    }

    private static String withoutFirstLine(String text) {
        return text.substring(text.indexOf('\n') + 1);
    }

    @Test
    void whyThisColourIsWhatInspectPrintsAndTheReadmeQuotes() throws Exception {
        Path scene = own("lit-shading.simp");
        String report = (String) call("whyThisColour", scene, 510, 409);
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "510,409", "--history", "--explain");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertEquals(run.out(), report);
        String first = report.lines().findFirst().orElseThrow();
        assertTrue(section.replace("\n", " ").contains("`" + first + "`"), "the README quotes " + first);
        assertTrue(report.contains("shading: phong"), report);
        assertTrue(section.contains("`whyThisColour(Path.of(\"simp/lit-shading.simp\"), 510, 409)`"), section);
    }

    /**
     * The API pages lead a newcomer to what the examples use: each simpview
     * type they import has its own comment, its package a package comment,
     * and the command line's package comment, the map from each command to
     * the types that do its work, names it.
     */
    @Test
    void everyTypeTheExamplesImportIsDocumentedAndOnTheCommandLinesMap() throws IOException {
        Path main = project.resolve("src/main/java");
        String map = Files.readString(main.resolve("simpview/cli/package-info.java"));
        Matcher m = Pattern.compile("(?m)^import (simpview(?:\\.[a-z]+)+)\\.([A-Z]\\w*);$").matcher(imports);
        List<String> undocumented = new ArrayList<>();
        int types = 0;
        while (m.find()) {
            types++;
            String name = m.group(1) + "." + m.group(2);
            Path folder = main.resolve(m.group(1).replace('.', '/'));
            Pattern commented = Pattern.compile("\\*/\\s*public (?:final |abstract )?(?:class|record|interface|enum) "
                    + m.group(2) + "\\b");
            if (!commented.matcher(Files.readString(folder.resolve(m.group(2) + ".java"))).find()) {
                undocumented.add(name + " has no class comment");
            }
            if (!Files.isRegularFile(folder.resolve("package-info.java"))) {
                undocumented.add(m.group(1) + " has no package comment");
            }
            if (!map.contains("{@link " + name)) {
                undocumented.add(name + " is not named in simpview/cli/package-info.java");
            }
        }
        assertTrue(types >= 10, "the examples import simpview's types: " + imports);
        assertEquals(List.of(), undocumented);
    }

    /**
     * Beyond the types the examples import, those the section's calls lead to: the canvas
     * {@code renderScene} returns ({@code image()}, {@code snapshot()}), and the command line run in-process.
     */
    private static final List<String> ALSO_REACHED = List.of("simpview.surface.PageCanvas", "simpview.cli.Main");

    /**
     * Every public member of those types (constructor, method, constant, nested type) has a comment of its
     * own, so the API pages say what each takes and gives, not only its signature: javadoc's doclint runs
     * without "missing" for the rest of the code.
     */
    @Test
    void everyPublicMemberOfTheTypesTheExamplesUseHasAComment() throws IOException {
        Path main = project.resolve("src/main/java");
        List<String> types = new ArrayList<>(ALSO_REACHED);
        Matcher m = Pattern.compile("(?m)^import (simpview(?:\\.[a-z]+)+\\.[A-Z]\\w*);$").matcher(imports);
        while (m.find()) {
            types.add(m.group(1));
        }
        Pattern member = Pattern.compile("^    public .*");
        List<String> uncommented = new ArrayList<>();
        for (String type : types) {
            List<String> lines = Files.readAllLines(main.resolve(type.replace('.', '/') + ".java"));
            for (int i = 0; i < lines.size(); i++) {
                if (!member.matcher(lines.get(i)).matches()) {
                    continue;
                }
                int before = i - 1;
                while (before >= 0 && lines.get(before).strip().startsWith("@")) {
                    before--; // an annotation stands between a member and its comment
                }
                if (before < 0 || !lines.get(before).strip().endsWith("*/")) {
                    uncommented.add(type + ":" + (i + 1) + ": " + lines.get(i).strip());
                }
            }
        }
        assertEquals(List.of(), uncommented);
    }
}
