package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Camera;

/**
 * Hand-made lit scenes whose answers are worked out here: a triangle cut by
 * the far plane lists "clipped" (cut by yon) at a pixel its cut-away part
 * would have covered and "written" where its drawn part is; a triangle
 * nearer than the near plane with a vertex behind the eye is "culled" (by
 * hither) where its part in front of the eye projects, and not elsewhere; a
 * gouraud triangle cut by the near plane is explained by its own three lit
 * vertex colours and the pixel's weights against them, found here from the
 * pixel's ray and the triangle's plane.
 *
 * <p>The camera -1 -1 1 1 -1 -100 maps window (wx, wy) in [-1, 1] to panel
 * (wx + 1) 325: pixel x's centre is wx = (x + 0.5) / 325 - 1.
 */
class ClippedHistoryTest {

    private static final String CAMERA = "camera -1 -1 1 1 -1 -100\n";

    @TempDir
    Path dir;

    private final PixelInspector inspector = new PixelInspector();

    private InspectedScene scene(String name, String text) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, text);
        return InspectedScene.of(file);
    }

    @Test
    void aTriangleCutByTheFarPlane() throws Exception {
        // Base at z = -50 (window y -0.2, x -0.2 to 0.2), apex at z = -200 (window (0, 0.05)). The far plane
        // z = -100 cuts it a third of the way up: there y = -10/3 and x = +-20/3, window y -1/30, x +-1/15.
        InspectedScene s = scene("yon.simp", CAMERA + "polygon (-10, -10, -50) (10, -10, -50) (0, 10, -200)\n");
        // Window (-0.0015, -0.0015): above the cut (y > -1/30), inside the projected triangle (its half width
        // at y = 0 is 0.2 * 0.05 / 0.25 = 0.04).
        PixelReport beyond = inspector.inspect(s, 324, 324);
        assertEquals(1, beyond.history().size(), beyond.text(true, false));
        HistoryEntry e = beyond.history().get(0);
        assertEquals(Outcome.CLIPPED, e.outcome());
        assertEquals(0, e.primitive(), "it was drawn (elsewhere): it has its number");
        assertEquals(List.of("yon"), e.planeNames());
        assertTrue(beyond.json(true, false).contains("\"outcome\": \"clipped\", \"cut_by\": [\"yon\"]"),
                beyond.json(true, false));
        assertTrue(beyond.text(true, false).contains("drawn, but not here (cut by yon)"), beyond.text(true, false));
        // Where the pixel's ray (wx, wy, -1) t meets the triangle's plane z = -50 - 7.5 (y + 10):
        // -t = -125 - 7.5 wy t, t = 125 / (1 - 7.5 wy): beyond the far plane, which is what cut it here.
        double wx = 324.5 / 325 - 1;
        double wy = 324.5 / 325 - 1;
        double t = 125 / (1 - 7.5 * wy);
        assertArrayEquals(new double[] {wx * t, wy * t, -t}, e.here(), 1e-9);
        assertEquals(1 << Camera.YON, e.herePlanes());
        assertTrue(beyond.text(true, false).contains(", and there it is at camera (") && beyond.text(true, false)
                .contains("), outside the yon plane"), beyond.text(true, false));
        assertTrue(beyond.json(true, false).contains("\"here\": {\"camera\": ["), beyond.json(true, false));
        assertTrue(beyond.json(true, false).contains("], \"outside\": [\"yon\"]}"), beyond.json(true, false));
        // Window y -0.0754, below the cut: drawn, and only written.
        PixelReport drawn = inspector.inspect(s, 324, 300);
        assertEquals(1, drawn.history().size(), drawn.text(true, false));
        assertEquals(Outcome.WRITTEN, drawn.history().get(0).outcome());
        // Window y -0.229, below the base: nothing.
        assertEquals(0, inspector.inspect(s, 324, 250).history().size());
        // Window x 0.1: outside the triangle at any height above the cut.
        assertEquals(0, inspector.inspect(s, 357, 324).history().size());
    }

    /**
     * An obj floor whose face starts along its near edge, three vertices on
     * one line (y = -1, z = -2), then goes out past the far plane z = -20.
     * The ray through window (wx, wy), wy below 0, meets the floor at
     * t = 1 / -wy; at pixel (325, 312), wy = 312.5 / 325 - 1 = -1/26, so
     * t = 26, beyond the far plane: the face is cut away there by yon.
     */
    @Test
    void aFaceWhoseFirstThreeVerticesLieOnALineStillSaysWhereItIs() throws Exception {
        Files.writeString(dir.resolve("floor.obj"),
                "v -5 -1 -2\nv 0 -1 -2\nv 5 -1 -2\nv 5 -1 -50\nv -5 -1 -50\nf 1 2 3 4 5\n");
        InspectedScene s = scene("floor.simp", "camera -1 -1 1 1 -1 -20\nobj \"floor\"\n");
        PixelReport r = inspector.inspect(s, 325, 312);
        assertEquals(1, r.history().size(), r.text(true, false));
        HistoryEntry e = r.history().get(0);
        assertEquals(Outcome.CLIPPED, e.outcome());
        double wx = 325.5 / 325 - 1;
        double wy = 312.5 / 325 - 1;
        double t = 1 / -wy;
        assertNotNull(e.here(), r.text(true, false));
        assertArrayEquals(new double[] {wx * t, -1, -t}, e.here(), 1e-9);
        assertEquals(1 << Camera.YON, e.herePlanes());
        assertTrue(r.text(true, false).contains("), outside the yon plane"), r.text(true, false));
    }

    @Test
    void aTriangleNearerThanTheNearPlaneWithAVertexBehindTheEye() throws Exception {
        // Every z > -1 (the near plane): culled by hither. The apex (z = 0.2) is behind the eye. The part in
        // front of the eye has its base at window y = -2 (x from -2 to 2) and its sides going up and out
        // from there (away from the vanishing point (-1/0.7, -2/0.7) of the edge direction (1, 2, 0.7)), so
        // it covers the whole panel. The same triangle moved 10 to the right projects right of the panel.
        InspectedScene s = scene("eye.simp", CAMERA + "polygon (-1, -1, -0.5) (1, -1, -0.5) (0, 1, 0.2)\n"
                + "polygon (9, -1, -0.5) (11, -1, -0.5) (10, 1, 0.2)\n");
        for (int[] xy : new int[][] {{325, 325}, {3, 640}, {640, 3}}) {
            PixelReport r = inspector.inspect(s, xy[0], xy[1]);
            assertEquals(1, r.history().size(), r.text(true, false));
            HistoryEntry e = r.history().get(0);
            assertEquals(Outcome.CULLED, e.outcome());
            assertEquals(HistoryEntry.NO_NUMBER, e.primitive());
            assertEquals(List.of("hither"), e.planeNames());
            assertEquals("eye.simp:2", e.chain().get(e.chain().size() - 1).toString());
            assertTrue(r.json(true, false).contains("\"outcome\": \"culled\", \"culled_by\": [\"hither\"]"));
        }
    }

    @Test
    void aTriangleThroughTheEyesPlaneIsJudgedByItsPartInFrontOfTheEye() throws Exception {
        // Base at z = -10 (window x -0.1 to 0.1, y -0.1), apex (0, 0.5, 1) behind the eye. The near plane
        // z = -1 crosses the sides 9/11 of the way up, at window (-+2/11, 5/22): the drawn part is the
        // quadrilateral below that. The part between the near plane and the eye projects above it, its sides
        // going on up and out at dx/dy = -+1/4 (at window y 0.8 they are 0.1 + 0.9 / 4 = 0.325 from x = 0).
        InspectedScene s = scene("through.simp", CAMERA + "polygon (-1, -1, -10) (1, -1, -10) (0, 0.5, 1)\n");
        // Window (-0.0015, 0.7985): above the drawn part, inside the part nearer than the near plane.
        PixelReport cut = inspector.inspect(s, 324, 584);
        assertEquals(1, cut.history().size(), cut.text(true, false));
        HistoryEntry e = cut.history().get(0);
        assertEquals(Outcome.CLIPPED, e.outcome());
        assertEquals(0, e.primitive());
        assertTrue(e.planeNames().contains("hither"), e.planeNames().toString());
        // Window (-0.0015, -0.0015): the drawn part.
        PixelReport drawn = inspector.inspect(s, 324, 324);
        assertEquals(List.of(Outcome.WRITTEN), drawn.history().stream().map(HistoryEntry::outcome).toList());
        // Window (0.5, 0.7985): outside both.
        assertEquals(0, inspector.inspect(s, 487, 584).history().size());
    }

    /**
     * A vertex behind the eye is outside every side plane (they cross behind
     * it), but the clipper's hither pass takes it away before the side passes
     * run: VertexTableTest's triangle is cut by hither and yon only. Its part
     * between the eye and the near plane projects up and right from the cut,
     * between the lines through window (0.413, 0.413) with slope 1 and
     * (0.694, 0.485) with slope 0.768: window (0.9, 0.8) is in it.
     */
    @Test
    void aClippedEntryNamesThePlanesTheClipperCutBy() throws Exception {
        InspectedScene s = scene("behind.simp", CAMERA + "polygon (0.5, 0.5, 2) (-1, -1, -50) (20, -1, -300)\n");
        PixelReport r = inspector.inspect(s, 617, 584);
        assertEquals(1, r.history().size(), r.text(true, false));
        HistoryEntry e = r.history().get(0);
        assertEquals(Outcome.CLIPPED, e.outcome());
        assertEquals(List.of("hither", "yon"), e.planeNames());
        assertTrue(r.text(true, false).contains("drawn, but not here (cut by hither, yon)"), r.text(true, false));
        // At this pixel it is between the eye and the near plane: hither cut it away here, not yon.
        assertEquals(1 << Camera.HITHER, e.herePlanes());
        assertTrue(e.here()[2] > -1 && e.here()[2] < 0, Arrays.toString(e.here()));
    }

    /**
     * A window twice as wide as high, [-1, 1] x [-1, 0]: 325 pixels to a
     * unit, 650 wide and 325 high, centred, so panel y 162.5 to 487.5; the
     * bands above and below it show nothing, and a background pixel there
     * says why. A background pixel inside the window does not.
     */
    @Test
    void aBackgroundPixelOutsideTheCamerasWindowSaysSo() throws Exception {
        InspectedScene s = scene("wide.simp", "camera -1 -1 1 0 -1 -100\nambient 1 1 1\n"
                + "polygon (-1, -1, -5) (1, -1, -5) (0, -0.5, -5)\n");
        String above = inspector.inspect(s, 325, 600).text(true, false);
        assertTrue(above.contains("drawn by no primitive (background): its centre is outside the camera's window, "
                + "which covers panel x 0 to 650 and y 162.5 to 487.5: nothing of the scene lands here"), above);
        assertTrue(inspector.inspect(s, 325, 600).json(true, true).contains("\"outside_window\": \"its centre is"));
        String inside = inspector.inspect(s, 325, 480).text(true, false);
        assertTrue(inside.contains("drawn by no primitive (background)\n"), inside);
        assertEquals(null, inspector.inspect(scene("square.simp", CAMERA + "polygon (-1, -1, -5) (1, -1, -5) (0, 1, -5)\n"),
                3, 3).outsideTheWindow());
    }

    @Test
    void gouraudThroughTheNearPlaneIsExplainedByItsOwnVertices() throws Exception {
        // Ambient 1 and no lights: each vertex lit is its own colour. The apex (z = -0.5) is nearer than the
        // near plane (z = -1): the clipper cuts the triangle into a quadrilateral, drawn as a fan of two.
        double[][] v = {{-2, -2, -4, 1, 0, 0}, {2, -2, -4, 0, 1, 0}, {0, 2, -0.5, 0, 0, 1}};
        StringBuilder sb = new StringBuilder(CAMERA + "ambient 1 1 1\ngouraud\npolygon");
        for (double[] p : v) {
            sb.append(" (").append(p[0]).append(", ").append(p[1]).append(", ").append(p[2]).append(", ")
                    .append(p[3]).append(", ").append(p[4]).append(", ").append(p[5]).append(')');
        }
        InspectedScene s = scene("gouraud.simp", sb.append('\n').toString());
        int checked = 0;
        int pieces = 0;
        for (int y = 20; y < 650; y += 59) {
            for (int x = 20; x < 650; x += 61) {
                PixelReport r = inspector.inspect(s, x, y);
                Terms t = r.explanation();
                if (t == null) {
                    continue;
                }
                checked++;
                String where = "pixel (" + x + ", " + y + ")";
                assertEquals("gouraud", t.get("shading"), where);
                List<Terms> vertices = t.list("vertex_colours");
                assertEquals(3, vertices.size(), where + ": the triangle's own three vertices");
                for (int k = 0; k < 3; k++) {
                    assertArrayEquals(new double[] {v[k][0], v[k][1], v[k][2]}, vertices.get(k).vector("camera"), 1e-12);
                    assertArrayEquals(new double[] {v[k][3], v[k][4], v[k][5]}, vertices.get(k).vector("colour"), 1e-12);
                }
                double[] expected = weights(v, (x + 0.5) / 325 - 1, (y + 0.5) / 325 - 1);
                assertArrayEquals(expected, t.vector("weights"), 1e-9, where + ": weights against the triangle");
                // The colour of each vertex is one channel: the interpolated colour is the weights themselves.
                assertArrayEquals(expected, t.vector("interpolated"), 1e-9, where + ": the drawn colour");
                assertArrayEquals(t.vector("interpolated"), t.vector("weighted"), 1e-12, where);
                assertNotNull(t.get("fan_piece"), where + ": the clipper cut it, the piece is shown");
                pieces++;
                int[] bytes = (int[]) t.get("final_rgb");
                int argb = r.argb();
                assertArrayEquals(new int[] {argb >>> 16 & 0xFF, argb >>> 8 & 0xFF, argb & 0xFF}, bytes, where);
            }
        }
        assertTrue(checked > 15, "too few drawn pixels: " + checked);
        assertEquals(checked, pieces);
        // Uncut, no fan piece: the weights are against the same three vertices.
        InspectedScene whole = scene("whole.simp", CAMERA + "ambient 1 1 1\ngouraud\n"
                + "polygon (-2, -2, -4, 1, 0, 0) (2, -2, -4, 0, 1, 0) (0, 2, -4, 0, 0, 1)\n");
        Terms t = inspector.inspect(whole, 325, 325).explanation();
        assertNull(t.get("fan_piece"));
        assertEquals(3, t.vector("weights").length);
    }

    /** Perspective-correct weights: where the pixel's ray (wx, wy, -1) meets the triangle's plane, barycentric. */
    private static double[] weights(double[][] v, double wx, double wy) {
        double[] a = sub(v[1], v[0]);
        double[] b = sub(v[2], v[0]);
        double[] n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double[] d = {wx, wy, -1};
        double s = (n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2]) / (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
        double[] p = {s * d[0], s * d[1], s * d[2]};
        double total = dot(n, n);
        double[] pa = sub(v[0], p);
        double[] pb = sub(v[1], p);
        double[] pc = sub(v[2], p);
        double w0 = dot(n, cross(pb, pc)) / total;
        double w1 = dot(n, cross(pc, pa)) / total;
        return new double[] {w0, w1, 1 - w0 - w1};
    }

    private static double[] sub(double[] p, double[] q) {
        return new double[] {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
