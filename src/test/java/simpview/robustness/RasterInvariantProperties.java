package simpview.robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Assume;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.statistics.Statistics;
import simpview.geometry.Vertex;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.raster.FilledPolygonRenderer;
import simpview.testing.CountingDrawable;

/**
 * Invariants of the filled renderer over many triangles at once: a
 * triangulation covers its rectangle exactly once per pixel, and with
 * distinct depths the z-buffered picture does not depend on drawing order.
 */
class RasterInvariantProperties {

    static final int W = 83;
    static final int H = 67;

    private final FilledPolygonRenderer filled = new FilledPolygonRenderer();

    /** A rectangle and a triangulation of it; coordinates on a 1/4 grid, so every orientation test is exact. */
    record Mesh(double x0, double y0, double x1, double y1, List<double[]> points, List<int[]> triangles) {
        Vertex vertex(int i, double z) {
            double[] p = points.get(i);
            return Vertex.of(p[0], p[1], z);
        }

        @Override
        public String toString() {
            StringBuilder sb = new StringBuilder("rectangle [" + x0 + "," + x1 + "]x[" + y0 + "," + y1 + "] triangles");
            for (int[] t : triangles) {
                sb.append(" (");
                for (int k = 0; k < 3; k++) {
                    double[] p = points.get(t[k]);
                    sb.append(k > 0 ? " " : "").append(p[0]).append(',').append(p[1]);
                }
                sb.append(')');
            }
            return sb.toString();
        }
    }

    @Provide
    Arbitrary<Mesh> meshes() {
        // Rectangle sides on the quarter grid: through pixel centres (.5), corners (.0) and between.
        Arbitrary<Integer> qx = Arbitraries.integers().between(-12, W * 4 + 12);
        Arbitrary<Integer> qy = Arbitraries.integers().between(-12, H * 4 + 12);
        return Combinators.combine(qx, qx, qy, qy, Arbitraries.integers().between(3, 40),
                Arbitraries.integers().between(0, 60), Arbitraries.longs())
                .filter((ax, bx, ay, by, n, flips, seed) -> Math.abs(ax - bx) >= 2 && Math.abs(ay - by) >= 2)
                .as((ax, bx, ay, by, n, flips, seed) -> triangulate(Math.min(ax, bx) / 4.0, Math.min(ay, by) / 4.0,
                        Math.max(ax, bx) / 4.0, Math.max(ay, by) / 4.0, n, flips, new Random(seed)));
    }

    /**
     * Starts from the rectangle split on a diagonal, inserts points (inside a
     * triangle: split it in three; on an edge, the rectangle's sides included:
     * split the one or two triangles there in two), then flips random edges
     * whose quadrilateral is strictly convex. Every step keeps a
     * triangulation without overlaps or T-junctions.
     */
    static Mesh triangulate(double x0, double y0, double x1, double y1, int n, int flips, Random random) {
        List<double[]> pts = new ArrayList<>();
        pts.add(new double[] {x0, y0});
        pts.add(new double[] {x1, y0});
        pts.add(new double[] {x1, y1});
        pts.add(new double[] {x0, y1});
        List<int[]> tris = new ArrayList<>();
        tris.add(new int[] {0, 1, 2});
        tris.add(new int[] {0, 2, 3});
        int qx0 = (int) Math.round(x0 * 4);
        int qy0 = (int) Math.round(y0 * 4);
        int qw = (int) Math.round((x1 - x0) * 4);
        int qh = (int) Math.round((y1 - y0) * 4);
        for (int k = 0; k < n; k++) {
            // Half the points snap to the rectangle's sides or to pixel centres, where ties happen.
            double px = (qx0 + random.nextInt(qw + 1)) / 4.0;
            double py = (qy0 + random.nextInt(qh + 1)) / 4.0;
            switch (random.nextInt(4)) {
                case 0:
                    px = random.nextBoolean() ? x0 : x1;
                    break;
                case 1:
                    py = random.nextBoolean() ? y0 : y1;
                    break;
                default:
                    break;
            }
            insert(pts, tris, px, py);
        }
        for (int k = 0; k < flips && tris.size() > 1; k++) {
            flipRandomEdge(pts, tris, random);
        }
        return new Mesh(x0, y0, x1, y1, pts, tris);
    }

    private static int orient(List<double[]> pts, int a, int b, double px, double py) {
        double[] p = pts.get(a);
        double[] q = pts.get(b);
        return Hostile.orientation(p[0], p[1], q[0], q[1], px, py);
    }

    /** Triangles are kept counter-clockwise. */
    private static void insert(List<double[]> pts, List<int[]> tris, double px, double py) {
        for (double[] p : pts) {
            if (p[0] == px && p[1] == py) {
                return;
            }
        }
        for (int i = 0; i < tris.size(); i++) {
            int[] t = tris.get(i);
            int[] o = new int[3];
            for (int e = 0; e < 3; e++) {
                o[e] = orient(pts, t[e], t[(e + 1) % 3], px, py);
            }
            if (o[0] < 0 || o[1] < 0 || o[2] < 0) {
                continue;
            }
            int p = pts.size();
            pts.add(new double[] {px, py});
            if (o[0] > 0 && o[1] > 0 && o[2] > 0) {
                tris.remove(i);
                tris.add(new int[] {t[0], t[1], p});
                tris.add(new int[] {t[1], t[2], p});
                tris.add(new int[] {t[2], t[0], p});
                return;
            }
            // On edge e (exactly one zero: the point is no vertex): split this triangle and its neighbour there.
            int e = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
            int a = t[e];
            int b = t[(e + 1) % 3];
            splitAtEdge(tris, a, b, p);
            splitAtEdge(tris, b, a, p);
            return;
        }
        throw new AssertionError("point " + px + "," + py + " lies in no triangle: the mesh is broken");
    }

    /** The triangle holding directed edge a->b becomes two, meeting at p on that edge. */
    private static void splitAtEdge(List<int[]> tris, int a, int b, int p) {
        for (int i = 0; i < tris.size(); i++) {
            int[] t = tris.get(i);
            for (int e = 0; e < 3; e++) {
                if (t[e] == a && t[(e + 1) % 3] == b) {
                    int c = t[(e + 2) % 3];
                    tris.remove(i);
                    tris.add(new int[] {a, p, c});
                    tris.add(new int[] {p, b, c});
                    return;
                }
            }
        }
    }

    private static void flipRandomEdge(List<double[]> pts, List<int[]> tris, Random random) {
        int i = random.nextInt(tris.size());
        int[] t = tris.get(i);
        int e = random.nextInt(3);
        int a = t[e];
        int b = t[(e + 1) % 3];
        int c = t[(e + 2) % 3];
        for (int j = 0; j < tris.size(); j++) {
            int[] u = tris.get(j);
            for (int f = 0; f < 3; f++) {
                if (u[f] == b && u[(f + 1) % 3] == a) {
                    int d = u[(f + 2) % 3];
                    double[] pa = pts.get(a);
                    double[] pb = pts.get(b);
                    // Convex iff c-d crosses a-b properly.
                    if (orient(pts, c, d, pa[0], pa[1]) * orient(pts, c, d, pb[0], pb[1]) < 0) {
                        tris.set(i, new int[] {c, a, d});
                        tris.set(j, new int[] {d, b, c});
                    }
                    return;
                }
            }
        }
    }

    @Property(tries = 600, seed = "5150")
    void aTriangulatedRectangleWritesEachPixelInsideItExactlyOnce(@ForAll("meshes") Mesh mesh,
            @ForAll boolean reverseWinding) {
        int n = mesh.triangles().size();
        Statistics.label("triangles").collect(n <= 2 ? "2" : n <= 10 ? "3-10" : n <= 40 ? "11-40" : "41+");
        CountingDrawable d = new CountingDrawable(W, H);
        double area = 0;
        for (int[] t : mesh.triangles()) {
            Vertex a = mesh.vertex(t[0], -1);
            Vertex b = mesh.vertex(t[1], -1);
            Vertex c = mesh.vertex(t[2], -1);
            area += ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x())) / 2;
            if (reverseWinding) {
                filled.drawPolygon(a, c, b, d);
            } else {
                filled.drawPolygon(a, b, c, d);
            }
        }
        assertEquals((mesh.x1() - mesh.x0()) * (mesh.y1() - mesh.y0()), area, 1e-9,
                "the generated triangles do not tile the rectangle: " + mesh);
        assertEquals(0, d.strays());
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double cx = x + 0.5;
                double cy = y + 0.5;
                // Top-left rule on the rectangle (y up): its left and top sides are in, right and bottom out.
                boolean in = mesh.x0() <= cx && cx < mesh.x1() && mesh.y0() < cy && cy <= mesh.y1();
                if (d.count(x, y) != (in ? 1 : 0)) {
                    fail("pixel " + x + "," + y + " written " + d.count(x, y) + " times, expected " + (in ? 1 : 0)
                            + " (" + mesh.triangles().size() + " triangles): " + mesh);
                }
            }
        }
    }

    /**
     * Overlapping triangles, each in its own depth band (no two ever tie at a
     * pixel, even tilted): the z-buffered, depth-cued picture is the same in
     * any drawing order.
     */
    @Property(tries = 150, seed = "8086")
    void withDistinctDepthsTheZBufferedImageIgnoresDrawingOrder(@ForAll("layers") List<Vertex[]> triangles,
            @ForAll long shuffleSeed, @ForAll boolean cued) {
        List<Vertex[]> shuffled = new ArrayList<>(triangles);
        Collections.shuffle(shuffled, new Random(shuffleSeed));
        PageCanvas first = new PageCanvas();
        PageCanvas second = new PageCanvas();
        Drawable a = cued ? first.depthCued(new Rgb(1, 0.5, 0.25), Rgb.BLACK) : first.depthTested();
        Drawable b = cued ? second.depthCued(new Rgb(1, 0.5, 0.25), Rgb.BLACK) : second.depthTested();
        for (Vertex[] t : triangles) {
            filled.drawPolygon(t[0], t[1], t[2], a);
        }
        for (Vertex[] t : shuffled) {
            filled.drawPolygon(t[0], t[1], t[2], b);
        }
        int[] pa = GeometryFuzzProperties.pixels(first);
        int[] pb = GeometryFuzzProperties.pixels(second);
        int differing = 0;
        for (int i = 0; i < pa.length; i++) {
            differing += (pa[i] & 0xFFFFFF) != (pb[i] & 0xFFFFFF) ? 1 : 0;
        }
        assertEquals(0, differing, "pixels that differ between the two drawing orders");
        boolean anyDrawn = false;
        for (int i = 0; i < pa.length && !anyDrawn; i++) {
            anyDrawn = (pa[i] & 0xFFFFFF) != 0xFFFFFF && (pa[i] & 0xFFFFFF) != 0;
        }
        // Degenerate edge cases draw nothing; such a try says nothing, so it does not count as a check.
        Assume.that(anyDrawn);
    }

    @Provide
    Arbitrary<List<Vertex[]>> layers() {
        Arbitrary<Double> c = Arbitraries.doubles().between(-50, 700).ofScale(3);
        Arbitrary<Double> tilt = Arbitraries.doubles().between(-0.45, 0.45).ofScale(4);
        Arbitrary<Double> ch = Arbitraries.doubles().between(0, 1).ofScale(3);
        Arbitrary<double[]> raw = Combinators.combine(List.of(c, c, c, c, c, c, tilt, tilt, tilt, ch, ch, ch))
                .as(l -> l.stream().mapToDouble(Double::doubleValue).toArray());
        return raw.list().ofMinSize(2).ofMaxSize(12).map(list -> {
            List<Vertex[]> out = new ArrayList<>();
            for (int i = 0; i < list.size(); i++) {
                double[] r = list.get(i);
                // Band i: z within 0.45 of -190 + 15 i, so bands never meet.
                double z = -190 + 15 * i;
                out.add(new Vertex[] {new Vertex(r[0], r[1], z + r[6], r[9], r[10], r[11]),
                    new Vertex(r[2], r[3], z + r[7], r[10], r[11], r[9]),
                    new Vertex(r[4], r[5], z + r[8], r[11], r[9], r[10])});
            }
            return out;
        });
    }
}
