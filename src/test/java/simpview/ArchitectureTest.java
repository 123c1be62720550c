package simpview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The shape docs/architecture.md describes, held against the sources: the
 * packages in pipeline order with no package importing one below it in
 * that list, no type named like a package, every thread the program
 * starts named and listed, and every type named in code by its import.
 */
class ArchitectureTest {

    private static final Path MAIN = Path.of("src/main/java");
    private static final Path DOC = Path.of("docs/architecture.md");

    /** Bottom to top: a package may import only those before it (and itself). */
    private static final List<String> LAYERS = List.of(
            "geometry", "surface", "raster", "shading", "stage",
            "scene", "scene.text", "scene.obj", "scene.simp",
            "pages", "compare", "inspect",
            "window.render", "window.instruments", "window",
            "cli");

    private static final Pattern PACKAGE = Pattern.compile("^package simpview(?:\\.([a-z.]+))?;", Pattern.MULTILINE);
    /** An import, or a type named in full in the code: simpview.pkg.Type. */
    private static final Pattern USE = Pattern.compile("\\bsimpview\\.([a-z][a-z.]*)\\.[A-Z]");

    /** A type named in full, package and all, as code: java.util.List, simpview.surface.Span. */
    private static final Pattern IN_FULL = Pattern.compile(
            "(?<![\\w.])(?:java|javax|simpview)(?:\\.[a-z][a-z0-9_]*)+\\.[A-Z]\\w*");
    /** A package or import line: the file's names start after the last. */
    private static final Pattern HEADER_LINE = Pattern.compile("^(?:package|import)\\b[^;]*;", Pattern.MULTILINE);

    record Source(Path file, String pkg, String text) {
    }

    private static List<Source> sources() throws IOException {
        return sources(MAIN);
    }

    /** The Java files below root, each with its package below simpview ("" for simpview itself). */
    private static List<Source> sources(Path root) throws IOException {
        List<Source> all = new ArrayList<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                String text = Files.readString(file);
                Matcher m = PACKAGE.matcher(text);
                assertTrue(m.find(), file + " has a package");
                all.add(new Source(file, m.group(1) == null ? "" : m.group(1), text));
            }
        }
        return all;
    }

    @Test
    void everyPackageHasItsPlaceInThePipeline() throws IOException {
        Set<String> packages = new TreeSet<>();
        for (Source s : sources()) {
            packages.add(s.pkg());
        }
        Set<String> placed = new TreeSet<>(LAYERS);
        assertEquals(placed, packages, "every package of src/main is in LAYERS (and docs/architecture.md), and no more");
        String doc = Files.readString(DOC);
        for (String layer : LAYERS) {
            String last = layer.substring(layer.lastIndexOf('.') + 1);
            assertTrue(doc.contains("── " + last) || doc.contains("── (" + last + ")"), layer + " in the doc's tree");
        }
    }

    @Test
    void noPackageImportsOneAboveItInThePipeline() throws IOException {
        List<String> wrong = new ArrayList<>();
        for (Source s : sources()) {
            int own = LAYERS.indexOf(s.pkg());
            Matcher m = USE.matcher(s.text());
            while (m.find()) {
                String used = m.group(1);
                int at = LAYERS.indexOf(used);
                if (at > own) {
                    wrong.add(s.file().getFileName() + " (" + s.pkg() + ") uses " + used);
                }
            }
        }
        assertEquals(List.of(), wrong);
    }

    /**
     * No type of any source set (the program, its tests, benchmarks and
     * tools) is named like a package of any of them: {@code Pages} beside
     * {@code simpview.pages} would read as that package's own.
     */
    @Test
    void noTypeSharesANameWithAPackage() throws IOException {
        List<Source> all = new ArrayList<>(sources());
        for (Path root : List.of(Path.of("src/test/java"), Path.of("src/jmh/java"), Path.of("src/tools/java"))) {
            all.addAll(sources(root));
        }
        Set<String> segments = new TreeSet<>();
        for (Source s : all) {
            segments.addAll(List.of(s.pkg().split("\\.")));
        }
        List<String> clashes = new ArrayList<>();
        Pattern type = Pattern.compile("\\b(?:class|interface|record|enum)\\s+([A-Z]\\w*)");
        for (Source s : all) {
            Matcher m = type.matcher(s.text());
            while (m.find()) {
                if (segments.contains(m.group(1).toLowerCase(Locale.ROOT))) {
                    clashes.add(s.pkg() + "." + m.group(1));
                }
            }
        }
        assertEquals(List.of(), clashes);
    }

    /**
     * Every jqwik property names its own seed, so that a run's random inputs
     * are the same on every machine and every run: a property that finds a
     * case only now and then would turn CI red at random.
     */
    @Test
    void everyPropertyNamesItsSeed() throws IOException {
        List<String> unseeded = new ArrayList<>();
        // Spelt in two parts, so that this line is not one of the annotations it looks for.
        Pattern property = Pattern.compile("@" + "Property(\\([^)]*\\))?");
        try (Stream<Path> files = Files.walk(Path.of("src/test/java"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                Matcher m = property.matcher(Files.readString(file));
                while (m.find()) {
                    if (m.group(1) == null || !m.group(1).contains("seed")) {
                        unseeded.add(file.getFileName() + ": " + m.group());
                    }
                }
            }
        }
        assertEquals(List.of(), unseeded, "properties without a seed");
    }

    /**
     * Test classes run two at a time (junit-platform.properties): one of
     * simpview.window that opens windows (a driver, a robot, a frame) must run
     * alone.
     */
    @Test
    void everyWindowTestRunsAlone() throws IOException {
        List<String> shared = new ArrayList<>();
        try (Stream<Path> files = Files.list(Path.of("src/test/java/simpview/window"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                String text = Files.readString(file);
                boolean tests = (text.contains("@Test") || text.contains("@ParameterizedTest"))
                        && (text.contains("WindowDriver") || text.contains("Robot") || text.contains("JFrame")
                        || text.contains("SimpviewWindow") || text.contains("xprop"));
                boolean alone = text.contains("@Isolated") || text.contains("extends WindowTestCase");
                if (tests && !alone) {
                    shared.add(file.getFileName().toString());
                }
            }
        }
        assertEquals(List.of(), shared, "window test classes without @Isolated (or WindowTestCase)");
    }

    /**
     * A window test that times what it tests (how long the event thread stalls, how soon a save is redrawn)
     * is tagged {@code timed}: the build's test launcher runs those after all others, with the machine to
     * themselves, rather than beside the tests that share it (docs/building.md).
     */
    @Test
    void everyWindowTestThatTimesIsTaggedTimed() throws IOException {
        List<String> untagged = new ArrayList<>();
        try (Stream<Path> files = Files.walk(Path.of("src/test/java/simpview/window"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                String text = Files.readString(file);
                boolean times = text.contains("@Test") && (text.contains("EdtProbe.start()")
                        || text.contains("System.nanoTime() -"));
                if (times && !text.contains("@Tag(\"timed\")")) {
                    untagged.add(file.getFileName().toString());
                }
            }
        }
        assertEquals(List.of(), untagged, "window tests that time what they test, not tagged timed");
    }

    @Test
    void everyThreadIsNamedAndListed() throws IOException {
        String doc = Files.readString(DOC);
        Pattern start = Pattern.compile("new Thread\\(([^;]*)\\);", Pattern.DOTALL);
        Pattern name = Pattern.compile("\"([^\"]+)\"");
        int threads = 0;
        for (Source s : sources()) {
            Matcher m = start.matcher(s.text());
            while (m.find()) {
                threads++;
                Matcher n = name.matcher(m.group(1));
                assertTrue(n.find(), s.file().getFileName() + " starts a thread without a name: " + m.group());
                String prefix = n.group(1).strip();
                assertTrue(doc.contains("`" + prefix), "thread '" + prefix + "' of " + s.file().getFileName()
                        + " is listed in docs/architecture.md");
            }
        }
        assertTrue(threads >= 4, "found the threads: " + threads);
    }

    /**
     * The other ways to get a thread: an executor must make its threads with
     * a factory of its own (whose {@code new Thread} is named and listed,
     * above); a timer's thread is listed by the class that starts it; and the
     * ways that borrow an unnamed, process-wide pool are not used at all.
     */
    @Test
    void everyOtherWayToAThreadIsNamedAndListed() throws IOException {
        String doc = Files.readString(DOC);
        Pattern executor = Pattern.compile("Executors\\.new\\w+\\(");
        Pattern utilTimer = Pattern.compile("new (java\\.util\\.)?Timer\\(\\s*\"([^\"]+)\"");
        List<String> pooled = List.of("parallelStream(", ".parallel()", "ForkJoinPool", "supplyAsync(", "runAsync(",
                "defaultThreadFactory(", "newWorkStealingPool(", "SwingWorker", "Thread.ofVirtual(");
        List<String> wrong = new ArrayList<>();
        for (Source s : sources()) {
            String text = s.text();
            String file = s.file().getFileName().toString();
            String className = file.substring(0, file.length() - ".java".length());
            Matcher m = executor.matcher(text);
            while (m.find()) {
                // the factory's new Thread(task, "simpview-...") follows within the call
                String call = text.substring(m.end(), Math.min(text.length(), m.end() + 300));
                if (!call.contains("new Thread(")) {
                    wrong.add(file + " makes an executor whose threads have no name of ours: " + m.group());
                }
            }
            for (String way : pooled) {
                if (text.contains(way)) {
                    wrong.add(file + " uses " + way + ": threads of a shared pool, named nowhere");
                }
            }
            boolean swingTimer = text.contains("import javax.swing.Timer;") || text.contains("new javax.swing.Timer(");
            if (swingTimer && !(doc.contains("`javax.swing.Timer`") && doc.contains("`" + className + "`"))) {
                wrong.add(file + " ticks on a javax.swing.Timer, and docs/architecture.md's thread table does not "
                        + "name it and " + className);
            }
            boolean utilTimers = text.contains("import java.util.Timer;") || text.contains("new java.util.Timer(");
            if (utilTimers) {
                Matcher named = utilTimer.matcher(text);
                if (!named.find() || !doc.contains("`" + named.group(2))) {
                    wrong.add(file + " starts a java.util.Timer without a name listed in docs/architecture.md");
                }
            }
        }
        assertEquals(List.of(), wrong);
    }

    @Test
    void codeNamesTypesByTheirImports() throws IOException {
        List<String> wrong = new ArrayList<>();
        for (String root : List.of("src/main/java", "src/test/java", "src/jmh/java", "src/tools/java")) {
            for (Source s : sources(Path.of(root))) {
                String code = codeOnly(s.text());
                Matcher header = HEADER_LINE.matcher(code);
                int body = 0;
                while (header.find()) {
                    body = header.end();
                }
                Matcher m = IN_FULL.matcher(code).region(body, code.length());
                while (m.find()) {
                    long line = code.substring(0, m.start()).chars().filter(c -> c == '\n').count() + 1;
                    wrong.add(s.file() + ":" + line + " names " + m.group() + " in full: import it");
                }
            }
        }
        assertEquals(List.of(), wrong);
    }

    /**
     * The text with every comment, string, text block and character literal
     * blanked out, line breaks kept, so that what is left is code.
     */
    static String codeOnly(String text) {
        StringBuilder out = new StringBuilder(text.length());
        int i = 0;
        int n = text.length();
        while (i < n) {
            int end;
            if (text.startsWith("//", i)) {
                end = text.indexOf('\n', i);
                end = end < 0 ? n : end;
            } else if (text.startsWith("/*", i)) {
                end = text.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
            } else if (text.startsWith("\"\"\"", i)) {
                end = text.indexOf("\"\"\"", i + 3);
                end = end < 0 ? n : end + 3;
            } else if (text.charAt(i) == '"' || text.charAt(i) == '\'') {
                char quote = text.charAt(i);
                end = i + 1;
                while (end < n && text.charAt(end) != quote) {
                    end += text.charAt(end) == '\\' ? 2 : 1;
                }
                end = Math.min(end + 1, n);
            } else {
                out.append(text.charAt(i++));
                continue;
            }
            for (int k = i; k < end; k++) {
                out.append(text.charAt(k) == '\n' ? '\n' : ' ');
            }
            i = end;
        }
        return out.toString();
    }
}
