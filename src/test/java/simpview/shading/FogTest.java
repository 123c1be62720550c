package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class FogTest {

    private static final Fog FOG = new Fog(-20, -220, 0.2, 0.4, 0.6);
    private static final double[] LIT = {0.9, 0.5, 0.1};

    private static double[] fogged(Fog fog, double z) {
        double[] c = {-1, LIT[0], LIT[1], LIT[2], -1};
        fog.apply(z, c, 1);
        assertArrayEquals(new double[] {-1, -1}, new double[] {c[0], c[4]}, 0, "only the colour's slots change");
        return new double[] {c[1], c[2], c[3]};
    }

    @Test
    void atAndBeforeNearTheColourStays() {
        assertArrayEquals(LIT, fogged(FOG, -20), 0);
        assertArrayEquals(LIT, fogged(FOG, -1), 0);
        assertArrayEquals(LIT, fogged(FOG, 5), 0);
    }

    @Test
    void atAndBeyondFarItIsTheFogColour() {
        double[] fog = {0.2, 0.4, 0.6};
        assertArrayEquals(fog, fogged(FOG, -220), 0);
        assertArrayEquals(fog, fogged(FOG, -1000), 0);
        assertArrayEquals(fog, fogged(FOG, Double.NEGATIVE_INFINITY), 0);
    }

    @Test
    void halfWayItIsTheMean() {
        assertArrayEquals(new double[] {0.55, 0.45, 0.35}, fogged(FOG, -120), 1e-15);
    }

    @Test
    void betweenItIsTheLinearMixOfSpec() {
        for (double z = -219.5; z < -20; z += 7.25) {
            double t = (z - -220) / (-20 - -220);
            double[] expected = {t * 0.9 + (1 - t) * 0.2, t * 0.5 + (1 - t) * 0.4, t * 0.1 + (1 - t) * 0.6};
            assertArrayEquals(expected, fogged(FOG, z), 1e-15, "z " + z);
        }
    }

    @Test
    void noFogKeepsEveryColour() {
        assertTrue(Fog.NONE.isNone());
        assertFalse(FOG.isNone());
        for (double z : new double[] {0, -1, -200, -1e300, Double.NEGATIVE_INFINITY, Double.NaN}) {
            assertArrayEquals(LIT, fogged(Fog.NONE, z), 0, "z " + z);
        }
    }

    @Test
    void aNaNDepthKeepsTheColourAndNothingBecomesNaN() {
        assertArrayEquals(LIT, fogged(FOG, Double.NaN), 0);
        Fog endless = new Fog(-20, Double.NEGATIVE_INFINITY, 0, 0, 0);
        for (double c : fogged(endless, -100)) {
            assertFalse(Double.isNaN(c));
        }
    }
}
