package simpview.compare;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.IntBinaryOperator;

/** Synthetic panels and batch rows for the grading tests: made here, pixel by pixel, sharing no code with pages. */
final class GradingFixtures {

    static final int N = Comparison.N;

    private GradingFixtures() {
    }

    /** A 650x650 panel whose pixel (x, row from the top) is {@code colour.applyAsInt(x, row)}. */
    static int[] panel(IntBinaryOperator colour) {
        int[] p = new int[N * N];
        for (int row = 0; row < N; row++) {
            for (int x = 0; x < N; x++) {
                p[row * N + x] = colour.applyAsInt(x, row) & 0xFFFFFF;
            }
        }
        return p;
    }

    /** White vertical lines one pixel wide every four pixels, starting at column {@code offset}, on black. */
    static int[] stripes(int offset) {
        return panel((x, row) -> Math.floorMod(x - offset, 4) == 0 ? 0xFFFFFF : 0);
    }

    /** A copy of {@code p} with a block of {@code pixels} pixels (whole rows from the top, then a part row) set to red. */
    static int[] spoiled(int[] p, int pixels) {
        int[] out = p.clone();
        for (int i = 0; i < pixels; i++) {
            out[i] = 0xFF0000 ^ (p[i] & 0x00FF00);
        }
        return out;
    }

    /** Every channel of every pixel moved by {@code steps} toward the middle grey (so it never clips). */
    static int[] nudged(int[] p, int steps) {
        int[] out = new int[p.length];
        for (int i = 0; i < p.length; i++) {
            int rgb = 0;
            for (int shift = 16; shift >= 0; shift -= 8) {
                int c = p[i] >> shift & 0xFF;
                rgb |= (c < 128 ? c + steps : c - steps) << shift;
            }
            out[i] = rgb;
        }
        return out;
    }

    /** The panel as a Picture (a 750x750 page with white margins). */
    static Picture picture(int[] panel, String name) {
        return Picture.ofPage(HeatMap.asPage(panel), name);
    }

    /** A batch row for {@code theirs} against {@code ours} under {@code rule}, with its diff image written under {@code outDir}. */
    static BatchRow row(String file, String target, int[] ours, int[] theirs, RubricRule rule, boolean partial,
            Path outDir) throws IOException {
        Comparison c = Comparison.of(ours, theirs, rule.deviation(), rule.metric());
        ComparisonReport report = ComparisonReport.of(picture(theirs, file), target, c, rule);
        String diff = "";
        if (outDir != null) {
            diff = "diffs/" + file.replace('/', '_').replace(".png", "") + "-diff.png";
            Files.createDirectories(outDir.resolve("diffs"));
            Files.write(outDir.resolve(diff), HeatMap.diffPng(c, rule.tolerance()));
        }
        return BatchRow.compared(file, target, report, diff, rule, rule.score(c, partial), "");
    }

    static RubricRule defaults() {
        return RubricRule.defaults(8, 99, Comparison.DEFAULT_DEVIATION, Comparison.Metric.EXACT);
    }
}
