package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Arrays;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;

/**
 * A batch of points lit together ({@link Lighting#shade(LitPoints)}) gives
 * every point the very bits that {@link Lighting#shade} gives it alone: on
 * ordinary scenes, and on batches where any number may be one of the edge
 * cases Lighting's javadoc lists (zero, tiny and huge normals and distances,
 * the light at the lit point, the eye at the lit point, infinities, NaN,
 * huge intensities, zero attenuation, p = 0, integer and fractional p). Each
 * batch is lit twice: as usual, and as a batch guessed unlit
 * ({@link LitPoints#unlit}), whatever its lights do: the guess must never
 * show.
 */
class BatchLightingTest {

    private static final double[] AWKWARD = {0.0, -0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, -1e300, 1e-160,
        1e160, 1e-76, 1e76, Double.MIN_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, Double.NaN,
        Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 1e154, 1e-154};
    private static final double[] EXPONENTS = {0, 1, 2, 7.5, 8, 16, 64, 128, 1024, 1025, 1e6, 0.5};

    /** A number of its usual range, or often one of the awkward ones. */
    private static double number(Random random, double range, double awkwardShare) {
        if (random.nextDouble() < awkwardShare) {
            return AWKWARD[random.nextInt(AWKWARD.length)];
        }
        return (random.nextDouble() * 2 - 1) * range;
    }

    private static double ambient(Random random, boolean wild, double awkward) {
        return wild ? number(random, 2, awkward) : random.nextDouble() * 0.3;
    }

    private static double kd(Random random, boolean wild, double awkward) {
        return wild ? number(random, 1.5, awkward) : random.nextDouble();
    }

    @Property(tries = 400, seed = "1202001")
    void aBatchLitTogetherEqualsEachPointLitAloneBitForBit(@ForAll long seed) {
        Random random = new Random(seed);
        double awkward = random.nextInt(3) * 0.1; // none, some, many
        Lights lights = new Lights();
        int lightCount = random.nextInt(4);
        for (int i = 0; i < lightCount; i++) {
            lights.add(number(random, 50, awkward), number(random, 50, awkward), number(random, 50, awkward),
                    Math.abs(number(random, 2, awkward)), Math.abs(number(random, 2, awkward)),
                    Math.abs(number(random, 2, awkward)), random.nextBoolean() ? 1 : Math.abs(number(random, 2, awkward)),
                    random.nextBoolean() ? 0 : Math.abs(number(random, 0.1, awkward)));
        }
        Lighting lighting = new Lighting(lights);
        double p = random.nextBoolean() ? EXPONENTS[random.nextInt(EXPONENTS.length)] : random.nextDouble() * 200;
        // The ambient light and kd now and then outside [0, 1], or awkward,
        // so that colours need clamping (also with the ambient term alone).
        boolean wild = random.nextInt(3) == 0;
        lighting.prepare(ambient(random, wild, awkward), ambient(random, wild, awkward),
                ambient(random, wild, awkward), random.nextDouble(), p, lightCount, random.nextBoolean());
        LitPoints points = new LitPoints(1 + random.nextInt(80));
        int count = 1 + random.nextInt(points.capacity());
        for (int i = 0; i < count; i++) {
            // Near a light now and then, so that P - light is tiny or zero.
            boolean atLight = lightCount > 0 && random.nextInt(10) == 0;
            double px = atLight ? lights.x(0) + number(random, 1e-80, awkward) : number(random, 40, awkward);
            double py = atLight ? lights.y(0) : number(random, 40, awkward);
            double pz = atLight ? lights.z(0) : -Math.abs(number(random, 100, awkward));
            points.add(px, py, pz, number(random, 1, awkward), number(random, 1, awkward),
                    number(random, 1, awkward), kd(random, wild, awkward), kd(random, wild, awkward),
                    kd(random, wild, awkward));
        }
        assertEachPointAsAlone(lighting, points);
    }

    @Test
    void theEdgeCasesOfLightingsJavadocInOneBatchAmongOrdinaryPoints() {
        Lights lights = new Lights();
        lights.add(0, 0, 0, 1, 1, 1, 1, 0);
        lights.add(3, 4, -5, 1e300, 1e300, 1e300, 0, 0); // huge intensity, zero attenuation
        lights.add(1e300, 1e300, -1e300, 0.5, 0.5, 0.5, 1, 0.01); // far away
        for (double p : EXPONENTS) {
            for (boolean perspective : new boolean[] {true, false}) {
                Lighting lighting = new Lighting(lights);
                lighting.prepare(0.1, 0.2, 0.3, 0.5, p, 3, perspective);
                LitPoints points = new LitPoints(32);
                points.add(1, 2, -10, 0, 0, 1, 0.5, 0.5, 0.5); // ordinary
                points.add(1, 2, -10, 0, 0, 0, 0.5, 0.5, 0.5); // zero normal
                points.add(1, 2, -10, 0, 0, 1e-300, 0.5, 0.5, 0.5); // tiny normal
                points.add(1, 2, -10, 0, 1e300, 1e300, 0.5, 0.5, 0.5); // huge normal
                points.add(3, 4, -5, 0, 0, 1, 0.5, 0.5, 0.5); // at the second light
                points.add(3 + 1e-200, 4, -5, -1, 0, 1, 0.5, 0.5, 0.5); // a hair from it
                points.add(0, 0, 0, 0, 0, 1, 0.5, 0.5, 0.5); // at the eye and the first light
                points.add(1e-200, 0, -1e-200, 0, 0, 1, 0.5, 0.5, 0.5); // a hair from the eye
                points.add(Double.NaN, 2, -10, 0, 0, 1, 0.5, 0.5, 0.5);
                points.add(1, Double.POSITIVE_INFINITY, -10, 0, 0, 1, 0.5, 0.5, 0.5);
                points.add(1, 2, -10, Double.NaN, 0, 1, 0.5, 0.5, 0.5);
                points.add(1, 2, -10, Double.NEGATIVE_INFINITY, 0, 1, 0.5, 0.5, 0.5);
                points.add(1, 2, -10, 0, 0, 1, Double.POSITIVE_INFINITY, 0.5, Double.NaN);
                points.add(-2, 1, -3, 0.3, 0.4, 0.9, 0.9, 0.1, 0.4); // ordinary, after them all
                assertEachPointAsAlone(lighting, points);
            }
        }
    }

    /**
     * Colours that need clamping, or just not: every awkward kd (and 0.5)
     * times ambient lights inside and outside [0, 1], -0 and NaN among them,
     * with no light (the ambient term alone) and with one.
     */
    @Test
    void coloursAtAndBeyondTheClampsBoundsAreLitAsAlone() {
        double[] ambients = {0.3, 1, 0, -0.0, -0.5, 2, 1e-300, Double.MAX_VALUE, Double.NaN};
        for (int lightCount = 0; lightCount <= 1; lightCount++) {
            Lights lights = new Lights();
            lights.add(0.3, -0.2, 0.1, 1, 1, 1, 1, 0.01);
            for (double ambient : ambients) {
                Lighting lighting = new Lighting(lights);
                lighting.prepare(ambient, 1 - ambient, 0.5, 0.5, 8, lightCount, true);
                LitPoints points = new LitPoints(AWKWARD.length + 1);
                for (double kd : AWKWARD) {
                    points.add(1, 2, -10, 0, 0.6, 0.8, kd, 0.5, -kd);
                }
                points.add(1, 2, -10, 0, 0.6, 0.8, 1 + 1e-16, Math.nextUp(1.0), Math.nextDown(0.0));
                assertEachPointAsAlone(lighting, points);
            }
        }
    }

    /**
     * The batch's length test (a sum of lengths and inverse lengths that
     * overflows) at the bounds of Lighting's: normals, eye distances and
     * light distances whose squared length is a hair inside or outside
     * [LOW, HIGH], each compared with the point lit alone.
     */
    @Test
    void lengthsAtTheBoundsOfTheUsualRangeAreLitAsAlone() {
        double[] squares = {Lighting.HIGH, Math.nextUp(Lighting.HIGH), Lighting.HIGH * 1.5, Lighting.HIGH / 4.5,
            Lighting.LOW, Math.nextDown(Lighting.LOW), Lighting.LOW / 1.5, Lighting.LOW * 4.5};
        for (double square : squares) {
            double length = Math.sqrt(square);
            for (boolean perspective : new boolean[] {true, false}) {
                Lights lights = new Lights();
                lights.add(0.3, -0.2, 0.1, 1, 1, 1, 1, 0.01);
                lights.add(length, 2, -10, 0.5, 0.5, 0.5, 1, 0); // |L| = length from the first point
                Lighting lighting = new Lighting(lights);
                lighting.prepare(0.1, 0.2, 0.3, 0.5, 8, 2, perspective);
                LitPoints points = new LitPoints(16);
                points.add(0, 2, -10, 1, 0, 0.2, 0.5, 0.5, 0.5); // the second light at |L| = length, reaching it
                points.add(1, 2, -10, 0, length * 0.6, length * 0.8, 0.5, 0.5, 0.5); // |N| = length
                points.add(length * 0.6, 0, -length * 0.8, 0.1, 0.2, 0.9, 0.5, 0.5, 0.5); // |E| = length
                points.add(-2, 1, -3, 0.3, 0.4, 0.9, 0.9, 0.1, 0.4); // ordinary
                assertEachPointAsAlone(lighting, points);
            }
        }
    }

    /**
     * The same once the JIT has compiled the batch's loops to packed
     * operations: a full batch of ordinary points with a few awkward ones
     * among them, lit many thousands of times, guessed unlit every other
     * time, checked all along.
     */
    @Test
    void compiledHotTheBatchStillEqualsEachPointAlone() {
        Random random = new Random(42);
        Lights lights = new Lights();
        lights.add(0, 0, 0, 1, 1, 1, 1, 0);
        lights.add(-8, 6, -4, 0.8, 0.6, 0.5, 1, 0.01);
        Lighting lighting = new Lighting(lights);
        lighting.prepare(0.2, 0.2, 0.2, 0.5, 16, 2, true);
        LitPoints points = new LitPoints(64);
        for (int i = 0; i < 64; i++) {
            points.add(number(random, 10, 0.05), number(random, 10, 0.05), -10 - random.nextDouble() * 4,
                    number(random, 0.3, 0.05), number(random, 0.3, 0.05), 1, 0.8, 0.6, 0.4);
        }
        for (int round = 0; round < 20_000; round++) {
            if (round % 1000 == 0) {
                assertEachPointAsAlone(lighting, points);
            } else {
                points.unlit = round % 2 == 1; // both ways compiled hot
                lighting.shade(points);
            }
        }
        assertEachPointAsAlone(lighting, points);
    }

    @Test
    void anEmptyBatchAndABatchWithNoLightAreLitToo() {
        Lights lights = new Lights();
        Lighting lighting = new Lighting(lights);
        lighting.prepare(0.25, 0.5, 1, 0.3, 8, 0, true);
        LitPoints points = new LitPoints(4);
        lighting.shade(points);
        assertEquals(0, points.count());
        points.add(1, 2, -3, 0, 0, 1, 0.5, 2, 0.7);
        assertEachPointAsAlone(lighting, points);
        assertEquals(0.125, points.red(0));
        assertEquals(1, points.green(0)); // 2 * 0.5, clamped
    }

    @Test
    void aBatchHoldsItsCapacityAndNoMore() {
        LitPoints points = new LitPoints(2);
        points.add(0, 0, -1, 0, 0, 1, 1, 1, 1);
        points.add(0, 0, -1, 0, 0, 1, 1, 1, 1);
        assertEquals(2, points.count());
        assertThrows(IllegalStateException.class, () -> points.add(0, 0, -1, 0, 0, 1, 1, 1, 1));
        assertThrows(IndexOutOfBoundsException.class, () -> points.red(2));
        points.clear();
        assertEquals(0, points.count());
        assertThrows(IndexOutOfBoundsException.class, () -> points.blue(0));
        assertThrows(IllegalArgumentException.class, () -> new LitPoints(0));
    }

    /**
     * Faces turned away from every light, as a cube's are: guessed unlit,
     * each point's own normal (a few ulps apart from the face's, or a hair
     * over the edge to the light, or tiny) and position, among points the
     * lights do reach, and a batch of them all alone.
     */
    @Test
    void aBatchGuessedUnlitGivesEachPointItsBitsWhereverTheLightsAre() {
        Random random = new Random(1205022);
        for (int trial = 0; trial < 200; trial++) {
            Lights lights = new Lights();
            int lightCount = 1 + random.nextInt(3);
            for (int i = 0; i < lightCount; i++) {
                lights.add(number(random, 20, 0), number(random, 20, 0), -30 - random.nextDouble() * 10, 1, 0.8, 0.6,
                        1, random.nextBoolean() ? 0 : 0.02);
            }
            Lighting lighting = new Lighting(lights);
            lighting.prepare(ambient(random, false, 0), ambient(random, false, 0), ambient(random, false, 0),
                    random.nextDouble(), EXPONENTS[random.nextInt(EXPONENTS.length)], lightCount, random.nextBoolean());
            LitPoints points = new LitPoints(64);
            int count = 1 + random.nextInt(64);
            boolean allAway = random.nextBoolean();
            for (int i = 0; i < count; i++) {
                double nz = 1 + Math.ulp(1.0) * random.nextInt(5);
                int kind = allAway ? 0 : random.nextInt(4);
                double nx = kind == 1 ? 3 : number(random, 1e-3, 0); // kind 1: turned to the side
                if (kind == 2) {
                    nz = -nz; // turned to the lights
                } else if (kind == 3) {
                    nz *= 1e-160; // tiny: Lighting rescales it
                    nx *= 1e-160;
                }
                points.add(number(random, 5, 0), number(random, 5, 0), -5 - random.nextDouble() * 10, nx,
                        number(random, 1e-3, 0) * (kind == 3 ? 1e-160 : 1), nz, kd(random, false, 0),
                        kd(random, false, 0), kd(random, false, 0));
            }
            assertEachPointAsAlone(lighting, points);
        }
        // A huge N whose N . L is 0 as given, and above 0 as Lighting rescales
        // it (by its largest part): lit, though the batch's own N . L says not.
        Lights one = new Lights();
        one.add(0, 0, 0, 1, 1, 1, 1, 0);
        Lighting lighting = new Lighting(one);
        lighting.prepare(0.1, 0.1, 0.1, 0.5, 8, 1, true);
        LitPoints points = new LitPoints(2);
        points.add(-6.425485839826166, 8.117399161206349, -8.260792656744275, 8.957307212181264e199,
                -2.10353007153653e199, -9.034271527463752e199, 0.5, 0.5, 0.5);
        points.add(-1, 2, -10, 0, 0, -1, 0.5, 0.5, 0.5); // turned away: unlit indeed
        assertEachPointAsAlone(lighting, points);
    }

    /**
     * Under an ambient light of zeros (+0 and -0), a batch guessed unlit that
     * no light reaches comes out +0 in every channel and says so
     * ({@link LitPoints#black}), kd outside [0, 1] and negative too; one with
     * a single point a light reaches, a NaN or infinite kd, or a normal that
     * Lighting rescales, is lit the usual way and says not; and under any
     * other ambient light none is black. Each point gets its bits alone.
     */
    @Test
    void underNoAmbientLightABatchNoLightReachesComesOutBlackAndSaysSo() {
        Lights lights = new Lights();
        lights.add(0, 0, 0, 8, 8, 12, 1, 0.2); // at the eye: a face turned to -z is turned from it
        double[][] ambients = {{0, 0, 0}, {-0.0, 0, -0.0}, {0, 0, 1e-300}, {0, Double.NaN, 0}};
        for (double[] ambient : ambients) {
            boolean none = ambient[2] == 0 && ambient[1] == 0;
            for (int odd = -1; odd < 5; odd++) {
                Lighting lighting = new Lighting(lights);
                lighting.prepare(ambient[0], ambient[1], ambient[2], 0.3, 8, 1, true);
                LitPoints points = new LitPoints(16);
                for (int i = 0; i < 12; i++) {
                    points.add(i - 6, 2, -10 - i, 0.01 * i, 0, -1, 0.2 * i, -0.5, 1e300);
                }
                switch (odd) {
                    case 0 -> points.add(1, 2, -10, 0, 0, 1, 0.5, 0.5, 0.5); // turned to the light
                    case 1 -> points.add(1, 2, -10, 0, 0, -1, 0.5, Double.NaN, 0.5);
                    case 2 -> points.add(1, 2, -10, 0, 0, -1, Double.NEGATIVE_INFINITY, 0.5, 0.5);
                    case 3 -> points.add(1, 2, -10, 0, 0, -1e-160, 0.5, 0.5, 0.5); // rescaled, still turned away
                    case 4 -> points.add(-6.425485839826166, 8.117399161206349, -8.260792656744275,
                            8.957307212181264e199, -2.10353007153653e199, -9.034271527463752e199, 0.5, 0.5, 0.5);
                    default -> { } // all turned away
                }
                points.unlit = true;
                points.black = !points.black; // whatever it was, the shading says
                lighting.shade(points);
                assertEquals(none && odd < 0, points.black, "ambient " + Arrays.toString(ambient)
                        + ", odd point " + odd);
                assertEachPointAsAlone(lighting, points);
            }
        }
    }

    /**
     * Lights the batch, then checks each point's colour against the point lit
     * alone, to the bit; then the same with the batch guessed unlit.
     */
    private static void assertEachPointAsAlone(Lighting lighting, LitPoints points) {
        for (boolean unlit : new boolean[] {false, true}) {
            points.unlit = unlit;
            lighting.shade(points);
            double[] alone = new double[3];
            for (int i = 0; i < points.count(); i++) {
                lighting.shade(points.px[i], points.py[i], points.pz[i], points.nx[i], points.ny[i], points.nz[i],
                        points.kdRed[i], points.kdGreen[i], points.kdBlue[i], alone, 0);
                double[] together = {points.red(i), points.green(i), points.blue(i)};
                for (int c = 0; c < 3; c++) {
                    assertEquals(Double.doubleToRawLongBits(alone[c]), Double.doubleToRawLongBits(together[c]),
                            "point " + i + " channel " + c + (unlit ? ", guessed unlit" : "") + ": alone " + alone[c]
                                    + ", in the batch " + together[c]);
                }
            }
        }
        points.unlit = false;
    }
}
