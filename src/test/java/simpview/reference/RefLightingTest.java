package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The reference's lighting formula on its edge cases (SPEC Part 2, "Colour"). */
class RefLightingTest {

    private static final double[] KD = {0.5, 0.4, 0.2};
    private static final double[] P = {0, 0, -10};
    private static final double[] UP = {0, 0, 1};

    private static RefLighting lighting(double ks, double p, RefLighting.Light... lights) {
        return new RefLighting(new double[] {0.2, 0.2, 0.2}, ks, p, List.of(lights), true);
    }

    private static RefLighting.Light light(double x, double y, double z, double a, double b) {
        return new RefLighting.Light(new double[] {x, y, z}, new double[] {1, 1, 1}, a, b);
    }

    private static final double[] AMBIENT = {0.1, 0.08, 0.04};

    @Test
    void aLightOnTheLitPointBehindItOrAZeroNormalGivesTheAmbientTerm() {
        assertArrayEquals(AMBIENT, lighting(0.5, 8, light(0, 0, -10, 1, 0)).colour(P, UP, KD), 1e-12);
        assertArrayEquals(AMBIENT, lighting(0.5, 8, light(0, 0, -20, 1, 0)).colour(P, UP, KD), 1e-12);
        assertArrayEquals(AMBIENT, lighting(0.5, 8, light(0, 0, 0, 1, 0)).colour(P, new double[3], KD), 1e-12);
    }

    /** max(0, V.R)^0 is 1, even where {@code V.R < 0}; with p = 1 the same place has no specular term. */
    @Test
    void exponentZeroGivesTheFullSpecularTerm() {
        // Lit point off to the side of the eye, light at 60 degrees from the other side: V.R is about -0.26.
        double[] p = {10, 0, -10};
        RefLighting.Light light = light(10 - 2 * Math.sqrt(3), 0, -8, 1, 0);
        double[] zero = lighting(0.3, 0, light).colour(p, UP, KD);
        double[] one = lighting(0.3, 1, light).colour(p, UP, KD);
        for (int ch = 0; ch < 3; ch++) {
            assertEquals(AMBIENT[ch] + KD[ch] * 0.5 + 0.3, zero[ch], 1e-9, "p = 0, channel " + ch);
            assertEquals(AMBIENT[ch] + KD[ch] * 0.5, one[ch], 1e-9, "p = 1, channel " + ch);
        }
    }

    @Test
    void attenuationOfTwoHalvesTheLightAndTheSumIsClamped() {
        double[] half = lighting(0, 1, light(0, 0, -5, 1, 0.2)).colour(P, UP, KD);
        assertArrayEquals(new double[] {0.1 + 0.25, 0.08 + 0.2, 0.04 + 0.1}, half, 1e-12);
        double[] bright = lighting(0, 1, new RefLighting.Light(new double[] {0, 0, -5}, new double[] {9, 9, 9}, 1, 0))
                .colour(P, UP, KD);
        assertArrayEquals(new double[] {1, 1, 1}, bright, 0);
    }

    @Test
    void aHugeExponentLeavesOnlyTheMirrorDirection() {
        // Light and eye both straight above: V.R = 1 and the peak survives p = 1e6.
        double[] peak = lighting(0.3, 1e6, light(0, 0, -5, 1, 0)).colour(P, UP, KD);
        assertArrayEquals(new double[] {0.1 + 0.5 + 0.3, 0.08 + 0.4 + 0.3, 0.04 + 0.2 + 0.3}, peak, 1e-9);
    }
}
