package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * FLIP's properties from its paper, checked on pictures made here: identical
 * pictures give 0, it is symmetric and in [0, 1], flat colours give what the
 * paper's colour formula gives (computed here again from textbook CIELAB,
 * sharing no code with {@link Flip}), another antialiasing of an edge is
 * forgiven while a wrong colour is not, and a one-pixel shift of a
 * high-contrast edge is seen (that is slack's business, not FLIP's).
 */
class FlipTest {

    private static final int N = 120;

    @Test
    void identicalPicturesGiveZeroEverywhere() {
        int[] busy = noisy(disc(N, 60.3, 59.7, 35, 16), 7);
        float[] flip = Flip.of(busy, busy.clone(), N, N);
        for (float v : flip) {
            assertEquals(0f, v);
        }
    }

    @Test
    void isSymmetricAndBetweenZeroAndOne() {
        int[] a = noisy(disc(N, 60.3, 59.7, 35, 16), 1);
        int[] b = noisy(disc(N, 58.1, 61.2, 30, 2), 2);
        float[] ab = Flip.of(a, b, N, N);
        float[] ba = Flip.of(b, a, N, N);
        assertArrayEquals(ab, ba);
        double max = 0;
        for (float v : ab) {
            assertTrue(v >= 0 && v <= 1, "FLIP " + v);
            max = Math.max(max, v);
        }
        assertTrue(max > 0.5, "two different noisy pictures differ visibly: " + max);
    }

    @Test
    void flatColoursGiveThePapersColourDifference() {
        int[][] pairs = {{0x808080, 0x888888}, {0x000000, 0x080808}, {0xFF0000, 0x0000FF}, {0x336699, 0x339966},
            {0xFFFFFF, 0x000000}, {0x00FF00, 0x0000FF}, {0x101010, 0x141414}};
        for (int[] pair : pairs) {
            int[] a = new int[40 * 40];
            int[] b = new int[40 * 40];
            Arrays.fill(a, pair[0]);
            Arrays.fill(b, pair[1]);
            float[] flip = Flip.of(a, b, 40, 40);
            double expected = TextbookFlip.flat(pair[0], pair[1]);
            for (float v : flip) {
                assertEquals(expected, v, 2e-4, Integer.toHexString(pair[0]) + " against " + Integer.toHexString(pair[1]));
            }
            assertEquals(expected, Flip.flat(pair[0], pair[1]), 2e-4);
        }
        // green against blue is the largest colour difference: FLIP maps it to 1
        assertEquals(1.0, TextbookFlip.flat(0x00FF00, 0x0000FF), 1e-9);
    }

    @Test
    void theThresholdIsJustAboveTheDefaultToleranceOnFlatGrey() {
        double grey = Flip.flat(0x808080, 0x888888);
        assertTrue(grey < Comparison.FLIP_THRESHOLD && grey > Comparison.FLIP_THRESHOLD - 0.005, "8/255 on mid grey: " + grey);
        assertTrue(Flip.flat(0x000000, 0x080808) < Comparison.FLIP_THRESHOLD);
        assertTrue(Flip.flat(0xF7F7F7, 0xFFFFFF) < Comparison.FLIP_THRESHOLD);
        assertTrue(Flip.flat(0x808080, 0x909090) > Comparison.FLIP_THRESHOLD, "16/255 on flat grey is seen");
    }

    @Test
    void anotherAntialiasingOfTheSameEdgeIsForgivenWhereTheExactMetricIsNot() {
        int[] fine = disc(N, 60.3, 59.7, 35, 16);
        int[] coarse = disc(N, 60.3, 59.7, 35, 4);
        float[] flip = Flip.of(fine, coarse, N, N);
        int overThreshold = 0;
        for (float v : flip) {
            overThreshold += v > Comparison.FLIP_THRESHOLD ? 1 : 0;
        }
        int beyondTolerance = 0;
        for (int i = 0; i < fine.length; i++) {
            beyondTolerance += Rasters.distance(fine[i], coarse[i]) > 8 ? 1 : 0;
        }
        // 16x16 against 4x4 samples per pixel: 63 edge pixels differ by more than 8/255; FLIP passes all but
        // 4 of the disc's pixels (its largest value is 0.138)
        assertTrue(beyondTolerance > 50, "the two antialiasings differ in grey levels: " + beyondTolerance);
        assertTrue(overThreshold * 10 < beyondTolerance, "FLIP above its threshold: " + overThreshold);
    }

    @Test
    void aWrongColourScoresHigh() {
        int[] white = disc(N, 60.3, 59.7, 35, 16);
        int[] yellow = white.clone();
        for (int i = 0; i < yellow.length; i++) {
            yellow[i] = yellow[i] == 0xFFFFFF ? 0xFFFF00 : yellow[i];
        }
        float[] flip = Flip.of(white, yellow, N, N);
        assertTrue(flip[60 * N + 60] > 0.9, "a white disc drawn yellow: " + flip[60 * N + 60]);
        assertEquals(0f, flip[5 * N + 5], "the black around it is the same");
    }

    @Test
    void aOnePixelShiftOfAHighContrastEdgeIsSeenWhileSlackForgivesIt() {
        int n = Comparison.N;
        int[] here = disc(n, 325.3, 324.7, 200, 4);
        int[] there = disc(n, 326.3, 324.7, 200, 4);
        Comparison exact = Comparison.of(here, there, 1, Comparison.Metric.EXACT);
        Comparison flip = Comparison.of(here, there, 1, Comparison.Metric.FLIP);
        assertEquals(0, exact.failing(8), "one pixel of slack forgives the shift");
        assertTrue(flip.failing(8) > 1000, "flipping between them shows the edge move: " + flip.failing(8));
        double max = 0;
        for (int i = 0; i < n * n; i++) {
            max = Math.max(max, flip.flip(i));
        }
        assertTrue(max > 0.5, "largest FLIP " + max);
        // the colour shares with slack are the same under both metrics; only the verdict differs
        assertEquals(exact.withSlack(), flip.withSlack());
        assertTrue(flip.verdictShare(8) < exact.verdictShare(8));
    }

    @Test
    void theComparisonCountsFailingPixelsAndRegionsByFlip() {
        int n = Comparison.N;
        int[] ours = new int[n * n];
        int[] theirs = new int[n * n];
        Arrays.fill(ours, 0x202020);
        Arrays.fill(theirs, 0x202020);
        for (int y = 100; y < 140; y++) {
            for (int x = 300; x < 360; x++) {
                theirs[y * n + x] = 0xFF00FF;
            }
        }
        Comparison c = Comparison.of(ours, theirs, 1, Comparison.Metric.FLIP);
        int counted = 0;
        int disagree = 0;
        for (int i = 0; i < n * n; i++) {
            boolean above = c.flip(i) > Comparison.FLIP_THRESHOLD;
            counted += above ? 1 : 0;
            disagree += above != c.fails(i, 8) ? 1 : 0;
        }
        assertEquals(0, disagree, "a pixel fails exactly when its FLIP value is above the threshold");
        assertEquals(counted, c.failing(8));
        assertTrue(counted >= 40 * 60, "the whole magenta block fails, and FLIP spreads it a little: " + counted);
        assertEquals(1 - counted / (double) (n * n), c.verdictShare(8), 1e-12);
        DiffRegions.Found regions = DiffRegions.of(c, 8, 5);
        assertEquals(1, regions.count());
        assertEquals(counted, regions.pixels());
        assertTrue(Double.isNaN(Comparison.of(ours, theirs, 0, Comparison.Metric.EXACT).flip(0)));
    }

    /** A white disc of radius r on black, each pixel's coverage by s x s samples. */
    static int[] disc(int n, double cx, double cy, double r, int s) {
        int[] p = new int[n * n];
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int in = 0;
                for (int j = 0; j < s; j++) {
                    for (int i = 0; i < s; i++) {
                        double px = x + (i + 0.5) / s - cx;
                        double py = y + (j + 0.5) / s - cy;
                        in += px * px + py * py <= r * r ? 1 : 0;
                    }
                }
                int g = (int) Math.round(255.0 * in / (s * s));
                p[y * n + x] = g << 16 | g << 8 | g;
            }
        }
        return p;
    }

    private static int[] noisy(int[] picture, long seed) {
        Random random = new Random(seed);
        int[] out = picture.clone();
        for (int i = 0; i < out.length; i += 3) {
            out[i] = random.nextInt(0x1000000);
        }
        return out;
    }

    /** The paper's colour difference of two flat sRGB colours, from textbook sRGB and CIELAB (D65). */
    private static final class TextbookFlip {

        static double flat(int a, int b) {
            double[] p = hunt(lab(a));
            double[] q = hunt(lab(b));
            double cmax = Math.pow(hyab(hunt(lab(0x00FF00)), hunt(lab(0x0000FF))), 0.7);
            double e = Math.pow(hyab(p, q), 0.7);
            return e < 0.4 * cmax ? 0.95 * e / (0.4 * cmax) : 0.95 + 0.05 * (e - 0.4 * cmax) / (0.6 * cmax);
        }

        private static double[] lab(int rgb) {
            double r = linear(rgb >> 16 & 0xFF);
            double g = linear(rgb >> 8 & 0xFF);
            double b = linear(rgb & 0xFF);
            double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
            double y = (0.2126 * r + 0.7152 * g + 0.0722 * b);
            double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
            return new double[] {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
        }

        private static double linear(int v) {
            double c = v / 255.0;
            return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
        }

        private static double f(double t) {
            return t > 216.0 / 24389 ? Math.cbrt(t) : (24389.0 / 27 * t + 16) / 116;
        }

        private static double[] hunt(double[] lab) {
            return new double[] {lab[0], lab[1] * lab[0] / 100, lab[2] * lab[0] / 100};
        }

        private static double hyab(double[] p, double[] q) {
            return Math.abs(p[0] - q[0]) + Math.hypot(p[1] - q[1], p[2] - q[2]);
        }
    }
}
