package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The vertex tables against numbers worked out by hand. */
class VertexTableTest {

    private static final double EPS = 1e-9;

    @TempDir
    Path dir;

    private Terms table(String scene, int x, int y) throws Exception {
        Path file = dir.resolve("t" + scene.hashCode() + ".simp");
        Files.writeString(file, scene);
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(file), x, y);
        HistoryEntry owner = report.lastWritten();
        assertNotNull(owner, "nothing drawn at (" + x + ", " + y + ")");
        return report.vertices(owner.primitive());
    }

    /**
     * The camera placed by translate 0 0 10 (so W moves z by -10), window
     * [-2, 2] x [-1, 1]: s = 650 / 4 = 162.5, the window 650 x 325 pixels,
     * 162.5 from the bottom. The triangle's CTM: translate 1 2 -20, scale 2.
     * Its vertex (1, 0, 0): world (3, 2, -20), camera (3, 2, -30), window
     * (0.1, 1/15), panel ((0.1 + 2) 162.5, 162.5 + (1/15 + 1) 162.5) =
     * (341.25, 335.8333...), pixel (341, 336).
     */
    @Test
    void aCameraAndACtm() throws Exception {
        Terms t = table("{\ntranslate 0 0 10\ncamera -2 -1 2 1 -1 -100\n}\n"
                + "{\ntranslate 1 2 -20\nscale 2 2 2\npolygon (0, 0, 0) (1, 0, 0) (0, 1, 0)\n}\n", 333, 338);
        assertArrayEquals(new double[] {2, 0, 0, 1}, t.terms("ctm").vector("row 1"), EPS);
        assertArrayEquals(new double[] {0, 0, 1, -10}, t.terms("world_to_camera").vector("row 3"), EPS);
        List<Terms> v = t.list("vertices");
        assertEquals(3, v.size());
        assertArrayEquals(new double[] {1, 0, 0}, v.get(1).vector("written"), EPS);
        assertArrayEquals(new double[] {3, 2, -20}, v.get(1).vector("world"), EPS);
        assertArrayEquals(new double[] {3, 2, -30}, v.get(1).vector("camera"), EPS);
        assertArrayEquals(new double[] {0.1, 1.0 / 15}, v.get(1).vector("window"), 1e-12);
        assertArrayEquals(new double[] {341.25, 162.5 + (1.0 / 15 + 1) * 162.5}, v.get(1).vector("panel"), 1e-9);
        assertArrayEquals(new int[] {341, 336}, v.get(1).bytes("pixel"));
        // vertex 0: world (1, 2, -20), camera (1, 2, -30): panel ((1/30 + 2) 162.5, 162.5 + (2/30 + 1) 162.5)
        assertArrayEquals(new double[] {(1.0 / 30 + 2) * 162.5, 162.5 + (2.0 / 30 + 1) * 162.5},
                v.get(0).vector("panel"), 1e-9);
        assertEquals("none: every vertex is inside the view", t.terms("clipping").get("cut_by"));
    }

    /**
     * Camera at the origin, window [-1, 1]^2, hither -5: the triangle
     * (0, 0, -2) (4, 0, -10) (0, 4, -10) has its first vertex nearer than
     * the near plane. Cut at z = -5 (t = 3/8 along both edges from it):
     * (1.5, 0, -5) and (0, 1.5, -5); (1.5, 0, -5) projects to
     * ((0.3 + 1) 325, 325) = (422.5, 325), (4, 0, -10) to (455, 325).
     */
    @Test
    void aClippedTriangle() throws Exception {
        Terms t = table("camera -1 -1 1 1 -5 -100\npolygon (0, 0, -2) (4, 0, -10) (0, 4, -10)\n", 380, 380);
        List<Terms> v = t.list("vertices");
        assertEquals("hither", v.get(0).get("outside"));
        assertEquals("none", v.get(1).get("outside"));
        assertArrayEquals(new double[] {455, 325}, v.get(1).vector("panel"), 1e-9);
        Terms clip = t.terms("clipping");
        assertEquals("hither", clip.get("cut_by"));
        List<double[]> out = new ArrayList<>();
        for (Terms o : clip.list("output")) {
            out.add(o.vector("camera"));
        }
        assertEquals(4, out.size());
        double[][] expected = {{1.5, 0, -5}, {0, 1.5, -5}, {4, 0, -10}, {0, 4, -10}};
        for (double[] e : expected) {
            assertTrue(out.stream().anyMatch(o -> Math.abs(o[0] - e[0]) < EPS && Math.abs(o[1] - e[1]) < EPS
                    && Math.abs(o[2] - e[2]) < EPS), "the clipper's output lacks " + Arrays.toString(e));
        }
        int found = 0;
        for (Terms o : clip.list("output")) {
            double[] c = o.vector("camera");
            if (Math.abs(c[0] - 1.5) < EPS && Math.abs(c[2] + 5) < EPS) {
                assertArrayEquals(new double[] {422.5, 325}, o.vector("panel"), 1e-9);
                found++;
            }
        }
        assertEquals(1, found);
    }

    /**
     * A vertex behind the eye, (0.5, 0.5, 2): x = 0.5 is both less than
     * xlow (-z) = 2 and more than xhigh (-z) = -2, so it is outside the left
     * and the right plane (and the bottom and the top), as well as hither.
     * The hither pass cuts it away, both new vertices inside the window
     * ((0.413, 0.413) and (0.694, 0.485) on it); the yon pass cuts
     * (20, -1, -300). So the clipper cut the triangle by hither and yon only,
     * though its vertices are outside every plane between them.
     */
    @Test
    void aTriangleIsCutByThePlanesThatChangedIt() throws Exception {
        Terms t = table("camera -1 -1 1 1 -1 -100\npolygon (0.5, 0.5, 2) (-1, -1, -50) (20, -1, -300)\n", 422, 406);
        List<Terms> v = t.list("vertices");
        assertEquals("hither, left, right, bottom, top", v.get(0).get("outside"));
        assertEquals("yon", v.get(2).get("outside"));
        Terms clip = t.terms("clipping");
        assertEquals("hither, yon", clip.get("cut_by"));
        assertEquals(5, clip.list("output").size());
    }

    /**
     * A line from camera (0, 0, -10) to (5, 2, -10): panel (325, 325) and
     * ((0.5 + 1) 325, (0.2 + 1) 325) = (487.5, 390), rounded (488, 390):
     * x-major, from (325, 325), 163 steps, slope 65 / 163, up and right.
     */
    @Test
    void aLinesDda() throws Exception {
        Terms t = table("camera -1 -1 1 1 -1 -100\nline (0, 0, -10) (5, 2, -10)\n", 400, 355);
        Terms dda = t.terms("dda");
        assertArrayEquals(new double[] {325, 325}, dda.vector("start_pixel"), 0);
        assertArrayEquals(new double[] {488, 390}, dda.vector("end_pixel"), 0);
        assertEquals("x", dda.get("major_axis"));
        assertArrayEquals(new int[] {1, 1}, dda.bytes("direction"));
        assertEquals(163, dda.number("steps"), 0);
        assertEquals(65.0 / 163, dda.number("slope"), EPS);
        // Pixel x 400 is step 75: y = 325 + 75 (65 / 163) = 354.91, as the slope is added 75 times; 355.
        Terms at = dda.terms("at_pixel");
        assertEquals(75, at.number("step"), 0);
        assertEquals(325 + 75 * 65.0 / 163, at.number("y"), 1e-9);
        assertEquals(355, at.number("rounds_to"), 0);
        assertEquals(true, at.get("steps_on_pixel"));
    }

    /**
     * A depth-cued wire triangle: world (-50, -50), (50, -50), (0, 50) land
     * at panel (162.5, 162.5), (487.5, 162.5), (325, 487.5). Pixel (300, 163)
     * is on edge 0-1 only (x-major from (163, 163), step 137); its corner
     * (163, 163) is where edges 0-1 and 2-0 both start.
     */
    @Test
    void aWirePolygonsEdgesAtThePixel() throws Exception {
        String scene = "wire\npolygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n";
        List<Terms> edges = table(scene, 300, 163).list("edges_at_pixel");
        assertEquals(1, edges.size());
        assertEquals("0-1", edges.get(0).get("edge"));
        Terms dda = edges.get(0).terms("dda");
        assertArrayEquals(new double[] {163, 163}, dda.vector("start_pixel"), 0);
        assertEquals(137, dda.terms("at_pixel").number("step"), 0);
        List<Terms> corner = table(scene, 163, 163).list("edges_at_pixel");
        assertEquals(List.of("0-1", "2-0"), corner.stream().map(e -> e.get("edge")).toList());
        assertEquals(0, corner.get(1).terms("dda").terms("at_pixel").number("step"), 0);
    }

    /** A depth-cued line drawn right to left starts at its left end and steps down: direction (1, -1). */
    @Test
    void aDepthCuedLine() throws Exception {
        // world (50, -20) -> panel 487.5, 260; world (-50, 20) -> 162.5, 390 (rounded 163, 390).
        Terms t = table("line (50, -20, -50) (-50, 20, -50)\n", 163, 390);
        Terms dda = t.terms("dda");
        assertArrayEquals(new double[] {163, 390}, dda.vector("start_pixel"), 0);
        assertArrayEquals(new double[] {488, 260}, dda.vector("end_pixel"), 0);
        assertArrayEquals(new int[] {1, -1}, dda.bytes("direction"));
        assertEquals(325, dda.number("steps"), 0);
        assertTrue(String.valueOf(t.get("clipping")).startsWith("none"));
    }

    /**
     * Where each vertex of the clipper's output comes from. The triangle
     * (0, 0, -2) (4, 0, -10) (0, 4, -10) with hither -5 is cut 3/8 of the
     * way from its first vertex along both its edges: (1.5, 0, -5) is 5/8 of
     * vertex 0 and 3/8 of vertex 1, on the hither plane; (4, 0, -10) is
     * vertex 1 as written.
     */
    @Test
    void theClippersVerticesSayWhereTheyComeFrom() throws Exception {
        Terms clip = table("camera -1 -1 1 1 -5 -100\npolygon (0, 0, -2) (4, 0, -10) (0, 4, -10)\n", 380, 380)
                .terms("clipping");
        Terms cut = byCamera(clip, 1.5, 0, -5);
        assertEquals("new, made by the clipper where the outline crosses the hither plane", cut.get("from"));
        assertArrayEquals(new double[] {5.0 / 8, 3.0 / 8, 0}, cut.vector("of_the_vertices"), EPS);
        Terms kept = byCamera(clip, 4, 0, -10);
        assertEquals("vertex 1, as written", kept.get("from"));
        assertEquals(null, kept.get("of_the_vertices"));
        assertNotNull(clip.get("new_vertices"));
    }

    /**
     * A floor from beside the eye into the distance, (-30, -5, -0.5)
     * (30, -5, -0.5) (0, -5, -60), window [-1, 1]^2, hither -1: the clipper
     * leaves a corner at (-5, -5, -5), on the left plane (x = z) and the
     * bottom one (y = z). Its shares a, b, c of the three vertices: c from
     * z, -0.5 (1 - c) - 60 c = -5, so c = 9/119; a - b from x, 30 (b - a) =
     * -5, so a - b = 1/6, a + b = 110/119.
     */
    @Test
    void aCornerOfTheViewIsOnTwoPlanes() throws Exception {
        Terms clip = table("camera -1 -1 1 1 -1 -100\npolygon (-30, -5, -0.5) (30, -5, -0.5) (0, -5, -60)\n",
                300, 100).terms("clipping");
        Terms corner = byCamera(clip, -5, -5, -5);
        assertEquals("new, made by the clipper where the outline crosses the left and bottom planes",
                corner.get("from"));
        double c = 9.0 / 119;
        double a = (110.0 / 119 + 1.0 / 6) / 2;
        assertArrayEquals(new double[] {a, 110.0 / 119 - a, c}, corner.vector("of_the_vertices"), EPS);
    }

    /**
     * A line from camera (0, 0, -10) to (20, 0, -10) leaves the window's
     * right side at x = 10, halfway: its new end is half of each end, at
     * panel (650, 325), and the DDA walks the clipped line, to (650, 325).
     */
    @Test
    void aClippedLinesNewEnd() throws Exception {
        Terms t = table("camera -1 -1 1 1 -1 -100\nline (0, 0, -10) (20, 0, -10)\n", 400, 325);
        Terms clip = t.terms("clipping");
        assertEquals("vertex 0, as written", clip.list("output").get(0).get("from"));
        Terms end = clip.list("output").get(1);
        assertEquals("new, made by the clipper where the line crosses the right plane", end.get("from"));
        assertArrayEquals(new double[] {0.5, 0.5}, end.vector("of_the_vertices"), EPS);
        assertArrayEquals(new double[] {650, 325}, t.terms("dda").vector("end_pixel"), 0);
    }

    private static Terms byCamera(Terms clip, double x, double y, double z) {
        for (Terms o : clip.list("output")) {
            double[] c = o.vector("camera");
            if (Math.abs(c[0] - x) < EPS && Math.abs(c[1] - y) < EPS && Math.abs(c[2] - z) < EPS) {
                return o;
            }
        }
        throw new AssertionError("the clipper's output lacks (" + x + ", " + y + ", " + z + ")");
    }
}
