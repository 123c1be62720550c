package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The table-and-series arc cosine against Math.acos: everywhere within a few units in the last place. */
class ArcCosineTest {

    /** Four ulps of pi, the largest angle. */
    private static final double WITHIN = 4 * Math.ulp(Math.PI);

    @Test
    void agreesWithMathAcosEverywhere() {
        Random random = new Random(29);
        double worst = 0;
        for (int i = 0; i < 100_000; i++) {
            double x = 2 * random.nextDouble() - 1;
            if (i % 2 == 1) {
                // Near the ends, where acos is steepest.
                x = Math.copySign(1 - Math.pow(10, -16 * random.nextDouble()), x);
            }
            worst = Math.max(worst, Math.abs(ArcCosine.of(x) - Math.acos(x)));
        }
        assertTrue(worst <= WITHIN, "worst difference " + worst);
    }

    @Test
    void theEndsTheTableRowsAndTheirBordersAreExactOrNearly() {
        assertEquals(0, ArcCosine.of(1), 0);
        assertEquals(Math.PI, ArcCosine.of(-1), WITHIN);
        assertEquals(Math.PI / 2, ArcCosine.of(0), WITHIN);
        for (int j = -128; j <= 128; j++) {
            for (double x : new double[] {j / 128.0, (j + 0.5) / 128.0, Math.nextUp(j / 128.0), Math.nextDown(j / 128.0)}) {
                if (Math.abs(x) <= 1) {
                    assertEquals(Math.acos(x), ArcCosine.of(x), WITHIN, "x " + x);
                }
            }
        }
        double border = Math.sqrt(0.5);
        for (double x : new double[] {border, -border, Math.nextUp(border), Math.nextDown(-border)}) {
            assertEquals(Math.acos(x), ArcCosine.of(x), WITHIN, "x " + x);
        }
    }
}
