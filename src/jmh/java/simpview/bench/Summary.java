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

    /** What a benchmark measures, how to show it, and its target. */
    private record Row(String label, String benchmark, String page, String baseline, String unit,
                       double scale, boolean timeLike, String target) {
    }

    private static final String B = "simpview.bench.";

    private static List<Row> rows() {
        List<Row> rows = new ArrayList<>();
        for (int page = 1; page <= 8; page++) {
            rows.add(new Row("Page " + page + ", clear + draw", B + "Pages.clearAndDraw", String.valueOf(page),
                    null, "ms", 1, true, "<= 2 ms"));
        }
        rows.add(new Row("Full-panel fill: 2 triangles, blerp + z-buffer + depth cue (Java2D: flat fillPolygon)",
                B + "FillRate.simpview", null, B + "FillRate.java2d", "Mpixels/s", 1, false,
                ">= 300 and >= 0.5x Java2D"));
        rows.add(new Row("Small triangles: 100,000-triangle mesh, z-buffer + depth cue (Java2D: flat fillPolygon)",
                B + "SmallTriangles.simpview", null, B + "SmallTriangles.java2d", "triangles/s", 1, false,
                ">= 5x Java2D"));
        rows.add(new Row("100,000 random lines, DDA onto the panel, colour lerp (Java2D: drawLine)",
                B + "Lines.simpviewPanel", null, B + "Lines.java2d", "lines/s", 1, false, ""));
        rows.add(new Row("100,000 random lines, DDA, z-buffer + depth cue (Java2D: drawLine)",
                B + "Lines.simpviewDepthCued", null, B + "Lines.java2d", "lines/s", 1, false, ""));
        rows.add(new Row("End to end: 1,000,000-polygon SIMP file, -Xmx64m",
                B + "SimpEndToEnd.readInterpretDraw", null, null, "SIMP lines/s", 1, false, ">= 2,000,000"));
        return rows;
    }

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
            Map<String, Object> ours = find(results, row.benchmark(),
                    row.page() == null ? Map.of() : Map.of("page", row.page()));
            Map<String, Object> theirs = row.baseline() == null ? null : find(results, row.baseline(), Map.of());
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
        if (row.target().isEmpty()) {
            return "";
        }
        boolean met;
        if (row.timeLike()) {
            met = our <= 2;
        } else if (row.benchmark().endsWith("FillRate.simpview")) {
            met = our >= 300 && ratio >= 0.5;
        } else if (row.benchmark().endsWith("SmallTriangles.simpview")) {
            met = ratio >= 5;
        } else {
            met = our >= 2_000_000;
        }
        return row.target() + (met ? ": met" : ": MISSED");
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
