package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The reference's clipper against the frustum of `camera -1 -1 1 1 -1 -100` and hand-worked crossings. */
class RefClipperTest {

    private static final RefView VIEW = RefView.camera(-1, -1, 1, 1, -1, -100);

    private static double[] v(double x, double y, double z, double colour) {
        return new double[] {x, y, z, colour};
    }

    /** The pass walks from the last vertex to the first: the crossing on edge v2-v0 comes out first. */
    @Test
    void aVertexBehindHitherIsCutInSpecOrder() {
        List<double[]> out = RefClipper.polygon(VIEW, List.of(v(0, 0, 1, 0), v(1, 0, -3, 1), v(-1, 0, -3, 1)));
        assertEquals(4, out.size());
        // v2 (-1, 0, -3) to v0 (0, 0, 1) crosses z = -1 half way, colour half way.
        assertArrayEquals(new double[] {-0.5, 0, -1, 0.5}, out.get(0), 1e-12);
        assertArrayEquals(new double[] {0.5, 0, -1, 0.5}, out.get(1), 1e-12);
        assertArrayEquals(new double[] {1, 0, -3, 1}, out.get(2), 1e-12);
        assertArrayEquals(new double[] {-1, 0, -3, 1}, out.get(3), 1e-12);
    }

    /** For each of the six planes, a triangle with one corner beyond it only: four corners, two on the plane. */
    @Test
    void eachPlaneCutsOffOneCorner() {
        double[][] beyond = {{0, 0, -0.5}, {0, 0, -150}, {-30, 0, -20}, {30, 0, -20}, {0, -30, -20}, {0, 30, -20}};
        for (int plane = 0; plane < RefClipper.PLANES; plane++) {
            double[] b = beyond[plane];
            List<double[]> in = List.of(v(b[0], b[1], b[2], 0), v(1, 1, -10, 0), v(-1, -1, -12, 0));
            List<double[]> out = RefClipper.polygon(VIEW, in);
            assertEquals(4, out.size(), "plane " + plane);
            int onPlane = 0;
            for (double[] p : out) {
                assertInside(p);
                onPlane += Math.abs(VIEW.inside(plane, p)) < 1e-9 ? 1 : 0;
            }
            assertEquals(2, onPlane, "plane " + plane);
        }
    }

    @Test
    void randomPolygonsComeOutInsideAndInsideOnesUntouched() {
        Random random = new Random(7);
        for (int i = 0; i < 2000; i++) {
            List<double[]> in = List.of(randomVertex(random), randomVertex(random), randomVertex(random));
            List<double[]> out = RefClipper.polygon(VIEW, in);
            out.forEach(RefClipperTest::assertInside);
            boolean allInside = in.stream().allMatch(p -> insideAll(p, 0));
            if (allInside) {
                assertEquals(in, out);
            }
        }
    }

    /** A triangle far larger than the window, around the line of sight: it is cut to the window's square. */
    @Test
    void aPolygonAroundTheLineOfSightIsCutToTheWindow() {
        List<double[]> out = RefClipper.polygon(VIEW, List.of(v(-1000, -1000, -50, 0), v(1000, -1000, -50, 0),
                v(0, 2000, -50, 0)));
        assertEquals(4, out.size());
        out.forEach(RefClipperTest::assertInside);
    }

    @Test
    void aLineFromBehindTheEyePastYonKeepsTheSegmentBetweenHitherAndYon() {
        double[][] cut = RefClipper.line(VIEW, v(0, 0, 10, 0), v(0, 0, -190, 1));
        assertArrayEquals(new double[] {0, 0, -1, 0.055}, cut[0], 1e-12);
        assertArrayEquals(new double[] {0, 0, -100, 0.55}, cut[1], 1e-12);
        assertNull(RefClipper.line(VIEW, v(5, 0, -2, 0), v(9, 0, -3, 0)), "wholly right of the window");
    }

    @Test
    void cullingNeedsEveryVertexBeyondOnePlane() {
        assertTrue(RefClipper.culled(VIEW, List.of(v(0, 0, 1, 0), v(1, 0, 2, 0), v(0, 1, 0.5, 0))));
        assertTrue(!RefClipper.culled(VIEW, List.of(v(0, 0, 1, 0), v(1, 0, -5, 0), v(0, 1, 0.5, 0))));
    }

    private static double[] randomVertex(Random random) {
        return v(random.nextDouble() * 200 - 100, random.nextDouble() * 200 - 100, random.nextDouble() * 220 - 160,
                random.nextDouble());
    }

    private static boolean insideAll(double[] p, double slack) {
        for (int plane = 0; plane < RefClipper.PLANES; plane++) {
            if (VIEW.inside(plane, p) < -slack) {
                return false;
            }
        }
        return true;
    }

    private static void assertInside(double[] p) {
        assertTrue(insideAll(p, 1e-9), () -> Arrays.toString(p) + " is outside");
    }
}
