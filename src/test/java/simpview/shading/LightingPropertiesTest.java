package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;

/** Random inputs: hostile ones never give NaN or leave [0, 1]; ordinary ones agree with the plain formula. */
class LightingPropertiesTest {

    private static final int SCENE = 14;
    private static final int LIGHT = 8;

    /** Any doubles at all, the awkward ones often. */
    @Provide
    Arbitrary<double[]> hostile() {
        Arbitrary<Double> any = Arbitraries.frequencyOf(
                net.jqwik.api.Tuple.of(3, Arbitraries.of(0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, -1e300,
                        Double.MIN_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, Double.NaN,
                        Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 1e154, 1e-154)),
                net.jqwik.api.Tuple.of(3, Arbitraries.doubles().between(-200, 200)),
                net.jqwik.api.Tuple.of(1, Arbitraries.doubles()));
        return any.array(double[].class).ofSize(SCENE + 4 * LIGHT);
    }

    @Property(tries = 1500, seed = "20261203")
    void noInputGivesNaNOrAChannelOutsideZeroToOne(@ForAll("hostile") double[] x,
            @ForAll @IntRange(min = 0, max = 4) int lightCount, @ForAll boolean perspective) {
        Lights lights = new Lights();
        for (int i = 0; i < lightCount; i++) {
            int o = SCENE + LIGHT * i;
            lights.add(x[o], x[o + 1], x[o + 2], x[o + 3], x[o + 4], x[o + 5], x[o + 6], x[o + 7]);
        }
        Lighting lighting = new Lighting(lights);
        lighting.prepare(x[0], x[1], x[2], x[3], x[4], lightCount, perspective);
        double[] out = new double[3];
        lighting.shade(x[5], x[6], x[7], x[8], x[9], x[10], x[11], x[12], x[13], out, 0);
        for (double c : out) {
            assertTrue(c >= 0 && c <= 1, "channel " + c);
        }
    }

    @Provide
    Arbitrary<double[]> ordinary() {
        return Arbitraries.doubles().between(0, 1).array(double[].class).ofSize(SCENE + 4 * LIGHT);
    }

    @Provide
    Arbitrary<Double> exponents() {
        return Arbitraries.oneOf(Arbitraries.of(0.0, 1.0, 2.0, 8.0, 16.0, 64.0, 128.0, 256.0, 1024.0, 1e6),
                Arbitraries.doubles().between(0, 300));
    }

    /**
     * Ordinary scenes: points in front of the eye, lights around them, values
     * in their usual ranges. A point within 1e-9 of a light's horizon (N . L
     * about 0, where SPEC's formula jumps by the light's specular term) is not
     * one: there the two evaluations' last bits decide the side. Seed
     * -2593879915638028073 found such a point: N . L = 1.1e-16, p = 0, a
     * light of blue 0.01 and f = 10, so 0.001 from the one and 0 from the
     * other.
     */
    @Property(tries = 3000, seed = "20261202")
    void ordinaryInputsAgreeWithThePlainFormula(@ForAll("ordinary") double[] x, @ForAll("exponents") double p,
            @ForAll @IntRange(min = 0, max = 4) int lightCount, @ForAll boolean perspective) {
        PlainLighting plain = new PlainLighting();
        plain.ambient = new double[] {0.5 * x[0], 0.5 * x[1], 0.5 * x[2]};
        plain.ks = x[3];
        plain.p = p;
        plain.perspective = perspective;
        for (int i = 0; i < lightCount; i++) {
            int o = SCENE + LIGHT * i;
            plain.light(400 * x[o] - 200, 400 * x[o + 1] - 200, -250 * x[o + 2] + 20, x[o + 3], x[o + 4], x[o + 5],
                    0.1 + 2 * x[o + 6], 0.1 * x[o + 7]);
        }
        double[] point = {200 * x[5] - 100, 200 * x[6] - 100, -1 - 199 * x[7]};
        double[] normal = {2 * x[8] - 1, 2 * x[9] - 1, 2 * x[10] - 1};
        double[] kd = {x[11], x[12], x[13]};
        Assume.that(plain.nearestHorizon(point, normal) > 1e-9);
        assertArrayEquals(plain.colour(point, normal, kd),
                LightingTest.shade(plain.toLighting(), point, normal, kd), 1e-9);
    }
}
