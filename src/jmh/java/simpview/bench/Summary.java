package simpview.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Reads JMH's results.json and writes a markdown table: our median, Java2D's
 * median on the same geometry, their ratio, the target, and allocation per op
 * when the run had {@code -prof gc}. Usage: {@code Summary [results.json [out.md]]}.
 * Medians: for sampled benchmarks the median sample, for throughput ones the
 * median of the measurement iterations (JMH's 50th percentile either way).
 */
public final class Summary {

    private Summary() {
    }

    /** Whether a figure (and its ratio to the baseline, NaN without one) meets the row's target. */
    private interface Check {
        boolean met(double ours, double ratio);
    }

    /**
     * What a benchmark measures (with which parameters), what it is compared
     * with (a benchmark and its parameters, or null), how to show it, and its
     * target (empty and a null check: none).
     */
    private record Row(String label, String benchmark, Map<String, String> params, String baseline,
                       Map<String, String> baselineParams, String unit, double scale, boolean timeLike,
                       String target, Check check) {
    }

    private static final String B = "simpview.bench.";

    private static Row row(String label, String benchmark, String page, String baseline, String unit,
                           boolean timeLike, String target, Check check) {
        return new Row(label, benchmark, page == null ? Map.of() : Map.of("page", page), baseline, Map.of(), unit,
                1, timeLike, target, check);
    }

    private static List<Row> rows() {
        List<Row> rows = new ArrayList<>();
        for (int page = 1; page <= 8; page++) {
            rows.add(row("Page " + page + ", clear + draw", B + "Assignment2Pages.clearAndDraw", String.valueOf(page),
                    null, "ms", true, "<= 2 ms", (ours, ratio) -> ours <= 2));
        }
        rows.add(row("Full-panel fill: 2 triangles, blerp + z-buffer + depth cue (Java2D: flat fillPolygon)",
                B + "FillRate.simpview", null, B + "FillRate.java2d", "Mpixels/s", false,
                ">= 300 and >= 0.5x Java2D", (ours, ratio) -> ours >= 300 && ratio >= 0.5));
        rows.add(row("Small triangles: 100,000-triangle mesh, z-buffer + depth cue (Java2D: flat fillPolygon)",
                B + "SmallTriangles.simpview", null, B + "SmallTriangles.java2d", "triangles/s", false,
                ">= 5x Java2D", (ours, ratio) -> ratio >= 5));
        rows.add(row("100,000 random lines, DDA onto the panel, colour lerp (Java2D: drawLine)",
                B + "Lines.simpviewPanel", null, B + "Lines.java2d", "lines/s", false, "", null));
        rows.add(row("100,000 random lines, DDA, z-buffer + depth cue (Java2D: drawLine)",
                B + "Lines.simpviewDepthCued", null, B + "Lines.java2d", "lines/s", false, "", null));
        rows.add(row("End to end: 1,000,000-polygon SIMP file, -Xmx64m",
                B + "SimpEndToEnd.readInterpretDraw", null, null, "SIMP lines/s", false, ">= 2,000,000",
                (ours, ratio) -> ours >= 2_000_000));
        litRows(rows);
        instrumentRows(rows);
        return rows;
    }

    /** Issue 14: what the window's instruments cost, and a turning view's frame. */
    private static void instrumentRows(List<Row> rows) {
        rows.add(new Row("Page 7 with the inspector's record (ratio: against without)", B + "Inspector.clearAndDraw",
                Map.of("inspector", "record"), B + "Inspector.clearAndDraw", Map.of("inspector", "off"), "ms", 1,
                true, "at most 25 % slower", (ours, ratio) -> ratio >= 1 / 1.25));
        for (String scene : new String[] {"page7", "a4/page-d"}) {
            rows.add(new Row("Orbit frame of " + scene + " during a drag, turned, copied out (ratio: against unturned)",
                    B + "OrbitFrame.frame", Map.of("scene", scene, "turned", "true", "copy", "true", "record", "false"),
                    B + "OrbitFrame.frame", Map.of("scene", scene, "turned", "false", "copy", "true", "record", "false"),
                    "ms", 1, true,
                    "<= 16 ms", (ours, ratio) -> ours <= 16));
        }
    }

    /** Issues 11 and 12: the course's lit pages, the phong fill, the lighting and the .obj reader. */
    private static void litRows(List<Row> rows) {
        for (String scene : LIT_PAGES) {
            boolean modelTwice = scene.equals("a3/pageI");
            boolean phongModel = scene.equals("a4/page-d");
            double limit = scene.startsWith("a3") ? (modelTwice ? 10 : 5) : (phongModel ? 15 : 10);
            String target = String.format(Locale.ROOT, "<= %.0f ms", limit);
            rows.add(new Row("Lit page " + scene + ", clear + draw, models parsed", B + "LitPages.clearAndDraw",
                    Map.of("scene", scene), null, Map.of(), "ms", 1, true, target, (ours, ratio) -> ours <= limit));
        }
        rows.add(new Row("Full-panel phong fill, 2 lights, z-buffered, every pixel lit", B + "PhongFill.fill",
                Map.of("depthTest", "passes"), null, Map.of(), "Mpixels/s", 1, false, ">= 60",
                (ours, ratio) -> ours >= 60));
        rows.add(new Row("The same, the z-test rejecting every pixel (ratio: against every pixel lit)",
                B + "PhongFill.fill", Map.of("depthTest", "rejects"), B + "PhongFill.fill",
                Map.of("depthTest", "passes"), "Mpixels/s", 1, false, ">= 5x lit", (ours, ratio) -> ratio >= 5));
        for (String p : new String[] {"8", "128", "7.5"}) {
            rows.add(new Row("Lighting.shade + fog, 2 lights, p = " + p, B + "Shade.shade", Map.of("exponent", p),
                    null, Map.of(), "ns/call", 1, true, "", null));
        }
        rows.add(row("dummy.obj (2.2 MB) parsed, streamed to a sink", B + "ObjParse.streamDummy", null, null, "ms",
                true, "<= 15 ms", (ours, ratio) -> ours <= 15));
        rows.add(row("dummy.obj parsed into a kept model", B + "ObjParse.readDummyModel", null, null, "ms", true,
                "", null));
        rows.add(row("dummy.obj's kept model replayed", B + "ObjParse.replayDummy", null, null, "ms", true, "",
                null));
    }

    private static final String[] LIT_PAGES = {"a3/pageA", "a3/pageB", "a3/pageC", "a3/pageD", "a3/pageE",
        "a3/pageF", "a3/pageG", "a3/pageH", "a3/pageI", "a3/tomsPageJ", "a4/page-a1", "a4/page-a2", "a4/page-a3",
        "a4/page-b1", "a4/page-b2", "a4/page-b3", "a4/page-c1", "a4/page-c2", "a4/page-c3", "a4/page-d",
        "a4/page-e", "a4/page-f1", "a4/page-f2", "a4/page-g", "a4/page-h"};

    public static void main(String[] args) throws IOException {
        Path in = Path.of(args.length > 0 ? args[0] : "build/jmh/results.json");
        Path out = Path.of(args.length > 1 ? args[1] : "build/jmh/results.md");
        if (!Files.isRegularFile(in)) {
            System.out.println("No " + in + " (nothing was benchmarked), so no summary.");
            return;
        }
        String table = table(in);
        System.out.print(table);
        Files.writeString(out, table, StandardCharsets.UTF_8);
        System.out.println("(written to " + out + ")");
    }

    @SuppressWarnings("unchecked")
    static String table(Path resultsFile) throws IOException {
        List<Object> results = (List<Object>) Json.parse(Files.readString(resultsFile, StandardCharsets.UTF_8));
        StringBuilder sb = new StringBuilder();
        sb.append("| benchmark | simpview (median) | Java2D (median) | simpview / Java2D | target | B/op (simpview) |\n");
        sb.append("|---|---:|---:|---:|---|---:|\n");
        for (Row row : rows()) {
            Map<String, Object> ours = find(results, row.benchmark(), row.params());
            Map<String, Object> theirs = row.baseline() == null ? null
                    : find(results, row.baseline(), row.baselineParams());
            sb.append("| ").append(row.label()).append(" | ");
            if (ours == null) {
                sb.append("not measured (failed or not run) | | | ").append(row.target()).append(" | |\n");
                continue;
            }
            double our = median(ours) * row.scale();
            sb.append(format(our, row)).append(" | ");
            double ratio = Double.NaN;
            if (theirs != null) {
                double their = median(theirs) * row.scale();
                ratio = row.timeLike() ? their / our : our / their;
                sb.append(format(their, row)).append(" | ").append(String.format(Locale.ROOT, "%.2fx", ratio));
            } else {
                sb.append("— | —");
            }
            sb.append(" | ").append(verdict(row, our, ratio)).append(" | ").append(allocation(ours)).append(" |\n");
        }
        return sb.append(stages(results)).toString();
    }

    private static final String[] SCENES = {"mesh", "page5", "page7"};
    private static final String[] STAGES = {"renderer", "scissor", "zbuffer", "depthcue", "panel", "image"};

    /**
     * The ChainStages profile, when the run had it: each cut's time and what
     * the stage added to the one before.
     */
    @SuppressWarnings("unchecked")
    private static String stages(List<Object> results) {
        StringBuilder sb = new StringBuilder();
        double[] before = new double[SCENES.length];
        Arrays.fill(before, Double.NaN); // no cut before the first
        for (String stage : STAGES) {
            StringBuilder line = new StringBuilder("| ").append(stage);
            boolean any = false;
            for (int i = 0; i < SCENES.length; i++) {
                Map<String, Object> r = find(results, B + "ChainStages.draw", Map.of("scene", SCENES[i], "stage", stage));
                if (r == null) {
                    line.append(" | | ");
                    before[i] = Double.NaN;
                    continue;
                }
                any = true;
                double ms = ((Number) ((Map<String, Object>) r.get("primaryMetric")).get("score")).doubleValue();
                line.append(String.format(Locale.ROOT, " | %.2f ms | ", ms));
                line.append(stage.equals(STAGES[0]) ? String.format(Locale.ROOT, "%.2f ms", ms)
                        : Double.isNaN(before[i]) ? "—" : String.format(Locale.ROOT, "%+.2f ms", ms - before[i]));
                before[i] = ms;
            }
            if (any) {
                sb.append(line).append(" |\n");
            }
        }
        if (sb.length() == 0) {
            return "";
        }
        return "\nChainStages (the chain cut after each stage; mean of the iterations):\n\n"
                + "| cut after | 100,000-triangle mesh | stage adds | page 5 | stage adds | page 7 | stage adds |\n"
                + "|---|---:|---:|---:|---:|---:|---:|\n" + sb;
    }

    private static String verdict(Row row, double our, double ratio) {
        if (row.check() == null) {
            return "";
        }
        return row.target() + (row.check().met(our, ratio) ? ": met" : ": MISSED");
    }

    /** The result of {@code benchmark} run with every parameter in {@code params} (none: the first run). */
    @SuppressWarnings("unchecked")
    private static Map<String, Object> find(List<Object> results, String benchmark, Map<String, String> params) {
        for (Object o : results) {
            Map<String, Object> r = (Map<String, Object>) o;
            if (!benchmark.equals(r.get("benchmark"))) {
                continue;
            }
            Map<String, Object> had = (Map<String, Object>) r.get("params");
            if (params.entrySet().stream().allMatch(p -> had != null && p.getValue().equals(had.get(p.getKey())))) {
                return r;
            }
        }
        return null;
    }

    @SuppressWarnings("unchecked")
    private static double median(Map<String, Object> result) {
        Map<String, Object> metric = (Map<String, Object>) result.get("primaryMetric");
        Map<String, Object> percentiles = (Map<String, Object>) metric.get("scorePercentiles");
        Object p50 = percentiles == null ? null : percentiles.get("50.0");
        return p50 instanceof Double ? (Double) p50 : (Double) metric.get("score");
    }

    @SuppressWarnings("unchecked")
    private static String allocation(Map<String, Object> result) {
        Map<String, Object> secondary = (Map<String, Object>) result.get("secondaryMetrics");
        if (secondary != null) {
            for (Map.Entry<String, Object> e : secondary.entrySet()) {
                if (e.getKey().endsWith("gc.alloc.rate.norm")) {
                    Object score = ((Map<String, Object>) e.getValue()).get("score");
                    if (score instanceof Double) {
                        double bytes = (Double) score;
                        return String.format(Locale.ROOT, bytes >= 100 ? "%,.0f" : "%.2g", bytes);
                    }
                }
            }
        }
        return "(run with -prof gc)";
    }

    private static String format(double v, Row row) {
        String pattern = v >= 1000 ? "%,.0f %s" : v >= 10 ? "%.1f %s" : "%.3f %s";
        return String.format(Locale.ROOT, pattern, v, row.unit());
    }
}
