package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The lighting formula on scenes whose answer is known by hand: a large lit
 * square in the plane z = -100 facing the eye (N = (0, 0, 1)), perspective
 * view, the eye at the origin; and the hostile cases of SPEC and issue 12.
 */
class LightingTest {

    private static final double EXACT = 1e-12;
    private static final double[] UP = {0, 0, 1};
    private static final double[] UNDER_EYE = {0, 0, -100};

    static double[] shade(Lighting lighting, double[] point, double[] normal, double[] kd) {
        double[] out = new double[5];
        out[0] = -7; // the colour goes at offset 1; the slots around it stay as they were
        out[4] = -7;
        lighting.shade(point[0], point[1], point[2], normal[0], normal[1], normal[2], kd[0], kd[1], kd[2], out, 1);
        assertEquals(-7, out[0]);
        assertEquals(-7, out[4]);
        return new double[] {out[1], out[2], out[3]};
    }

    private static PlainLighting scene(double ia, double ks, double p) {
        PlainLighting s = new PlainLighting();
        s.ambient = new double[] {ia, 2 * ia, 3 * ia};
        s.ks = ks;
        s.p = p;
        return s;
    }

    @Test
    void underALightStraightAboveItIsAmbientPlusLightTimesKdPlusKs() {
        // Light 40 above the point on the eye's axis: V = N = L there, so R = N and V . R = 1.
        PlainLighting s = scene(0.1, 0.3, 8).light(0, 0, -60, 0.9, 0.6, 0.3, 1, 0.05);
        double[] kd = {0.5, 0.4, 0.2};
        double f = 1 / (1 + 0.05 * 40);
        double[] expected = new double[3];
        for (int c = 0; c < 3; c++) {
            expected[c] = kd[c] * s.ambient[c] + s.lights.get(0)[3 + c] * f * (kd[c] + 0.3);
        }
        assertArrayEquals(expected, shade(s.toLighting(), UNDER_EYE, UP, kd), EXACT);
        assertArrayEquals(expected, s.colour(UNDER_EYE, UP, kd), EXACT);
    }

    @Test
    void lightComingInAtSixtyDegreesHalvesTheDiffuseTerm() {
        PlainLighting s = scene(0.1, 0, 8).light(0, 0, -60, 0.9, 0.6, 0.3, 1, 0);
        Lighting lighting = s.toLighting();
        double[] kd = {0.5, 0.4, 0.2};
        double[] slanted = {40 * Math.sqrt(3), 0, -100}; // 40 below the light, 40 sqrt 3 across: 60 degrees
        double[] straight = shade(lighting, UNDER_EYE, UP, kd);
        double[] sixty = shade(lighting, slanted, UP, kd);
        for (int c = 0; c < 3; c++) {
            double ambient = kd[c] * s.ambient[c];
            assertEquals((straight[c] - ambient) / 2, sixty[c] - ambient, EXACT);
            assertEquals(s.lights.get(0)[3 + c] * kd[c] / 2, sixty[c] - ambient, EXACT);
        }
    }

    @Test
    void theSpecularPeakSitsWhereTheEyeSeesTheLightMirrored() {
        // Eye 100 above the plane, light 50 above it and 60 across: the mirror point is at x = 40.
        PlainLighting s = scene(0, 1, 8).light(60, 0, -50, 0.5, 0.5, 0.5, 1, 0);
        Lighting lighting = s.toLighting();
        double[] black = {0, 0, 0};
        assertEquals(0.5, shade(lighting, new double[] {40, 0, -100}, UP, black)[0], EXACT);
        double best = -1;
        double bestX = Double.NaN;
        for (int i = 0; i <= 6000; i++) {
            double x = i / 100.0;
            double red = shade(lighting, new double[] {x, 0, -100}, UP, black)[0];
            if (red > best) {
                best = red;
                bestX = x;
            }
        }
        assertEquals(40, bestX, 1e-9);
        assertTrue(shade(lighting, new double[] {39, 0, -100}, UP, black)[0] < 0.5 - 1e-3);
        assertTrue(shade(lighting, new double[] {41, 0, -100}, UP, black)[0] < 0.5 - 1e-3);
    }

    @Test
    void attenuationOfTwoHalvesTheLight() {
        double[] kd = {0.5, 0.4, 0.2};
        double[] full = shade(scene(0.1, 0.3, 8).light(0, 0, -60, 0.9, 0.6, 0.3, 1, 0).toLighting(),
                UNDER_EYE, UP, kd);
        double[] half = shade(scene(0.1, 0.3, 8).light(0, 0, -60, 0.9, 0.6, 0.3, 1, 1.0 / 40).toLighting(),
                UNDER_EYE, UP, kd);
        double[] ambient = shade(scene(0.1, 0.3, 8).toLighting(), UNDER_EYE, UP, kd);
        for (int c = 0; c < 3; c++) {
            assertEquals((full[c] - ambient[c]) / 2, half[c] - ambient[c], EXACT);
            assertTrue(half[c] > ambient[c]);
        }
    }

    @Test
    void aLightBehindTheSurfaceOrInItsPlaneAddsNothing() {
        double[] kd = {0.5, 0.4, 0.2};
        double[] ambient = {0.5 * 0.1, 0.4 * (2 * 0.1), 0.2 * (3 * 0.1)};
        PlainLighting behind = scene(0.1, 1, 0).light(0, 0, -150, 1, 1, 1, 1, 0).light(500, 3, -100, 1, 1, 1, 1, 0);
        assertArrayEquals(ambient, shade(behind.toLighting(), UNDER_EYE, UP, kd), EXACT);
    }

    @Test
    void aZeroNormalGivesTheAmbientTermOnly() {
        PlainLighting s = scene(0.1, 1, 8).light(0, 0, -60, 1, 1, 1, 1, 0);
        double[] kd = {0.5, 0.4, 0.2};
        double[] ambient = {0.5 * 0.1, 0.4 * (2 * 0.1), 0.2 * (3 * 0.1)};
        assertArrayEquals(ambient, shade(s.toLighting(), UNDER_EYE, new double[] {0, 0, 0}, kd), 0);
        s.perspective = false;
        assertArrayEquals(ambient, shade(s.toLighting(), UNDER_EYE, new double[] {0, 0, -0.0}, kd), 0);
    }

    @Test
    void theNormalMayHaveAnyLength() {
        PlainLighting s = scene(0.1, 0.3, 16).light(20, 10, -60, 0.9, 0.6, 0.3, 1, 0.01);
        Lighting lighting = s.toLighting();
        double[] kd = {0.5, 0.4, 0.2};
        double[] point = {5, -3, -100};
        double[] unit = shade(lighting, point, new double[] {0.6, 0, 0.8}, kd);
        for (double length : new double[] {1e-300, 1e-160, 1e-20, 0.5, 3, 1e20, 1e160, 1e300}) {
            double[] n = {0.6 * length, 0, 0.8 * length};
            assertArrayEquals(unit, shade(lighting, point, n, kd), EXACT, "length " + length);
        }
        assertArrayEquals(s.colour(point, new double[] {0.6, 0, 0.8}, kd), unit, EXACT);
    }

    @Test
    void onlyTheFirstLightCountLightsShine() {
        PlainLighting one = scene(0.1, 0.3, 8).light(0, 0, -60, 0.5, 0.5, 0.5, 1, 0);
        Lights both = one.light(10, 0, -60, 0.4, 0.2, 0.1, 1, 0).toLights();
        one.lights.remove(1);
        Lighting lighting = new Lighting(both);
        lighting.prepare(0.1, 0.2, 0.3, 0.3, 8, 1, true);
        double[] kd = {0.5, 0.4, 0.2};
        assertArrayEquals(one.colour(UNDER_EYE, UP, kd), shade(lighting, UNDER_EYE, UP, kd), EXACT);
        assertThrows(IllegalArgumentException.class, () -> lighting.prepare(0, 0, 0, 0, 8, 3, true));
        assertThrows(IllegalArgumentException.class, () -> lighting.prepare(0, 0, 0, 0, 8, -1, true));
    }

    @Test
    void aParallelViewLooksAlongZEverywhere() {
        // From (30, 0, -100) the light straight above is off the perspective eye's mirror direction,
        // but exactly on the parallel view's.
        PlainLighting s = scene(0, 1, 1024).light(30, 0, -60, 0.5, 0.5, 0.5, 1, 0);
        double[] black = {0, 0, 0};
        double[] point = {30, 0, -100};
        s.perspective = false;
        assertEquals(0.5, shade(s.toLighting(), point, UP, black)[0], EXACT);
        s.perspective = true;
        double perspective = shade(s.toLighting(), point, UP, black)[0];
        assertTrue(perspective < 1e-6, "perspective " + perspective);
        assertEquals(s.colour(point, UP, black)[0], perspective, EXACT);
    }

    @Test
    void theColourIsClampedPerChannel() {
        PlainLighting s = scene(0.5, 0.3, 8).light(0, 0, -60, 5, 0.01, 0, 1, 0);
        double[] c = shade(s.toLighting(), UNDER_EYE, UP, new double[] {0.5, 0.4, 3});
        assertEquals(1, c[0]);
        assertEquals(0.4 + 0.01 * 0.7, c[1], EXACT);
        assertEquals(1, c[2]);
    }

    @Test
    void aLightAtTheLitPointAddsNothingWhateverItsAttenuation() {
        double[] kd = {0.5, 0.4, 0.2};
        double[] ambient = {0.5 * 0.1, 0.4 * (2 * 0.1), 0.2 * (3 * 0.1)};
        for (double[] ab : new double[][] {{1, 0}, {0, 1}, {0, 0}, {1, 1}}) {
            PlainLighting s = scene(0.1, 1, 0).light(0, 0, -100, 1e300, 1, 1, ab[0], ab[1]);
            assertArrayEquals(ambient, shade(s.toLighting(), UNDER_EYE, UP, kd), 0);
        }
        PlainLighting withAnother = scene(0.1, 0.3, 8).light(0, 0, -100, 1, 1, 1, 0, 1)
                .light(0, 0, -60, 0.9, 0.6, 0.3, 1, 0.05);
        assertArrayEquals(withAnother.colour(UNDER_EYE, UP, kd), shade(withAnother.toLighting(), UNDER_EYE, UP, kd),
                EXACT);
    }

    @Test
    void aVanishingAttenuationSaturatesLitChannelsAndLeavesDarkOnesAmbient() {
        double[] kd = {1, 0, 0.5};
        double[] expected = {1, 0, 1};
        // Lit point (0, 0, 0) in a parallel view, or (0, 0, -1) in perspective; the light at distance d.
        // A = 0: f = 1 / d (1e200, 4.5e15); A = B = 0: f is infinite; with 1e300 intensities I f overflows.
        double tiny = Math.nextUp(-1.0);
        double[][] cases = {{1, 0, 1, 0, 1e-200}, {1e300, 0, 1, 0, 1e-200}, {1e300, 1, 1, -1, tiny},
            {1, 0, 0, 0, 40}, {1e300, 1, 0, 0, 40}, {1e300, 1, 1, -1, -0.5}};
        for (double[] k : cases) {
            PlainLighting s = scene(0, 0, 8).light(0, 0, k[4], k[0], k[0], k[0], k[1], k[2]);
            s.perspective = k[3] != 0;
            assertArrayEquals(expected, shade(s.toLighting(), new double[] {0, 0, k[3]}, UP, kd), 0,
                    Arrays.toString(k));
        }
        // A channel the light has none of keeps its ambient term, even where f is infinite.
        PlainLighting dark = scene(0.1, 0, 8).light(0, 0, -60, 1e300, 0, 1e300, 0, 0);
        assertArrayEquals(new double[] {1, 0.08, 1},
                shade(dark.toLighting(), UNDER_EYE, UP, new double[] {0.5, 0.4, 0.2}), EXACT);
    }

    @Test
    void exponentZeroGivesFullHighlightEvenWhereVDotRIsNegative() {
        // Parallel view, V = (0, 0, 1); N nearly along x, the light nearly straight above:
        // N . L > 0 but R points down, away from V.
        double[] black = {0, 0, 0};
        double[] point = {0, 0, -100};
        double[] normal = {1, 0, 0.1};
        double[] l = {10, 0, 100};
        double nl = PlainLighting.dot(normal, l) / PlainLighting.length(normal) / PlainLighting.length(l);
        double rz = 2 * nl * 0.1 / PlainLighting.length(normal) - 100 / PlainLighting.length(l);
        assertTrue(nl > 0 && rz < 0, "N . L " + nl + ", V . R " + rz);
        PlainLighting s = scene(0, 0.5, 0).light(10, 0, 0, 0.8, 0.8, 0.8, 1, 0);
        s.perspective = false;
        assertEquals(0.4, shade(s.toLighting(), point, normal, black)[0], EXACT);
        s.p = 8;
        assertEquals(0, shade(s.toLighting(), point, normal, black)[0]);
        s.p = 1e-300;
        assertEquals(0, shade(s.toLighting(), point, normal, black)[0]);
    }

    @Test
    void aHugeExponentIsOneOnTheMirrorAndNothingOffIt() {
        PlainLighting s = scene(0, 1, 1e6).light(60, 0, -50, 0.5, 0.5, 0.5, 1, 0);
        Lighting lighting = s.toLighting();
        double[] black = {0, 0, 0};
        assertEquals(0.5, shade(lighting, new double[] {40, 0, -100}, UP, black)[0], 1e-9);
        assertEquals(0, shade(lighting, new double[] {39, 0, -100}, UP, black)[0], 1e-12);
        for (double p : new double[] {1e6, 1e300, Double.MAX_VALUE, 1025, 1024, 1023.5}) {
            s.p = p;
            double[] c = shade(s.toLighting(), new double[] {40, 0, -100}, UP, black);
            assertEquals(0.5, c[0], 1e-6, "p " + p);
        }
    }

    @Test
    void tenThousandLightsAddUpAsThePlainFormulaSays() {
        Random random = new Random(5);
        PlainLighting s = scene(0.05, 0.3, 16);
        for (int i = 0; i < 10_000; i++) {
            s.light(random.nextDouble() * 400 - 200, random.nextDouble() * 400 - 200, -100 + random.nextDouble() * 100,
                    random.nextDouble() * 1e-4, random.nextDouble() * 1e-4, random.nextDouble() * 1e-4,
                    random.nextDouble() + 0.5, random.nextDouble() * 0.01);
        }
        Lighting lighting = s.toLighting();
        double[] kd = {0.5, 0.4, 0.2};
        for (int k = 0; k < 20; k++) {
            double[] point = {random.nextDouble() * 200 - 100, random.nextDouble() * 200 - 100, -100};
            double[] c = shade(lighting, point, UP, kd);
            double[] plain = s.unclamped(point, UP, kd);
            for (int ch = 0; ch < 3; ch++) {
                assertTrue(plain[ch] < 1 && c[ch] > kd[ch] * s.ambient[ch], "unclamped and lit");
            }
            assertArrayEquals(plain, c, 1e-12);
        }
    }

    @Test
    void squaringMatchesMathPow() {
        Random random = new Random(3);
        for (int e = 0; e <= Lighting.MAX_SQUARING_EXPONENT; e++) {
            for (int k = 0; k < 20; k++) {
                double x = Math.pow(1e-250, 1.0 / Math.max(e, 1) * random.nextDouble());
                double expected = Math.pow(x, e);
                assertEquals(expected, Lighting.bySquaring(x, e), Math.abs(expected) * 2e-13, "x " + x + " e " + e);
            }
            assertEquals(e == 0 ? 1 : 0, Lighting.bySquaring(0, e));
            assertEquals(1, Lighting.bySquaring(1, e));
        }
    }

    /**
     * The guess of which points no light reaches: each light at an angle of
     * more than about 95.7 degrees from N (a cosine below -0.1), worked out
     * by hand; a grazing light, a light in front, no light or a NaN make it
     * false; N's length does not count.
     */
    @Test
    void aPointIsGuessedUnlitOnlyWhenEveryLightIsPlainlyBehindIt() {
        Lights lights = new Lights();
        lights.add(0, 0, -20, 1, 1, 1, 1, 0); // 10 behind the point at z -10, whose N is +z
        lights.add(30, 0, -10 - 30 * Math.tan(Math.toRadians(10)), 1, 1, 1, 1, 0); // 10 degrees below its plane
        Lighting lighting = new Lighting(lights);
        lighting.prepare(0.1, 0.1, 0.1, 0.5, 8, 0, true);
        assertTrue(!lighting.unlitAt(0, 0, -10, 0, 0, 1), "no light");
        lighting.prepare(0.1, 0.1, 0.1, 0.5, 8, 1, true);
        assertTrue(lighting.unlitAt(0, 0, -10, 0, 0, 1), "straight behind: cosine -1");
        assertTrue(lighting.unlitAt(0, 0, -10, 0, 0, 1e-9), "a short N");
        assertTrue(lighting.unlitAt(0, 0, -10, 0, 0, 1e9), "a long N");
        assertTrue(!lighting.unlitAt(0, 0, -10, 0, 0, -1), "straight in front");
        assertTrue(!lighting.unlitAt(0, 0, -10, 0, 0, 0), "a zero N");
        assertTrue(!lighting.unlitAt(0, 0, -10, Double.NaN, 0, 1), "a NaN N");
        assertTrue(!lighting.unlitAt(0, 0, -20, 0, 0, 1), "at the light");
        lighting.prepare(0.1, 0.1, 0.1, 0.5, 8, 2, true);
        // The second light's cosine from +z is -sin 10 degrees, -0.17: behind, plainly.
        assertTrue(lighting.unlitAt(0, 0, -10, 0, 0, 1), "both behind");
        // N turned 5 degrees towards the second light (to +x): its cosine is -sin 5 degrees, -0.087, a graze.
        double t = Math.toRadians(5);
        assertTrue(!lighting.unlitAt(0, 0, -10, Math.sin(t), 0, Math.cos(t)), "the second grazing");
        // Turned 5 degrees away from it: -sin 15 degrees, -0.26.
        assertTrue(lighting.unlitAt(0, 0, -10, -Math.sin(t), 0, Math.cos(t)), "both behind, turned");
    }
}
