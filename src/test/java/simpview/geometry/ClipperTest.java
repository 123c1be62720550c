package simpview.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The clipper against each plane of a camera, worked out by hand. */
class ClipperTest {

    private static final Camera EYE = Camera.perspective(-1, -1, 1, 1, -1, -100);
    private final Clipper clipper = new Clipper(4);

    /** A polygon of (x, y, z, a) vertices. */
    private static double[] polygon(double... xyza) {
        return xyza;
    }

    private int clip(Camera camera, double[] p) {
        return clipper.clipPolygon(camera, p, 0, p.length / 4);
    }

    private double at(int vertex, int number) {
        return clipper.vertices()[vertex * 4 + number];
    }

    /** Every vertex of the result lies inside every plane, up to rounding. */
    private void assertInside(Camera camera, int n) {
        for (int k = 0; k < n; k++) {
            for (int plane = 0; plane < Camera.PLANES; plane++) {
                double d = camera.distance(plane, at(k, 0), at(k, 1), at(k, 2));
                assertTrue(d >= -1e-9, "vertex " + k + " outside plane " + plane + " by " + d);
            }
        }
    }

    @Test
    void aTriangleInsideIsKeptAsItIs() {
        double[] p = polygon(0, 0, -10, 1, 1, 0, -10, 2, 0, 1, -10, 3);
        assertEquals(3, clip(EYE, p));
        for (int i = 0; i < p.length; i++) {
            assertEquals(p[i], clipper.vertices()[i]);
        }
    }

    @Test
    void aPolygonInsideIsReadFromTheCallersArrayAndAClippedOneFromTheClippers() {
        double[] inside = polygon(0, 0, -10, 1, 1, 0, -10, 2, 0, 1, -10, 3);
        assertEquals(3, clip(EYE, inside));
        assertSame(inside, clipper.vertices(), "nothing clipped: not copied");
        double[] cut = polygon(0, 0, 1, 10, 0, 0, -3, 30, 0.5, 0, -3, 30);
        int n = clip(EYE, cut);
        assertNotSame(cut, clipper.vertices());
        assertInside(EYE, n);
        // Starting elsewhere than 0, a polygon inside is copied, so that its vertices start at 0.
        double[] shifted = new double[4 + inside.length];
        System.arraycopy(inside, 0, shifted, 4, inside.length);
        assertEquals(3, clipper.clipPolygon(EYE, shifted, 4, 3));
        assertNotSame(shifted, clipper.vertices());
        for (int i = 0; i < inside.length; i++) {
            assertEquals(inside[i], clipper.vertices()[i]);
        }
        // A line is always the clipper's own.
        assertTrue(clipper.clipLine(EYE, inside, 0, 4));
        assertNotSame(inside, clipper.vertices());
    }

    @Test
    void theHitherPlaneCutsWithTheAttributeLerped() {
        // One vertex in front of the near plane z = -1: the edges to it are cut at z = -1.
        double[] p = polygon(0, 0, 1, 10, 0, 0, -3, 30, 0.5, 0, -3, 30);
        int n = clip(EYE, p);
        assertEquals(4, n);
        assertInside(EYE, n);
        // The walk starts from the last vertex: the first vertex out is replaced by two crossings.
        assertEquals(-1, at(0, 2), 1e-12);
        assertEquals(20, at(0, 3), 1e-12, "half way from 10 to 30, as z is half way from 1 to -3");
    }

    @Test
    void theYonPlaneCuts() {
        double[] p = polygon(0, 0, -50, 0, 0, 0, -150, 100, 1, 0, -50, 0);
        int n = clip(EYE, p);
        assertEquals(4, n);
        for (int k = 0; k < n; k++) {
            assertTrue(at(k, 2) >= -100 - 1e-9);
        }
        assertInside(EYE, n);
    }

    @Test
    void eachSidePlaneCutsThroughTheEye() {
        // A triangle at z = -10 whose one corner is beyond each side in turn: the window at z = -10 is +-10.
        double[][] corners = {{-30, 0}, {30, 0}, {0, -30}, {0, 30}};
        for (double[] c : corners) {
            double[] p = polygon(c[0], c[1], -10, 0, 0.5, 0.5, -10, 0, -0.5, 0.5, -10, 0);
            int n = clip(EYE, p);
            assertEquals(4, n, "corner " + c[0] + "," + c[1]);
            assertInside(EYE, n);
        }
    }

    @Test
    void aTriangleBehindTheEyeIsGone() {
        double[] p = polygon(0, 0, 5, 0, 1, 0, 5, 0, 0, 1, 5, 0);
        assertEquals(0, clip(EYE, p));
    }

    @Test
    void aPolygonEnclosingTheEyeKeepsTheWholeNearWindow() {
        // A huge square around the eye in the plane z = -1 - 1e-9 ... cut to the window's square.
        double z = -2;
        double[] p = polygon(-1000, -1000, z, 0, 1000, -1000, z, 0, 1000, 1000, z, 0, -1000, 1000, z, 0);
        int n = clip(EYE, p);
        assertEquals(4, n);
        assertInside(EYE, n);
        for (int k = 0; k < n; k++) {
            assertEquals(2, Math.abs(at(k, 0)), 1e-9, "x on the window's side at z = -2");
            assertEquals(2, Math.abs(at(k, 1)), 1e-9, "y on the window's side at z = -2");
        }
    }

    @Test
    void aTriangleThroughTheEyePlaneAndBothDepthPlanes() {
        // pageB's kind: from in front of the eye to beyond the far plane.
        double[] p = polygon(0.02, 0, 1, 0, 80, -40, -201, 0, 0, 80, -290, 0);
        Camera wide = Camera.perspective(-1, -1, 1, 1, -0.1, -200);
        int n = clipper.clipPolygon(wide, p, 0, 3);
        assertTrue(n >= 3);
        assertInside(wide, n);
    }

    /**
     * pageC's triangle: its vertex behind the eye is outside hither and, as the side planes cross behind the
     * eye, outside left, right, bottom and top too; the others are beyond yon. The hither pass takes that
     * vertex away and puts two new ones at z = -0.1, at window (0.2, 3.0), above the window, and (4.6, -2.2),
     * right of it and below; the right pass cuts the second away and leaves no vertex below the window, and
     * the top pass cuts the first. So the planes that cut it are hither, yon, right and top: not left, which
     * no vertex left after the hither pass is outside of, nor bottom.
     */
    @Test
    void thePlanesThatCutAPolygonAreThePassesThatChangedIt() {
        Camera wide = Camera.perspective(-1, -1, 1, 1, -0.1, -200);
        double[] p = polygon(0.02, 0, 1, 0, 0, 80, -290, 0, 80, -40, -201, 0);
        int n = clipper.clipPolygon(wide, p, 0, 3);
        assertEquals(5, n);
        assertEquals(1 << Camera.HITHER | 1 << Camera.YON | 1 << Camera.RIGHT | 1 << Camera.TOP, clipper.cutPlanes());
        for (int k = 0; k < n; k++) {
            assertTrue(wide.distance(Camera.LEFT, at(k, 0), at(k, 1), at(k, 2)) > 0
                    && wide.distance(Camera.BOTTOM, at(k, 0), at(k, 1), at(k, 2)) > 0,
                    "no vertex on the left or the bottom side: " + k);
        }
        assertEquals(3, clip(EYE, polygon(-1, -1, -5, 0, 1, -1, -5, 0, 0, 1, -5, 0)));
        assertEquals(0, clipper.cutPlanes(), "in view whole: nothing cut it");
        assertEquals(0, clip(EYE, polygon(15, 6, -10, 0, 6, 15, -10, 0, 14, 14, -10, 0)));
        assertEquals(1 << Camera.RIGHT | 1 << Camera.TOP, clipper.cutPlanes(), "clipped away whole by right, then top");
    }

    @Test
    void thePlanesThatCutALineAreThoseThatSetItsNewEnds() {
        // From behind the eye (outside hither, left, right, bottom, top) to inside: only hither sets the start.
        assertTrue(clipper.clipLine(EYE, new double[] {0.5, 0.5, 1, 0, 0, 0, -3, 0}, 0, 4));
        assertEquals(1 << Camera.HITHER, clipper.cutPlanes());
        // From the left of the view to beyond the far plane: left sets the start, yon the end.
        assertTrue(clipper.clipLine(EYE, new double[] {-20, 0, -10, 0, 0, 0, -300, 0}, 0, 4));
        assertEquals(1 << Camera.LEFT | 1 << Camera.YON, clipper.cutPlanes());
        assertTrue(clipper.clipLine(EYE, new double[] {0, 0, -5, 0, 1, 1, -6, 0}, 0, 4));
        assertEquals(0, clipper.cutPlanes());
        assertFalse(clipper.clipLine(EYE, new double[] {-50, 0, -10, 0, -20, 0, -10, 0}, 0, 4), "wholly left");
        assertEquals(1 << Camera.LEFT, clipper.cutPlanes());
    }

    @Test
    void theParallelViewClipsToItsBox() {
        double[] p = polygon(-150, 0, -100, 0, 150, 0, -100, 0, 0, 150, -100, 0);
        int n = clip(Camera.PARALLEL, p);
        assertInside(Camera.PARALLEL, n);
        assertEquals(6, n, "cut by the left, the right and the top side: a hexagon");
    }

    @Test
    void linesAreCutParametrically() {
        double[] p = {0, 0, 1, 0, 0, 0, -3, 40};
        assertTrue(clipper.clipLine(EYE, p, 0, 4));
        assertEquals(-1, at(0, 2), 1e-12);
        assertEquals(20, at(0, 3), 1e-12);
        assertEquals(-3, at(1, 2));
        assertEquals(40, at(1, 3));
        assertFalse(clipper.clipLine(EYE, new double[] {0, 0, 1, 0, 0, 0, 2, 0}, 0, 4), "wholly behind the eye");
        assertFalse(clipper.clipLine(EYE, new double[] {-50, 0, -10, 0, -20, 0, -10, 0}, 0, 4), "wholly left");
    }

    /**
     * Two triangles that share an edge crossing a plane walk it opposite ways (A to B, B to A): the crossing is
     * found from its inside end in both, so both clipped triangles hold the same vertex, to the bit, and meet
     * without a crack or an overlap. From the previous vertex, one found it from A and the other from B.
     */
    @Test
    void aSharedEdgeCrossesAtTheSameBitsWalkedEitherWay() {
        Random random = new Random(7);
        for (int i = 0; i < 200; i++) {
            double z = -2 - 40 * random.nextDouble();
            // A inside the window, B beyond its right side (x > -z); C below and D above the edge, both inside
            double[] a = {-z * (0.8 * random.nextDouble() - 0.4), -z * (0.2 * random.nextDouble() - 0.1), z, random.nextDouble()};
            double[] b = {-z * (1.2 + 3 * random.nextDouble()), -z * (0.2 * random.nextDouble() - 0.1), z - 3 * random.nextDouble(), random.nextDouble()};
            double[] c = {-z * 0.3 * random.nextDouble(), -z * (0.5 + 0.3 * random.nextDouble()), z, random.nextDouble()};
            double[] d = {-z * 0.3 * random.nextDouble(), -z * (0.5 + 0.3 * random.nextDouble()), z, random.nextDouble()};
            c[1] = -c[1];
            Clipper other = new Clipper(4);
            int n = clipper.clipPolygon(EYE, concat(a, b, c), 0, 3);
            int m = other.clipPolygon(EYE, concat(b, a, d), 0, 3);
            int shared = 0;
            for (int k = 0; k < n; k++) {
                for (int j = 0; j < m; j++) {
                    shared += Arrays.equals(Arrays.copyOfRange(clipper.vertices(), 4 * k, 4 * k + 4),
                            Arrays.copyOfRange(other.vertices(), 4 * j, 4 * j + 4)) ? 1 : 0;
                }
            }
            assertEquals(2, shared, "A and the crossing on A-B, in both, edge " + i);
        }
    }

    private static double[] concat(double[]... vertices) {
        double[] p = new double[4 * vertices.length];
        for (int k = 0; k < vertices.length; k++) {
            System.arraycopy(vertices[k], 0, p, 4 * k, 4);
        }
        return p;
    }

    /**
     * A vertex far outside (x = 1e20): the crossings are found from the ends nearer the plane, here the inside ones, so they land on the plane
     * where the edges cross it. From the outside end, a + t (b - a) with t = 1 - 1e-19, which rounds to 1, gave
     * the inside end itself: (0, 5, -10) twice, and a wrong diagonal edge.
     */
    @Test
    void aVertexFarOutsideIsCutWhereItsEdgesCrossThePlane() {
        Camera camera = Camera.perspective(-1, -1, 1, 1, -0.1, -200);
        double[] p = {-5, -5, -10, 0, 1e20, -5, -10, 1, 0, 5, -10, 0};
        int n = clipper.clipPolygon(camera, p, 0, 3);
        assertEquals(4, n);
        // From the last vertex: (0, 5) kept, then the edge to (-5, -5): inside, then the crossing from (-5, -5)
        // toward (1e20, -5) at x = 10, then the crossing from (0, 5) toward (1e20, -5) at x = 10, y just under 5.
        double[][] expected = {{-5, -5, -10, 0}, {10, -5, -10, 1.5e-19}, {10, 5, -10, 1e-19}, {0, 5, -10, 0}};
        for (int k = 0; k < 4; k++) {
            for (int i = 0; i < 4; i++) {
                assertEquals(expected[k][i], at(k, i), 1e-12, "vertex " + k + " number " + i);
            }
        }
        // A line drawn from the far end: its start is found from its inside end too.
        assertTrue(clipper.clipLine(camera, new double[] {1e20, -5, -10, 1, 0, 5, -10, 0}, 0, 4));
        assertEquals(10, at(0, 0), 1e-12);
        assertEquals(5, at(0, 1), 1e-12);
        assertEquals(1e-19, at(0, 3), 1e-30);
        assertEquals(0, at(1, 0));
        assertEquals(5, at(1, 1));
    }

    /**
     * A vertex far inside (z = -1e20, past the yon plane too) with the other end just in front of the hither
     * plane: the hither crossing is found from the near end, outside. From the inside end, t = 1 - 1e-20 rounds
     * to 1 and gave the far end itself: a line of 4 pixels on the wrong side of the centre, a polygon of none.
     */
    @Test
    void aVertexFarInsideIsCutWhereItsEdgesCrossThePlaneNearTheOtherEnd() {
        Camera camera = Camera.perspective(-1, -1, 1, 1, -1, -100);
        assertTrue(clipper.clipLine(camera, new double[] {0.1, 0.1, 10, 0, 0.1, 0.1, -1e20, 1}, 0, 4));
        // the start on the hither plane z = -1, 11 / (1e20 + 10) of the way; the end on the yon plane z = -100
        assertEquals(0.1, at(0, 0));
        assertEquals(0.1, at(0, 1));
        assertEquals(-1, at(0, 2), 1e-12);
        assertEquals(11 / (1e20 + 10), at(0, 3), 1e-30);
        assertEquals(0.1, at(1, 0));
        assertEquals(-100, at(1, 2), 1e-9);
        double[] p = {0.1, -0.1, 10, 0, 0.1, 0.1, -1e20, 1, -0.1, 0.1, -2, 0};
        int n = clipper.clipPolygon(camera, p, 0, 3);
        assertInside(camera, n);
        // the crossing of the edge from (0.1, -0.1, 10) to the far vertex with the hither plane
        boolean found = false;
        for (int k = 0; k < n; k++) {
            found |= Math.abs(at(k, 2) + 1) < 1e-12 && Math.abs(at(k, 0) - 0.1) < 1e-12
                    && Math.abs(at(k, 1) + 0.1) < 1e-12;
        }
        assertTrue(found, "no crossing at (0.1, -0.1, -1) among " + Arrays.toString(
                Arrays.copyOf(clipper.vertices(), 4 * n)));
    }

    @Test
    void aBigPolygonGrowsTheBuffers() {
        int n = 40;
        double[] p = new double[4 * n];
        for (int k = 0; k < n; k++) {
            double t = 2 * Math.PI * k / n;
            p[4 * k] = 25 * Math.cos(t);
            p[4 * k + 1] = 25 * Math.sin(t);
            p[4 * k + 2] = -20;
        }
        int kept = clipper.clipPolygon(EYE, p, 0, n);
        assertTrue(kept > 8, "the circle of radius 25 at z = -20 crosses the +-20 window on every side: " + kept);
        assertInside(EYE, kept);
    }

    @Test
    void insideIsEveryPlanesDistanceAtLeastZero() {
        Random random = new Random(11);
        double[] special = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0, -0.0, -1, 1, -100, 20};
        for (Camera camera : new Camera[] {EYE, Camera.PARALLEL}) {
            for (int i = 0; i < 20_000; i++) {
                double x = i % 7 == 0 ? special[random.nextInt(special.length)] : -150 + 300 * random.nextDouble();
                double y = i % 11 == 0 ? special[random.nextInt(special.length)] : -150 + 300 * random.nextDouble();
                double z = i % 13 == 0 ? special[random.nextInt(special.length)] : -250 + 260 * random.nextDouble();
                boolean everyPlane = true;
                for (int plane = 0; plane < Camera.PLANES; plane++) {
                    everyPlane &= camera.distance(plane, x, y, z) >= 0;
                }
                assertEquals(everyPlane, camera.inside(x, y, z), x + ", " + y + ", " + z);
            }
        }
    }
}
