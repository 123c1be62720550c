package simpview.robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import net.jqwik.api.Tuple;
import net.jqwik.api.lifecycle.AfterContainer;
import net.jqwik.api.lifecycle.BeforeContainer;
import net.jqwik.api.lifecycle.BeforeTry;
import net.jqwik.api.statistics.Statistics;
import simpview.scene.SceneException;

/**
 * Scene fuzzing: random token streams, mutated real scenes, webs of `file`
 * commands with cycles and missing files, well-formed scenes that must render,
 * and well-formed scenes with one bad line that must be reported at that line.
 * Whatever the input, ScenePipeline.drawDepthCued returns or throws a SceneException
 * with a sound location, within 2 seconds, without touching the margins.
 */
class SceneFuzzProperties {

    private static Path root;
    private static int tryNumber;
    /** Scenes to mutate, by name: the file's directory holds its siblings, so `file` commands in it resolve. */
    private static final Map<String, Path> BASES = new TreeMap<>();

    private final SceneHarness harness = new SceneHarness();
    private Path dir;

    // ---------------------------------------------------------------- set-up

    private static final String INLINE_UNIT = String.join("\n",
            "# a unit square in z = 0, two coloured triangles",
            "polygon (0, 0, 0) (1, 0, 0) (1, 1, 0)",
            "polygon (0,0,0)(1,0,0)(0,1,0) (1, 1, 0)(0,0,1) (0 1 0)(1 0 1)",
            "");

    private static final String INLINE_SCENE = String.join("\n",
            "# small scene written for the fuzzer",
            "{",
            "\tscale 40, 40, 40",
            "\trotate Y 30",
            "\ttranslate -0.5 -0.5 -2.5",
            "\tfile \"unit\"",
            "}",
            "wire",
            "line (-90, -90, -100) (90, 80, -150)",
            "polygon (-50, 0, -10) (50, 0, -10) (0, 60, -190)",
            "filled",
            "{",
            "  rotate Z 45",
            "  translate 10 -20 -30",
            "  polygon (0,0,0) (30,0,-5) (0,30,-10)",
            "}",
            "");

    @BeforeContainer
    static void makeScenes() throws IOException {
        root = Files.createTempDirectory("simp-fuzz");
        Path inline = root.resolve("inline");
        SceneHarness.write(inline.resolve("unit.simp"), INLINE_UNIT);
        SceneHarness.write(inline.resolve("scene.simp"), INLINE_SCENE);
        BASES.put("inline/unit", inline.resolve("unit.simp"));
        BASES.put("inline/scene", inline.resolve("scene.simp"));
        copyScenes(Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp")), "course");
        copyScenes(Path.of(System.getProperty("simpview.projectDir", ".")).resolve("simp"), "project");
    }

    private static void copyScenes(Path from, String name) throws IOException {
        if (!Files.isDirectory(from)) {
            return;
        }
        Path to = root.resolve(name);
        Files.createDirectories(to);
        try (Stream<Path> files = Files.list(from)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".simp")).sorted().collect(Collectors.toList())) {
                Files.copy(f, to.resolve(f.getFileName()));
                // Very large generated scenes would make a try slow; mutate the small and medium ones.
                if (Files.size(f) <= 16 * 1024) {
                    BASES.put(name + "/" + f.getFileName().toString().replace(".simp", ""), to.resolve(f.getFileName()));
                }
            }
        }
    }

    @AfterContainer
    static void removeScenes() {
        SceneHarness.deleteTree(root);
    }

    @BeforeTry
    void freshDirectory() {
        dir = root.resolve("try" + tryNumber++);
    }

    private void cleanUp() {
        SceneHarness.deleteTree(dir);
    }

    // ---------------------------------------------------------------- tokens

    static Arbitrary<String> numberSpelling() {
        return Arbitraries.frequencyOf(
                Tuple.of(25, Arbitraries.integers().between(-300, 300).map(String::valueOf)),
                Tuple.of(20, Arbitraries.doubles().between(-500, 500).ofScale(3).map(String::valueOf)),
                Tuple.of(30, Arbitraries.of("NaN", "-NaN", "nan", "Infinity", "-Infinity", "+Infinity", "inf",
                        "1e999", "-1e999", "1e-400", "-1e-400", "-0", "-0.0", "+0", ".5", "5.", "-.5", "-5.", "1e3",
                        "1E3", "2e+3", "1e-3", ".e1", "e5", "1e", "1e+", "--1", "+-1", "1.2.3", "0x1p3", "0x10",
                        "1_0", "1d", "1f", "4.9e-324", "1.7976931348623157e308", "1e308", "1e300", "-1e300",
                        "00012", "0.", "-", "+", ".", "..5", "1e400000000000", "1e-400000000000",
                        "123456789012345678901234567890", "0.000000000000000000000000000001", "٣", "１")),
                Tuple.of(5, Arbitraries.doubles().between(-1e300, 1e300).map(String::valueOf)));
    }

    static Arbitrary<String> wordToken() {
        return Arbitraries.of("{", "}", "{", "}", "scale", "translate", "rotate", "line", "polygon", "file", "wire",
                "filled", "Scale", "POLYGON", "rotat", "polygons", "Wire", "X", "Y", "Z", "x", "y", "z", "W", "XY",
                "#", "(", ")", "(", ")", ",", ",,", "\"unit\"", "unit", "\"scene\"", "\"mutant\"", "mutant", "\"\"",
                "\"", "\"unit", "\"../inline/unit\"", "\"/dev/null\"", "\"/\"", "\"a\u0000b\"", "\"missing\"",
                "\t", "é", "\uD835\uDF0B", "\u00A0", "\r");
    }

    static Arbitrary<String> token() {
        return Arbitraries.frequencyOf(Tuple.of(45, numberSpelling()), Tuple.of(55, wordToken()));
    }

    @Provide
    Arbitrary<List<List<String>>> tokenLines() {
        return token().list().ofMaxSize(9).list().ofMinSize(1).ofMaxSize(10);
    }

    /** Random token soup, one file, possibly including the scenes beside it. */
    @Property(tries = 2000, seed = "1969")
    void randomTokenStreamsRenderOrFailWithALocation(@ForAll("tokenLines") List<List<String>> lines,
            @ForAll boolean commas) throws Exception {
        StringBuilder text = new StringBuilder();
        for (List<String> line : lines) {
            text.append(String.join(commas ? ", " : " ", line)).append('\n');
        }
        SceneHarness.write(dir.resolve("unit.simp"), INLINE_UNIT);
        SceneHarness.write(dir.resolve("scene.simp"), INLINE_SCENE);
        Path top = SceneHarness.write(dir.resolve("mutant.simp"), text.toString());
        SceneException e = harness.run(top);
        Statistics.label("outcome").collect(e == null ? "rendered" : "error");
        cleanUp();
    }

    // ---------------------------------------------------------------- mutations

    enum Op { DELETE_TOKEN, DUPLICATE_TOKEN, SWAP_TOKENS, NUMBER, WORD, DELETE_LINE, DUPLICATE_LINE, SWAP_LINES,
        JOIN_LINES, SPLIT_LINE }

    record Mutation(Op op, int a, int b, String payload) {
    }

    @Provide
    Arbitrary<List<Mutation>> mutations() {
        Arbitrary<Integer> index = Arbitraries.integers().between(0, 100_000);
        Arbitrary<Mutation> m = Combinators.combine(Arbitraries.of(Op.class), index, index,
                Arbitraries.oneOf(numberSpelling(), wordToken())).as(Mutation::new);
        return m.list().ofMinSize(1).ofMaxSize(4);
    }

    @Provide
    Arbitrary<String> bases() {
        return Arbitraries.of(new ArrayList<>(BASES.keySet()));
    }

    private static final Pattern TOKEN = Pattern.compile("\"[^\"]*\"|[(),{}]|[^\\s(),{}]+");

    static String mutate(String text, List<Mutation> mutations) {
        List<List<String>> lines = new ArrayList<>();
        for (String line : text.split("\n", -1)) {
            List<String> tokens = new ArrayList<>();
            Matcher m = TOKEN.matcher(line);
            while (m.find()) {
                tokens.add(m.group());
            }
            lines.add(tokens);
        }
        for (Mutation mu : mutations) {
            apply(lines, mu);
        }
        return lines.stream().map(l -> String.join(" ", l)).collect(Collectors.joining("\n"));
    }

    private static void apply(List<List<String>> lines, Mutation mu) {
        int n = lines.size();
        List<String> line = lines.get(mu.a() % n);
        int t = line.isEmpty() ? 0 : mu.b() % line.size();
        switch (mu.op()) {
            case DELETE_TOKEN:
                if (!line.isEmpty()) {
                    line.remove(t);
                }
                break;
            case DUPLICATE_TOKEN:
                if (!line.isEmpty()) {
                    line.add(t, line.get(t));
                }
                break;
            case SWAP_TOKENS: {
                List<String> other = lines.get(mu.b() % n);
                if (!line.isEmpty() && !other.isEmpty()) {
                    int i = mu.a() / n % line.size();
                    int j = mu.b() / n % other.size();
                    String x = line.get(i);
                    line.set(i, other.get(j));
                    other.set(j, x);
                }
                break;
            }
            case NUMBER:
            case WORD:
                if (line.isEmpty()) {
                    line.add(mu.payload());
                } else {
                    line.set(t, mu.payload());
                }
                break;
            case DELETE_LINE:
                if (n > 1) {
                    lines.remove(mu.a() % n);
                }
                break;
            case DUPLICATE_LINE:
                lines.add(mu.a() % n, new ArrayList<>(line));
                break;
            case SWAP_LINES: {
                int j = mu.b() % n;
                lines.set(mu.a() % n, lines.get(j));
                lines.set(j, line);
                break;
            }
            case JOIN_LINES:
                if (mu.a() % n + 1 < n) {
                    line.addAll(lines.remove(mu.a() % n + 1));
                }
                break;
            default: // SPLIT_LINE
                if (!line.isEmpty()) {
                    List<String> tail = new ArrayList<>(line.subList(t, line.size()));
                    line.subList(t, line.size()).clear();
                    lines.add(mu.a() % n + 1, tail);
                }
        }
    }

    /** The project's and the course's scenes (and two small inline ones), each mutated a few times. */
    @Property(tries = 1800, seed = "4004")
    void mutatedScenesRenderOrFailWithALocation(@ForAll("bases") String base,
            @ForAll("mutations") List<Mutation> mutations) throws Exception {
        Path original = BASES.get(base);
        // The mutant sits beside the original, so its `file` commands find the same siblings.
        Path top = original.resolveSibling("mutant.simp");
        SceneHarness.write(top, mutate(Files.readString(original), mutations));
        SceneException e = harness.run(top);
        Statistics.label("base").collect(base.substring(0, base.indexOf('/')));
        Statistics.label("outcome").collect(e == null ? "rendered" : "error");
    }

    // ---------------------------------------------------------------- well-formed scenes

    /** Writes numbers as a person might: integers, decimals, leading dot, exponents, -0. */
    static String spell(double v, Random r) {
        if (v == Math.rint(v) && Math.abs(v) < 1e6) {
            long i = (long) v;
            switch (r.nextInt(4)) {
                case 0:
                    return i + ".0";
                case 1:
                    return i == 0 ? (r.nextBoolean() ? "-0" : "0") : i + "";
                default:
                    return Long.toString(i);
            }
        }
        String s = String.valueOf(v);
        if (r.nextInt(4) == 0 && s.startsWith("0.")) {
            return s.substring(1);
        }
        if (r.nextInt(4) == 0 && s.startsWith("-0.")) {
            return "-" + s.substring(2);
        }
        return s.replace("E", r.nextBoolean() ? "e" : "E");
    }

    /** Generates scenes that follow SPEC: every line valid, braces never popped when empty. */
    static final class SceneWriter {
        final Random r;
        final double magnitude;
        int depth;
        final List<String> lines = new ArrayList<>();
        /** depth before each line */
        final List<Integer> depths = new ArrayList<>();

        SceneWriter(long seed, double magnitude) {
            this.r = new Random(seed);
            this.magnitude = magnitude;
        }

        double value(double range) {
            switch (r.nextInt(6)) {
                case 0:
                    return r.nextInt(21) - 10;
                case 1:
                    return Math.round((r.nextDouble() * 2 - 1) * range * 4) / 4.0;
                default:
                    return (r.nextDouble() * 2 - 1) * range;
            }
        }

        String num(double range) {
            return spell(value(range), r);
        }

        String sep() {
            String[] s = {", ", ",", " ", " , ", ",  ", "  ", ", "};
            return s[r.nextInt(s.length)];
        }

        String triple(double range) {
            String in = r.nextInt(5) == 0 ? " " : "";
            return "(" + in + num(range) + sep() + num(range) + sep() + num(range) + in + ")";
        }

        String colour() {
            return "(" + spell(r.nextInt(11) / 10.0, r) + sep() + spell(r.nextInt(5) / 4.0, r) + sep()
                    + spell(r.nextDouble(), r) + ")";
        }

        String vertices(int n) {
            boolean coloured = r.nextInt(3) == 0;
            StringBuilder sb = new StringBuilder();
            for (int i = 0; i < n; i++) {
                sb.append(r.nextInt(4) == 0 ? "  " : " ").append(triple(magnitude));
                if (coloured) {
                    sb.append(' ').append(colour());
                }
            }
            return sb.toString();
        }

        String command() {
            switch (r.nextInt(14)) {
                case 0:
                case 1:
                    depth++;
                    return "{";
                case 2:
                case 3:
                    if (depth > 0) {
                        depth--;
                        return "}";
                    }
                    return "# nothing to pop";
                case 4:
                    return "scale " + num(Math.min(magnitude, 3)) + sep() + num(Math.min(magnitude, 3)) + sep()
                            + num(Math.min(magnitude, 3));
                case 5:
                    return "translate " + num(magnitude) + sep() + num(magnitude) + sep() + num(magnitude);
                case 6:
                    return "rotate " + "XYZ".charAt(r.nextInt(3)) + " " + num(Math.min(magnitude, 720));
                case 7:
                    return "line" + vertices(2);
                case 8:
                case 9:
                    return "polygon" + vertices(3);
                case 10:
                    return r.nextBoolean() ? "wire" : "filled";
                case 11:
                    return r.nextBoolean() ? "file \"unit\"" : "file unit";
                case 12:
                    return r.nextBoolean() ? "# a comment, (with) 1 2 3 and } {" : "";
                default:
                    return r.nextBoolean() ? "   " : "\t# indented comment";
            }
        }

        String indentation() {
            String[] s = {"", "", "\t", "  ", "\t\t"};
            return s[r.nextInt(s.length)];
        }

        String trailing() {
            String[] s = {"", "", "", " ", "\t"};
            return s[r.nextInt(s.length)];
        }


        SceneWriter write(int n) {
            for (int i = 0; i < n; i++) {
                int before = depth;
                String c = command();
                depths.add(before);
                lines.add(c.isBlank() || c.startsWith("#") ? c : indentation() + c + trailing());
            }
            return this;
        }

        String text(boolean crlf) {
            return String.join(crlf ? "\r\n" : "\n", lines) + (crlf ? "\r\n" : "\n");
        }
    }

    private static final String UNIT_COMMANDS = String.join("\n",
            "polygon (0, 0, 0) (1, 0, 0) (1, 1, 0)",
            "polygon (0, 0, 0) (1, 1, 0) (0, 1, 0)",
            "line (0, 0, 0) (1, 1, 1)",
            "");

    /** Scenes that follow SPEC to the letter render: no exception of any kind. */
    @Property(tries = 1000, seed = "2001")
    void wellFormedScenesRender(@ForAll long seed, @ForAll boolean crlf) throws Exception {
        SceneWriter w = new SceneWriter(seed, 150).write(1 + (int) Math.floorMod(seed, 25L));
        SceneHarness.write(dir.resolve("unit.simp"), UNIT_COMMANDS);
        Path top = SceneHarness.write(dir.resolve("scene.simp"), w.text(crlf));
        SceneException e = harness.run(top);
        assertNull(e, () -> "a well-formed scene was refused: " + e.getMessage());
        cleanUp();
    }

    /**
     * Valid but extreme: numbers up to 1e300 (finite, so allowed), so the CTM
     * and the vertices reach huge values or overflow. Must still render.
     */
    @Property(tries = 300, seed = "10300", shrinking = ShrinkingMode.OFF)
    void scenesWithHugeFiniteNumbersRender(@ForAll long seed) throws Exception {
        double magnitude = Math.pow(10, 6 + Math.floorMod(seed, 295L));
        SceneWriter w = new SceneWriter(seed, magnitude).write(1 + (int) Math.floorMod(seed >> 8, 20L));
        SceneHarness.write(dir.resolve("unit.simp"), UNIT_COMMANDS);
        Path top = SceneHarness.write(dir.resolve("scene.simp"), w.text(false));
        SceneException e = harness.run(top);
        assertNull(e, () -> "a scene with large finite numbers was refused: " + e.getMessage());
        cleanUp();
    }

    /** The smallest scene the property above finds: one valid line command, ends beyond 2^53 pixels. */
    @Example
    void aLineWithEndsAt1e17Renders() throws Exception {
        Path top = SceneHarness.write(dir.resolve("line.simp"), "line (-1e17, 0, -100) (1e17, 0, -100)\n");
        assertNull(harness.run(top));
        cleanUp();
    }

    private static final String[] BAD_LINES = {
        "polygn (0,0,0) (1,0,0) (0,1,0)",
        "Polygon (0,0,0) (1,0,0) (0,1,0)",
        "rotate x 30",
        "rotate W 30",
        "rotate 30",
        "scale 1 2",
        "scale 1 2 3 4",
        "translate 1 2 NaN",
        "translate 1e999 0 0",
        "scale Infinity 1 1",
        "translate 1 2 abc",
        "line (0,0,0)",
        "polygon (0,0,0) (1,0,0) (0,1,0) extra",
        "polygon (0,0,0) (1,0,0) (0,1",
        "polygon (0,0,0,1,1,1) (1,0,0) (0,1,0)",
        "polygon (0,0,0) (1,0,0) (0,1,0) (1,1,1)",
        "polygon (0,0,0) (1,0,0) (0,1,NaN)",
        "file \"no_such_scene\"",
        "wire now",
        "{ }",
        "}",
    };

    /** A well-formed scene with one bad line: the error is reported in that file, at that line. */
    @Property(tries = 800, seed = "404")
    void oneBadLineIsReportedAtItsLine(@ForAll long seed, @ForAll boolean crlf) throws Exception {
        SceneWriter w = new SceneWriter(seed, 150).write((int) Math.floorMod(seed, 15L));
        int at = w.lines.isEmpty() ? 0 : w.r.nextInt(w.lines.size() + 1);
        int depthThere = at < w.lines.size() ? w.depths.get(at) : w.depth;
        String bad = BAD_LINES[w.r.nextInt(BAD_LINES.length - (depthThere == 0 ? 0 : 1))];
        w.lines.add(at, (w.r.nextBoolean() ? "\t" : "") + bad);
        SceneHarness.write(dir.resolve("unit.simp"), UNIT_COMMANDS);
        Path top = SceneHarness.write(dir.resolve("scene.simp"), w.text(crlf));
        SceneException e = harness.run(top);
        assertTrue(e != null, "no error for the bad line " + (at + 1) + ": " + bad);
        assertEquals(top.getFileName(), e.file().getFileName(), "file of the error for '" + bad + "':\n" + e.getMessage());
        assertEquals(at + 1, e.line(), "line of the error for '" + bad + "':\n" + e.getMessage());
        Statistics.label("bad line").collect(bad);
        cleanUp();
    }

    // ---------------------------------------------------------------- files including files

    static final String[] NAMES = {"main", "alpha", "beta", "gamma"};

    /**
     * Four files whose lines are valid commands or `file` commands naming one
     * of the four, or a missing one; quoted or bare. What must happen is known
     * exactly: the first missing file or cycle met in reading order is the
     * error, in the file and at the line of its `file` command; else it renders.
     */
    @Property(tries = 1000, seed = "8128")
    void fileWebsFailAtTheFirstMissingFileOrCycle(@ForAll long seed) throws Exception {
        Random r = new Random(seed);
        Map<String, List<String>> files = new TreeMap<>();
        for (String name : NAMES) {
            List<String> lines = new ArrayList<>();
            int includes = 0;
            int n = 1 + r.nextInt(6);
            for (int i = 0; i < n; i++) {
                if (includes < 2 && r.nextInt(3) == 0) {
                    includes++;
                    String target = r.nextInt(6) == 0 ? "missing" : NAMES[r.nextInt(NAMES.length)];
                    lines.add((r.nextBoolean() ? "\t" : "") + "file " + (r.nextBoolean() ? "\"" + target + "\"" : target)
                            + (r.nextInt(4) == 0 ? " " : ""));
                } else {
                    lines.add(r.nextBoolean() ? "polygon (0,0,-1) (10,0,-1) (0,10,-1)"
                            : r.nextBoolean() ? "translate 1, 2, -3" : "# just a comment");
                }
            }
            files.put(name, lines);
            SceneHarness.write(dir.resolve(name + ".simp"), String.join("\n", lines) + "\n");
        }
        Deque<String> chain = new ArrayDeque<>();
        chain.push("main");
        String[] expected = firstError("main", files, chain);
        SceneException e = harness.run(dir.resolve("main.simp"));
        String web = files.entrySet().stream().map(f -> f.getKey() + ".simp:\n  " + String.join("\n  ", f.getValue()))
                .collect(Collectors.joining("\n"));
        if (expected == null) {
            assertNull(e, () -> "no missing file and no cycle, yet: " + e.getMessage() + "\n" + web);
            Statistics.label("expected").collect("renders");
        } else {
            assertTrue(e != null, "expected an error at " + expected[0] + ".simp:" + expected[1] + "\n" + web);
            String got = e.file().getFileName() + ":" + e.line();
            assertEquals(expected[0] + ".simp:" + expected[1], got, e.getMessage() + "\n" + web);
            if (!expected[2].equals("missing")) {
                assertTrue(e.getMessage().contains(expected[2]),
                        "a cycle error should name the chain, here " + expected[2] + ": " + e.getMessage());
            }
            Statistics.label("expected").collect(expected[2].equals("missing") ? "missing file" : "cycle");
        }
        cleanUp();
    }

    /** {file, line, target} of the first failing `file` command in reading order, or null. */
    private static String[] firstError(String name, Map<String, List<String>> files, Deque<String> chain) {
        List<String> lines = files.get(name);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (!line.startsWith("file ")) {
                continue;
            }
            String target = line.substring(5).replace("\"", "").strip();
            if (target.equals("missing") || chain.contains(target)) {
                return new String[] {name, Integer.toString(i + 1), target};
            }
            chain.push(target);
            String[] inner = firstError(target, files, chain);
            chain.pop();
            if (inner != null) {
                return inner;
            }
        }
        return null;
    }
}
