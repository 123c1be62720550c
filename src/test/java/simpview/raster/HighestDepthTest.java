package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The bound a lit triangle is skipped by ({@link TriangleSetup#highestDepth})
 * is above every z a fragment sink computes at its pixels, and its box
 * ({@link TriangleSetup#firstColumn}, {@link TriangleSetup#lastColumn})
 * holds every pixel it covers: for triangles of every shape (slivers,
 * steep planes, over the panel's edges, a million pixels across), each pixel's z
 * computed as {@code FragmentStage} computes it from the spans the
 * rasterizer gives.
 */
class HighestDepthTest {

    private static final int SIZE = 150;
    private static final int CHANNELS = FragmentLayout.COLOUR_CHANNELS;
    private static final int STRIDE = FragmentLayout.stride(CHANNELS);

    /** Every covered pixel's z, as the fragment stage computes it, and its column. */
    private static final class Pixels implements FragmentSink {
        double highestZ = Double.NEGATIVE_INFINITY;
        int firstColumn = Integer.MAX_VALUE;
        int lastColumn = Integer.MIN_VALUE;
        int count;

        @Override
        public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
            double z0 = v0[FragmentLayout.Z];
            double dz = dv[FragmentLayout.Z];
            for (int x = from; x < to; x++) {
                int k = x - from;
                double inv = 1 / (q0 + k * dq);
                highestZ = Math.max(highestZ, (z0 + k * dz) * inv);
                count++;
            }
            firstColumn = Math.min(firstColumn, from);
            lastColumn = Math.max(lastColumn, to - 1);
        }

        @Override
        public void pixel(int x, int y, double q, double[] v) {
            throw new AssertionError("a polygon gives spans");
        }
    }

    /** A triangle's vertices: x, y, q and z times q (the other channels 0.5 times q). */
    private static double[] triangle(double[] x, double[] y, double[] q, double[] z) {
        double[] v = new double[3 * STRIDE];
        for (int k = 0; k < 3; k++) {
            v[k * STRIDE + FragmentLayout.X] = x[k];
            v[k * STRIDE + FragmentLayout.Y] = y[k];
            v[k * STRIDE + FragmentLayout.Q] = q[k];
            for (int c = 0; c < CHANNELS; c++) {
                v[k * STRIDE + FragmentLayout.CHANNEL + c] = (c == FragmentLayout.Z ? z[k] : 0.5) * q[k];
            }
        }
        return v;
    }

    private static double[] randomTriangle(Random random) {
        double[] x = new double[3];
        double[] y = new double[3];
        double scale = random.nextInt(4) == 0 ? 8 : SIZE + 60;
        double ox = random.nextDouble() * SIZE;
        double oy = random.nextDouble() * SIZE;
        for (int k = 0; k < 3; k++) {
            x[k] = ox + (random.nextDouble() - 0.5) * scale;
            y[k] = oy + (random.nextDouble() - 0.5) * scale;
        }
        if (random.nextInt(4) == 0) {
            return tightTriangle(random);
        }
        switch (random.nextInt(4)) {
            case 0 -> { // a sliver: the third vertex near the line of the first two
                double t = random.nextDouble() * 3 - 1;
                double off = (random.nextDouble() - 0.5) * Math.pow(10, -random.nextInt(6));
                x[2] = x[0] + t * (x[1] - x[0]) + off;
                y[2] = y[0] + t * (y[1] - y[0]) - off;
            }
            case 1 -> { // a million pixels across: coordinates far from the origin
                for (int k = 0; k < 3; k++) {
                    x[k] = ox + (random.nextDouble() - 0.5) * 2e6;
                    y[k] = oy + (random.nextDouble() - 0.5) * 2e6;
                }
            }
            default -> {
            }
        }
        double[] q = new double[3];
        double[] z = new double[3];
        boolean steep = random.nextBoolean();
        for (int k = 0; k < 3; k++) {
            q[k] = steep ? Math.pow(10, -3 * random.nextDouble()) : 0.1 + random.nextDouble() * 0.01;
            z[k] = steep ? -0.1 - random.nextDouble() * 200 : -20 - random.nextDouble() * 1e-9;
        }
        if (random.nextInt(5) == 0) {
            for (int k = 0; k < 3; k++) {
                z[k] = random.nextDouble() * 4 - 1; // z of either sign
            }
        }
        return triangle(x, y, q, z);
    }

    /**
     * A right triangle with its sides along the rows and columns and its
     * corners at pixel centres, one q at every corner: its nearest pixel is
     * a corner, where the bound leaves only its margin for the roundings.
     */
    private static double[] tightTriangle(Random random) {
        double x0 = random.nextInt(SIZE - 20) + 0.5;
        double y0 = random.nextInt(SIZE - 20) + 0.5;
        double w = 1 + random.nextInt(19);
        double h = 1 + random.nextInt(19);
        double qAll = 0.005 + random.nextDouble();
        double[] q = {qAll, qAll, qAll};
        double[] z = new double[3];
        for (int k = 0; k < 3; k++) {
            z[k] = -1 - random.nextDouble() * (random.nextBoolean() ? 1e-6 : 100);
        }
        boolean flip = random.nextBoolean();
        return triangle(new double[] {x0, x0 + w, flip ? x0 + w : x0}, new double[] {y0, y0, y0 + h}, q, z);
    }

    /** The triangle's bound, its set-up left in {@code setup}; null when it is degenerate. */
    private static Double bound(double[] v, TriangleSetup setup) {
        if (!setup.set(v, 0, STRIDE, 2 * STRIDE, FragmentLayout.X, FragmentLayout.Y)) {
            return null;
        }
        Plane q = new Plane();
        Plane zq = new Plane();
        setup.plane(q, v, FragmentLayout.Q);
        setup.plane(zq, v, FragmentLayout.CHANNEL + FragmentLayout.Z);
        return setup.highestDepth(q, zq);
    }

    @Test
    void everyPixelsZIsBelowTheBoundAndInTheBox() {
        Random random = new Random(1205020);
        int bounded = 0;
        int unbounded = 0;
        for (int i = 0; i < 4000; i++) {
            double[] v = randomTriangle(random);
            TriangleSetup setup = new TriangleSetup();
            Double bound = bound(v, setup);
            if (bound == null) {
                continue;
            }
            Pixels pixels = new Pixels();
            new LitPolygonRasterizer().fill(v, 3, CHANNELS, SIZE, SIZE, pixels);
            if (pixels.count == 0) {
                continue;
            }
            assertTrue(pixels.firstColumn >= setup.firstColumn(SIZE), "triangle " + i + ": first column in the box");
            assertTrue(pixels.lastColumn <= setup.lastColumn(SIZE), "triangle " + i + ": last column in the box");
            if (Double.isNaN(bound)) {
                unbounded++; // q's plane not positive over the whole box: no bound, never skipped
                continue;
            }
            assertTrue(pixels.highestZ <= bound, "triangle " + i + ": " + pixels.highestZ + " is below " + bound);
            bounded++;
        }
        assertTrue(bounded > 1000, bounded + " triangles bounded, " + unbounded + " not");
    }

    @Test
    void aTriangleFacingTheCameraIsBoundedByItsZAndTheMargin() {
        double[] v = triangle(new double[] {10.2, 90.7, 40.1}, new double[] {12.3, 20.9, 80.4},
                new double[] {0.25, 0.25, 0.25}, new double[] {-40, -40, -40});
        TriangleSetup setup = new TriangleSetup();
        double bound = bound(v, setup);
        assertTrue(bound >= -40 && bound < -40 + 1e-9, "bound " + bound);
        assertEquals(10, setup.firstColumn(SIZE));
        assertEquals(90, setup.lastColumn(SIZE));
    }

    @Test
    void aTriangleWhoseQIsNotPositiveHasNoBound() {
        double[] v = triangle(new double[] {10, 90, 40}, new double[] {12, 20, 80},
                new double[] {0.25, -0.25, 0.25}, new double[] {-40, -40, -40});
        assertTrue(Double.isNaN(bound(v, new TriangleSetup())));
    }
}
