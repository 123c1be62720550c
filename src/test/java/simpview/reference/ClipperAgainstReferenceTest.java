package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;
import simpview.geometry.Clipper;

/**
 * simpview's clipper against the reference's, vertex by vertex and in order
 * (SPEC Part 2, "Clipping"): the planes in the order hither, yon, left,
 * right, bottom, top, each pass walking the edges from the last vertex to the
 * first, every number of a new vertex lerped. The order decides the fan a
 * clipped polygon is filled as (from its first vertex), and so how a gouraud
 * polygon's colours spread over it; a picture's tolerance does not see that,
 * a vertex list does. Random polygons of 3 to 7 vertices and random lines,
 * through the eye plane and past every side, against random cameras and the
 * parallel view.
 */
class ClipperAgainstReferenceTest {

    private static final int STRIDE = 5;
    private static final int POLYGONS = 3000;

    private record View(Camera camera, RefView reference) {
    }

    private static View randomView(Random random) {
        if (random.nextInt(4) == 0) {
            return new View(Camera.PARALLEL, RefView.parallel());
        }
        double xlow = -0.2 - 2 * random.nextDouble();
        double ylow = -0.2 - 2 * random.nextDouble();
        double xhigh = 0.2 + 2 * random.nextDouble();
        double yhigh = 0.2 + 2 * random.nextDouble();
        double hither = -0.05 - 3 * random.nextDouble();
        double yon = hither - 5 - 200 * random.nextDouble();
        return new View(Camera.perspective(xlow, ylow, xhigh, yhigh, hither, yon),
                RefView.camera(xlow, ylow, xhigh, yhigh, hither, yon));
    }

    /** A vertex around the view: x, y, z, then two attributes. */
    private static double[] randomVertex(Random random, View view) {
        double[] v = new double[STRIDE];
        if (view.reference().perspective()) {
            v[2] = 20 - 260 * random.nextDouble();
            double reach = 3 * Math.max(1, Math.abs(v[2]));
            v[0] = reach * (2 * random.nextDouble() - 1);
            v[1] = reach * (2 * random.nextDouble() - 1);
        } else {
            v[0] = 300 * random.nextDouble() - 150;
            v[1] = 300 * random.nextDouble() - 150;
            v[2] = 100 - 400 * random.nextDouble();
        }
        v[3] = random.nextDouble();
        v[4] = 10 * random.nextDouble() - 5;
        return v;
    }

    @Test
    void polygonsComeOutAsTheReferencesVertexForVertexInOrder() {
        Random random = new Random(20261207);
        Clipper clipper = new Clipper(STRIDE);
        int cutBySeveralPlanes = 0;
        for (int i = 0; i < POLYGONS; i++) {
            View view = randomView(random);
            int n = 3 + random.nextInt(5);
            List<double[]> vertices = new ArrayList<>();
            double[] flat = new double[n * STRIDE];
            for (int k = 0; k < n; k++) {
                double[] v = randomVertex(random, view);
                vertices.add(v);
                System.arraycopy(v, 0, flat, k * STRIDE, STRIDE);
            }
            List<double[]> expected = RefClipper.polygon(view.reference(), vertices);
            int kept = clipper.clipPolygon(view.camera(), flat, 0, n);
            assertEquals(expected.size(), kept, "vertices left of polygon " + i);
            for (int k = 0; k < kept; k++) {
                assertSameVertex(expected.get(k), clipper.vertices(), k, "polygon " + i + ", vertex " + k);
            }
            cutBySeveralPlanes += Integer.bitCount(clipper.cutPlanes()) >= 2 && kept > 0 ? 1 : 0;
        }
        assertTrue(cutBySeveralPlanes > POLYGONS / 10, "polygons cut by two planes or more: " + cutBySeveralPlanes);
    }

    /** The new vertex the first pass (hither) makes comes out first when the last vertex is in and the first out. */
    @Test
    void aPolygonWhoseFirstVertexIsCutStartsWithTheCrossingOfItsLastEdge() {
        Camera eye = Camera.perspective(-1, -1, 1, 1, -1, -100);
        double[] p = {0, 0, 1, 0, 0, 1, 0, -3, 1, 1, -1, 0, -3, 1, 1};
        Clipper clipper = new Clipper(STRIDE);
        assertEquals(4, clipper.clipPolygon(eye, p, 0, 3));
        assertSameVertex(new double[] {-0.5, 0, -1, 0.5, 0.5}, clipper.vertices(), 0, "the crossing on the edge 2-0");
        assertSameVertex(new double[] {0.5, 0, -1, 0.5, 0.5}, clipper.vertices(), 1, "the crossing on the edge 0-1");
        assertSameVertex(new double[] {1, 0, -3, 1, 1}, clipper.vertices(), 2, "vertex 1");
        assertSameVertex(new double[] {-1, 0, -3, 1, 1}, clipper.vertices(), 3, "vertex 2");
    }

    @Test
    void linesComeOutAsTheReferencesEndForEnd() {
        Random random = new Random(71);
        Clipper clipper = new Clipper(STRIDE);
        for (int i = 0; i < POLYGONS; i++) {
            View view = randomView(random);
            double[] a = randomVertex(random, view);
            double[] b = randomVertex(random, view);
            double[] flat = new double[2 * STRIDE];
            System.arraycopy(a, 0, flat, 0, STRIDE);
            System.arraycopy(b, 0, flat, STRIDE, STRIDE);
            double[][] expected = RefClipper.line(view.reference(), a, b);
            boolean kept = clipper.clipLine(view.camera(), flat, 0, STRIDE);
            if (expected == null) {
                assertFalse(kept, "line " + i + " is clipped away by the reference");
            } else {
                assertTrue(kept, "line " + i + " keeps a part by the reference");
                assertSameVertex(expected[0], clipper.vertices(), 0, "line " + i + ", start");
                assertSameVertex(expected[1], clipper.vertices(), 1, "line " + i + ", end");
            }
        }
    }

    /** Equal up to rounding: within 1e-9 of the larger magnitude involved, every number. */
    private static void assertSameVertex(double[] expected, double[] actual, int k, String what) {
        for (int i = 0; i < STRIDE; i++) {
            double e = expected[i];
            double a = actual[k * STRIDE + i];
            assertEquals(e, a, 1e-9 * Math.max(1, Math.max(Math.abs(e), Math.abs(a))), what + ", number " + i);
        }
    }
}
