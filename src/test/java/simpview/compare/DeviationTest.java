package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Position deviation, as dEQP's image comparison allows it: a pixel matches
 * when the other picture has its colour within that many pixels, both ways.
 * The stripes make a shift count: a quarter of all columns are lines.
 */
class DeviationTest {

    private static final int[] STRIPES = GradingFixtures.stripes(0);
    private static final RubricRule RULE = GradingFixtures.defaults();

    @Test
    void aOnePixelShiftPassesAtDeviationOneAndFailsAtZero() {
        int[] shifted = GradingFixtures.stripes(1);
        Comparison none = Comparison.of(STRIPES, shifted, 0, Comparison.Metric.EXACT);
        Comparison one = Comparison.of(STRIPES, shifted, 1, Comparison.Metric.EXACT);
        // Every line (columns 0, 4 ... 648: 163) and every pixel where one went (1, 5 ... 649: 163) is wrong.
        assertEquals((650 - 2 * 163) / 650.0, none.share(8, true), 1e-12);
        assertEquals(none.share(8, false), none.share(8, true), 1e-12, "deviation 0: slack is no slack");
        assertEquals(1.0, one.share(8, true), 1e-12);
        assertFalse(RULE.passes(none));
        assertTrue(RULE.passes(one));
    }

    @Test
    void aTwoPixelShiftNeedsDeviationTwo() {
        // Lines every 4 px moved by 2: the nearest line of the other picture is 2 px away.
        int[] shifted = GradingFixtures.stripes(2);
        assertFalse(RULE.passes(Comparison.of(STRIPES, shifted, 1, Comparison.Metric.EXACT)));
        assertTrue(RULE.passes(Comparison.of(STRIPES, shifted, 2, Comparison.Metric.EXACT)));
    }

    @Test
    void aMissingLineFailsAtEveryDeviation() {
        int[] black = GradingFixtures.panel((x, row) -> 0);
        for (int d = 0; d <= Comparison.MAX_DEVIATION; d++) {
            Comparison c = Comparison.of(STRIPES, black, d, Comparison.Metric.EXACT);
            assertEquals((650 - 163) / 650.0, c.share(8, true), 1e-12, "deviation " + d + ": 163 columns of lines");
            assertEquals(163 * 650, c.failing(8));
        }
    }

    @Test
    void deviationsBeyondTwoAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> Comparison.of(STRIPES, STRIPES, 3, Comparison.Metric.EXACT));
    }
}
