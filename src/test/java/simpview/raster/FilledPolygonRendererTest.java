package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.surface.Colors;
import simpview.testing.CountingDrawable;

class FilledPolygonRendererTest {

    private final FilledPolygonRenderer filled = new FilledPolygonRenderer();

    @Test
    void theCentroidPixelHasTheAverageOfTheVertexColours() {
        // Centroid (60.5, 50.5) is the centre of pixel (60, 50).
        Vertex red = new Vertex(10.5, 10.5, -10, 1, 0, 0);
        Vertex green = new Vertex(110.5, 10.5, -20, 0, 1, 0);
        Vertex blue = new Vertex(60.5, 130.5, -30, 0, 0, 1);
        CountingDrawable d = new CountingDrawable(200, 200);
        filled.drawPolygon(red, green, blue, d);
        int c = d.getPixel(60, 50);
        for (int channel : new int[] {Colors.red(c), Colors.green(c), Colors.blue(c)}) {
            assertEquals(85, channel, 1, "255/3 in every channel, got " + Integer.toHexString(c));
        }
        assertEquals(-20, d.depth(60, 50), 1e-9);
    }

    @Test
    void aPixelBesideAVertexHasThatVertexColourWithinOneLevel() {
        // Pixel (20, 20)'s centre lies inside, half a pixel from vertex a in x and y.
        Vertex a = new Vertex(20, 20, 0, 0.2, 0.4, 0.6);
        Vertex b = new Vertex(180, 30, 0, 1, 1, 1);
        Vertex c = new Vertex(40, 170, 0, 0, 0, 0);
        CountingDrawable d = new CountingDrawable(200, 200);
        filled.drawPolygon(a, b, c, d);
        int got = d.getPixel(20, 20);
        int expected = Colors.pack(0.2, 0.4, 0.6);
        assertEquals(Colors.red(expected), Colors.red(got), 1);
        assertEquals(Colors.green(expected), Colors.green(got), 1);
        assertEquals(Colors.blue(expected), Colors.blue(got), 1);
    }

    /**
     * A square whose edges run through pixel centres, split on its diagonal.
     * Top-left rule (y up): the left column and the top row are in, the right
     * column and the bottom row are out, and the diagonal goes to one triangle.
     */
    @Test
    void topLeftRuleOnASquareSplitIntoTwoTriangles() {
        Vertex p00 = Vertex.of(10.5, 10.5, 0);
        Vertex p10 = Vertex.of(20.5, 10.5, 0);
        Vertex p11 = Vertex.of(20.5, 20.5, 0);
        Vertex p01 = Vertex.of(10.5, 20.5, 0);
        CountingDrawable d = new CountingDrawable(40, 40);
        filled.drawPolygon(p00, p10, p11, d);
        filled.drawPolygon(p00, p11, p01, d);
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 40; x++) {
                boolean expected = x >= 10 && x <= 19 && y >= 11 && y <= 20;
                assertEquals(expected ? 1 : 0, d.count(x, y), "pixel " + x + "," + y);
            }
        }
        assertEquals(100, d.writes());
    }

    @Test
    void trianglesSharingAnEdgeWriteEveryPixelOfTheirUnionExactlyOnce() {
        Random random = new Random(7);
        for (int trial = 0; trial < 500; trial++) {
            Vertex shared1 = randomVertex(random);
            Vertex shared2 = randomVertex(random);
            Vertex left = randomVertex(random);
            Vertex right = randomVertex(random);
            if (side(shared1, shared2, left) * side(shared1, shared2, right) >= 0) {
                continue; // both on one side: they would overlap, not share
            }
            CountingDrawable together = new CountingDrawable(64, 64);
            filled.drawPolygon(shared1, shared2, left, together);
            filled.drawPolygon(shared2, shared1, right, together);
            assertTrue(together.maxCount() <= 1, "a pixel written twice in trial " + trial);
            CountingDrawable first = new CountingDrawable(64, 64);
            CountingDrawable second = new CountingDrawable(64, 64);
            filled.drawPolygon(shared1, shared2, left, first);
            filled.drawPolygon(shared1, shared2, right, second);
            assertEquals(first.writes() + second.writes(), together.covered(), "trial " + trial);
        }
    }

    @Test
    void aSharedEdgeThroughPixelCentresLeavesNoGap() {
        // A fan of triangles around a centre on a pixel centre: every spoke passes through centres.
        CountingDrawable d = new CountingDrawable(100, 100);
        double cx = 50.5;
        double cy = 50.5;
        double[][] ring = {{80, 0}, {30, 30}, {0, 40}, {-30, 30}, {-40, 0}, {-20, -20}, {0, -40}, {30, -30}};
        for (int k = 0; k < ring.length; k++) {
            double[] p = ring[k];
            double[] q = ring[(k + 1) % ring.length];
            filled.drawPolygon(Vertex.of(cx, cy, 0), Vertex.of(cx + p[0] / 2, cy + p[1] / 2, 0),
                    Vertex.of(cx + q[0] / 2, cy + q[1] / 2, 0), d);
        }
        assertEquals(1, d.maxCount());
        assertEquals(1, d.count(50, 50), "the shared centre is drawn exactly once");
        for (int x = 40; x <= 60; x++) {
            assertEquals(1, d.count(x, 50), "row through the centre, x = " + x);
        }
    }

    @Test
    void degenerateTrianglesDrawNothing() {
        CountingDrawable d = new CountingDrawable(100, 100);
        filled.drawPolygon(Vertex.of(10.5, 10.5, 0), Vertex.of(50.5, 50.5, 0), Vertex.of(90.5, 90.5, 0), d);
        filled.drawPolygon(Vertex.of(10, 20, 0), Vertex.of(10, 20, 0), Vertex.of(10, 20, 0), d);
        filled.drawPolygon(Vertex.of(10.5, 5, 0), Vertex.of(10.5, 50, 0), Vertex.of(10.5, 90, 0), d);
        assertEquals(0, d.writes());
    }

    @Test
    void windingDoesNotMatter() {
        Vertex a = new Vertex(3.3, 4.1, -5, 1, 0, 0);
        Vertex b = new Vertex(57.9, 12.2, -6, 0, 1, 0);
        Vertex c = new Vertex(22.7, 49.5, -7, 0, 0, 1);
        CountingDrawable ccw = new CountingDrawable(64, 64);
        CountingDrawable cw = new CountingDrawable(64, 64);
        filled.drawPolygon(a, b, c, ccw);
        filled.drawPolygon(a, c, b, cw);
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 64; x++) {
                assertEquals(ccw.count(x, y), cw.count(x, y));
                assertEquals(ccw.getPixel(x, y), cw.getPixel(x, y));
            }
        }
    }

    @Test
    void coverageIsExactlyThePixelCentresInside() {
        Random random = new Random(11);
        for (int trial = 0; trial < 200; trial++) {
            Vertex a = randomVertex(random);
            Vertex b = randomVertex(random);
            Vertex c = randomVertex(random);
            CountingDrawable d = new CountingDrawable(64, 64);
            filled.drawPolygon(a, b, c, d);
            for (int y = 0; y < 64; y++) {
                for (int x = 0; x < 64; x++) {
                    double s1 = side(a, b, x + 0.5, y + 0.5);
                    double s2 = side(b, c, x + 0.5, y + 0.5);
                    double s3 = side(c, a, x + 0.5, y + 0.5);
                    boolean strictlyInside = (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
                    boolean strictlyOutside = (s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0);
                    if (strictlyInside) {
                        assertEquals(1, d.count(x, y), "inside pixel " + x + "," + y + " trial " + trial);
                    } else if (strictlyOutside) {
                        assertEquals(0, d.count(x, y), "outside pixel " + x + "," + y + " trial " + trial);
                    }
                }
            }
        }
    }

    @Test
    void aHugeTriangleOnlyVisitsThePixelsOfTheSurface() {
        CountingDrawable d = new CountingDrawable(650, 650);
        filled.drawPolygon(Vertex.of(-1e12, -1e12, 0), Vertex.of(1e12, -1e12, 0), Vertex.of(0, 1e12, 0), d);
        assertEquals(650 * 650, d.writes());
        assertEquals(0, d.strays());
    }

    private static Vertex randomVertex(Random random) {
        // Quarter-pixel grid so that edges often pass exactly through pixel centres.
        return new Vertex(random.nextInt(256) / 4.0, random.nextInt(256) / 4.0, -random.nextInt(200),
                random.nextDouble(), random.nextDouble(), random.nextDouble());
    }

    private static double side(Vertex a, Vertex b, Vertex p) {
        return side(a, b, p.x(), p.y());
    }

    private static double side(Vertex a, Vertex b, double px, double py) {
        return (b.x() - a.x()) * (py - a.y()) - (b.y() - a.y()) * (px - a.x());
    }
}
