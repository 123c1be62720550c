package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Under the FLIP metric the pixel to look at first is the one FLIP rates
 * highest in the largest patch FLIP fails, not the one whose colour is
 * farthest: on black, a pure blue pixel is 255 levels off but FLIP rates it
 * well below a light grey one 200 levels off, which the eye sees far more.
 */
class WorstPixelFlipTest {

    private static final int N = 16;

    /** Black panels, the picture with a blue pixel and a light grey one side by side in row 8 (from the top). */
    private static Comparison of(Comparison.Metric metric) {
        int[] ours = new int[N * N];
        int[] theirs = new int[N * N];
        theirs[8 * N + 7] = 0x0000FF;
        theirs[8 * N + 8] = 0xC8C8C8;
        return Comparison.of(ours, theirs, N, 0, metric, Comparison.FLIP_THRESHOLD);
    }

    private static WorstPixel look(Comparison comparison) {
        DiffRegion patch = DiffRegions.of(comparison, Comparison.DEFAULT_TOLERANCE, 5).largest().get(0);
        return WorstPixel.in(comparison, patch, Comparison.DEFAULT_TOLERANCE);
    }

    @Test
    void underFlipTheLookIsThePixelFlipRatesHighest() {
        Comparison flip = of(Comparison.Metric.FLIP);
        assertTrue(flip.fails(8 * N + 7, Comparison.DEFAULT_TOLERANCE) && flip.fails(8 * N + 8, 0),
                "both pixels fail FLIP: " + flip.flip(8 * N + 7) + ", " + flip.flip(8 * N + 8));
        assertTrue(flip.flip(8 * N + 8) > flip.flip(8 * N + 7), flip.flip(8 * N + 8) + " " + flip.flip(8 * N + 7));
        WorstPixel look = look(flip);
        assertEquals(8, look.x(), look.describe());
        assertEquals(N - 1 - 8, look.y(), look.describe());
        assertEquals(0xC8C8C8, look.theirs(), look.describe());
        // FLIP fails the black pixels around the two as well: they are counted in the patch, not looked at
        assertTrue(look.differing() > 2, look.describe());
    }

    /** Measured exactly, the colour farthest from simpview's is the pixel to look at: the blue one. */
    @Test
    void exactlyTheLookIsTheFarthestColour() {
        WorstPixel look = look(of(Comparison.Metric.EXACT));
        assertEquals(7, look.x(), look.describe());
        assertEquals(0x0000FF, look.theirs(), look.describe());
    }
}
