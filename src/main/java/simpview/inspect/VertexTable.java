package simpview.inspect;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import simpview.geometry.Camera;
import simpview.geometry.Clipper;
import simpview.geometry.Matrix4;
import simpview.raster.CentreTest;
import simpview.stage.Painter;
import simpview.surface.PageCanvas;

/**
 * A primitive's vertices through every space, as the geometry stages take
 * them: as written, after the CTM (world), after W (camera space), projected
 * (panel coordinates with their fractions) and the pixel each rounds to; for
 * a lit scene the clipper's output (by the program's own {@link Clipper}) and
 * the planes that cut it, each vertex of the output named: a vertex as
 * written, or a new one with the planes it lies on and how much of each
 * vertex as written it is; for a line, the DDA's start pixel, direction and
 * step count by SPEC's rule; for a filled polygon, whether it covers the
 * pixel's centre, by the rasterizer's own edge tests ({@link CentreTest}), and
 * on an edge, which way the top-left rule took it.
 */
final class VertexTable {

    static final String[] PLANES = {"hither", "yon", "left", "right", "bottom", "top"};

    private VertexTable() {
    }

    /**
     * Primitive s's table, named by its command (its include chain, as the
     * history names a write), its coverage asked at pixel (x, y).
     */
    static Terms of(PrimitiveSource s, String command, int pixelX, int pixelY) {
        Terms t = new Terms();
        t.put("primitive", PixelReport.shown(s.primitive()));
        t.put("command", command);
        t.put("kind", s.kind() == Painter.LINE ? "line" : s.kind() == Painter.WIRE ? "wire polygon" : "filled polygon");
        t.put("ctm", rows(s.ctm()));
        Matrix4 toCamera = s.worldToCamera().times(s.ctm());
        if (s.lit()) {
            t.put("world_to_camera", rows(s.worldToCamera()));
        }
        Camera camera = s.camera();
        int n = s.vertices();
        double[] cam = new double[3 * n];
        List<Terms> vertices = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            double x = s.xyz()[3 * k];
            double y = s.xyz()[3 * k + 1];
            double z = s.xyz()[3 * k + 2];
            Matrix4 m = s.ctm();
            double[] world = {m.applyX(x, y, z), m.applyY(x, y, z), m.applyZ(x, y, z)};
            cam[3 * k] = toCamera.applyX(x, y, z);
            cam[3 * k + 1] = toCamera.applyY(x, y, z);
            cam[3 * k + 2] = toCamera.applyZ(x, y, z);
            Terms v = new Terms().put("written", x, y, z).put("world", world);
            if (s.lit()) {
                v.put("camera", cam[3 * k], cam[3 * k + 1], cam[3 * k + 2]);
            }
            v.put("outside", planes(camera.outcode(cam[3 * k], cam[3 * k + 1], cam[3 * k + 2])));
            project(camera, cam[3 * k], cam[3 * k + 1], cam[3 * k + 2], v);
            vertices.add(v);
        }
        t.put("vertices", vertices);
        boolean culled = camera.culls(cam, 3, n);
        double[] ends = null;
        if (culled) {
            t.put("culled", "every vertex is outside the " + planes(commonOutside(camera, cam, n)) + " plane");
        } else if (!s.lit()) {
            t.put("clipping", "none: a depth-cued scene is not clipped; the scissor drops the pixels outside the view");
            if (s.kind() == Painter.LINE) {
                ends = new double[] {cam[0], cam[1], cam[2], cam[3], cam[4], cam[5]};
            }
        } else {
            // Each vertex carries its shares of the vertices as written (one-hot), which the clipper lerps
            // as it lerps colours and normals: a new vertex's shares say what it is made of.
            int stride = 3 + n;
            double[] marked = new double[stride * n];
            for (int k = 0; k < n; k++) {
                System.arraycopy(cam, 3 * k, marked, k * stride, 3);
                marked[k * stride + 3 + k] = 1;
            }
            Clipper clipper = new Clipper(stride);
            int kept;
            if (s.kind() == Painter.LINE) {
                kept = clipper.clipLine(camera, marked, 0, stride) ? 2 : 0;
            } else {
                kept = clipper.clipPolygon(camera, marked, 0, n);
            }
            double[] out = clipper.vertices();
            Terms clip = new Terms();
            int crossed = clipper.cutPlanes();
            clip.put("cut_by", crossed == 0 ? "none: every vertex is inside the view" : planes(crossed));
            List<Terms> output = new ArrayList<>();
            boolean anyNew = false;
            for (int k = 0; k < kept; k++) {
                int at = k * stride;
                double[] shares = Arrays.copyOfRange(out, at + 3, at + stride);
                int source = asWritten(shares);
                Terms v = new Terms();
                if (source >= 0) {
                    v.put("from", "vertex " + source + ", as written");
                } else {
                    anyNew = true;
                    int on = onPlanes(camera, out[at], out[at + 1], out[at + 2]);
                    v.put("from", on == 0 ? "new, made by the clipper"
                            : "new, made by the clipper where the " + (s.kind() == Painter.LINE ? "line" : "outline")
                            + " crosses the " + and(planeNames(on)) + (Integer.bitCount(on) == 1 ? " plane" : " planes"));
                    v.put("of_the_vertices", shares);
                }
                v.put("camera", out[at], out[at + 1], out[at + 2]);
                project(camera, out[at], out[at + 1], out[at + 2], v);
                output.add(v);
            }
            if (anyNew) {
                clip.put("new_vertices", "of_the_vertices is how much of each vertex as written a new vertex is: its "
                        + "position, colour and normal are those shares of theirs (SPEC Part 2: linear in camera "
                        + "space at the crossing)");
            }
            clip.put("output", output);
            if (kept == 0) {
                clip.put("result", "nothing is left in view");
            }
            t.put("clipping", clip);
            if (s.kind() == Painter.LINE && kept == 2) {
                ends = new double[] {out[0], out[1], out[2], out[stride], out[stride + 1], out[stride + 2]};
            }
        }
        if (ends != null) {
            t.put("dda", dda(camera.panelX(ends[0], ends[2]), camera.panelY(ends[1], ends[2]),
                    camera.panelX(ends[3], ends[5]), camera.panelY(ends[4], ends[5]), pixelX, pixelY));
        }
        if (s.kind() == Painter.WIRE && !culled && s.drawn() != null && s.drawn().length >= 4) {
            List<Terms> edges = wireEdges(s.drawn(), pixelX, pixelY);
            if (edges.isEmpty()) {
                t.put("edges_at_pixel", "none: no edge's DDA steps on the pixel");
            } else {
                t.put("edges_at_pixel", edges);
            }
        }
        if (s.kind() == Painter.FILLED && !culled && s.drawn() != null && s.drawn().length >= 6) {
            t.put("centre", centre(s.drawn(), pixelX, pixelY));
        }
        return t;
    }

    /**
     * Whether the outline the rasterizer was given (panel x and y of each
     * vertex) covers the centre of pixel (x, y): fan triangle by fan triangle
     * from its first vertex, as the rasterizers fill it, each edge asked by
     * their own exact test; and in words why, naming the top-left rule when
     * the centre is exactly on an edge.
     */
    static Terms centre(double[] drawn, int x, int y) {
        double cx = x + 0.5;
        double cy = y + 0.5;
        int n = drawn.length / 2;
        List<Terms> outline = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            outline.add(new Terms().put("vertex", k).put("panel", drawn[2 * k], drawn[2 * k + 1]));
        }
        List<Terms> fan = new ArrayList<>();
        String why = null;
        String tie = null;
        boolean degenerate = true;
        for (int i = 1; i + 1 < n; i++) {
            int[] v = {0, i, i + 1};
            int[] sides = CentreTest.sides(drawn[0], drawn[1], drawn[2 * i], drawn[2 * i + 1], drawn[2 * i + 2],
                    drawn[2 * i + 3], cx, cy);
            Terms triangle = new Terms().put("vertices", v);
            if (sides == null) {
                fan.add(triangle.put("covers", false).put("why", "no area: it draws nothing"));
                continue;
            }
            degenerate = false;
            boolean covers = CentreTest.covered(sides);
            List<Terms> edges = new ArrayList<>();
            String onOut = null;
            String onIn = null;
            boolean outside = false;
            for (int k = 0; k < 3; k++) {
                String edge = v[k] + "-" + v[(k + 1) % 3];
                edges.add(new Terms().put("edge", edge).put("centre", SIDE_WORDS[sides[k]]));
                outside |= sides[k] == CentreTest.OUTSIDE;
                if (sides[k] == CentreTest.ON_RIGHT_OR_BOTTOM) {
                    onOut = edge;
                } else if (sides[k] == CentreTest.ON_TOP_OR_LEFT) {
                    onIn = edge;
                }
            }
            triangle.put("edges", edges).put("covers", covers);
            fan.add(triangle);
            String name = n == 3 ? "the triangle" : "fan triangle " + v[0] + "-" + v[1] + "-" + v[2];
            if (covers && why == null) {
                why = onIn == null ? "the centre is inside " + name
                        : "the centre is exactly on edge " + onIn + " of " + name + ", a top or left edge: the "
                        + "top-left rule gives the pixel to this triangle, not to one sharing that edge";
            } else if (!covers && !outside && tie == null) {
                tie = "the centre is exactly on edge " + onOut + " of " + name + ", a right or bottom edge: "
                        + "the top-left rule gives the pixel to the triangle on that edge's other side, if any";
            }
        }
        boolean covered = why != null;
        return new Terms().put("pixel_centre", cx, cy).put("covered", covered)
                .put("why", covered ? why : degenerate ? "the outline has no area: it draws nothing"
                        : tie != null ? tie : "the centre is outside the outline")
                .put("outline", outline).put("fan", fan);
    }

    /** What each of {@link CentreTest}'s answers says, in its order. */
    private static final String[] SIDE_WORDS = {
        "inside",
        "exactly on it, a top or left edge: in",
        "exactly on it, a right or bottom edge: out (the top-left rule)",
        "outside",
    };

    /**
     * In perspective the point on the window plane (x / -z, y / -z); then
     * panel coordinates and the pixel they round to, or why there are none.
     */
    private static void project(Camera camera, double x, double y, double z, Terms v) {
        if (camera.isPerspective() && !(z < 0)) {
            v.put("panel", "none: at or behind the eye (z >= 0)");
            return;
        }
        if (camera.isPerspective()) {
            // SPEC Part 2: the point lands on the window plane z = -1 at (x / -z, y / -z)
            v.put("window", x / -z, y / -z);
        }
        double px = camera.panelX(x, z);
        double py = camera.panelY(y, z);
        v.put("panel", px, py);
        double pixelX = Math.floor(px + 0.5);
        double pixelY = Math.floor(py + 0.5);
        if (Math.abs(pixelX) < Integer.MAX_VALUE && Math.abs(pixelY) < Integer.MAX_VALUE) {
            v.put("pixel", (int) pixelX, (int) pixelY);
            if (pixelX < 0 || pixelX >= PageCanvas.PANEL || pixelY < 0 || pixelY >= PageCanvas.PANEL) {
                v.put("pixel_outside", "past the panel's pixels, 0 to " + (PageCanvas.PANEL - 1) + " each way");
            }
        } else {
            v.put("pixel", "none: too far outside the panel to name");
        }
    }

    /**
     * The edges of a wire polygon's outline as the rasterizer was given it
     * (panel x and y of each vertex; edge k runs from vertex k to the next,
     * the last back to the first) whose DDA steps on pixel (x, y), each with
     * its DDA.
     */
    private static List<Terms> wireEdges(double[] drawn, int x, int y) {
        int n = drawn.length / 2;
        List<Terms> edges = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            int j = (k + 1) % n;
            if (Coverage.onLine(drawn[2 * k], drawn[2 * k + 1], drawn[2 * j], drawn[2 * j + 1], x, y)) {
                edges.add(new Terms().put("edge", k + "-" + j).put("from", drawn[2 * k], drawn[2 * k + 1])
                        .put("to", drawn[2 * j], drawn[2 * j + 1])
                        .put("dda", dda(drawn[2 * k], drawn[2 * k + 1], drawn[2 * j], drawn[2 * j + 1], x, y)));
            }
        }
        return edges;
    }

    /**
     * SPEC's DDA for a line between two panel points: start pixel, direction,
     * slope and step count; and at pixel (x, y): the step whose major
     * coordinate is the pixel's, the minor coordinate there as the DDA has it
     * (the slope added once a step) and the pixel it rounds to, half up.
     */
    static Terms dda(double x0, double y0, double x1, double y1, int x, int y) {
        DdaSteps dda = DdaSteps.of(x0, y0, x1, y1);
        boolean xMajor = dda.xMajor();
        long major = dda.steps();
        long minor = xMajor ? dda.endY() - dda.startY() : dda.endX() - dda.startX();
        Terms t = new Terms();
        t.put("start_pixel", (double) dda.startX(), (double) dda.startY());
        t.put("end_pixel", (double) dda.endX(), (double) dda.endY());
        t.put("major_axis", xMajor ? "x" : "y");
        t.put("direction", xMajor ? 1 : Long.signum(minor), xMajor ? Long.signum(minor) : 1);
        t.put("slope", dda.slope());
        t.put("steps", (double) major);
        t.put("pixels", (double) (major + 1));
        long step = dda.stepAt(x, y);
        if (step < 0 || step > major) {
            t.put("at_pixel", "none: the pixel's " + (xMajor ? "x" : "y") + " is outside the line's, "
                    + dda.majorStart() + " to " + dda.majorEnd());
        } else {
            double along = dda.minorAt(step);
            long rounded = (long) Math.floor(along + 0.5);
            t.put("at_pixel", new Terms().put("step", (double) step).put(xMajor ? "y" : "x", along)
                    .put("rounds_to", (double) rounded).put("steps_on_pixel", rounded == (xMajor ? y : x)));
        }
        return t;
    }

    /** The vertex as written that shares are wholly (one-hot), or -1 for a vertex the clipper made. */
    private static int asWritten(double[] shares) {
        int source = -1;
        for (int k = 0; k < shares.length; k++) {
            if (shares[k] == 1 && source < 0) {
                source = k;
            } else if (shares[k] != 0) {
                return -1;
            }
        }
        return source;
    }

    /**
     * The planes (Camera's bits) that the camera-space point lies on, to
     * within rounding: a vertex the clipper made lies on the plane whose
     * pass made it (and on two at a corner of the view).
     */
    private static int onPlanes(Camera camera, double x, double y, double z) {
        double tolerance = 1e-9 * (1 + Math.abs(x) + Math.abs(y) + Math.abs(z));
        int on = 0;
        for (int p = 0; p < Camera.PLANES; p++) {
            if (Math.abs(camera.distance(p, x, y, z)) <= tolerance) {
                on |= 1 << p;
            }
        }
        return on;
    }

    /** "a", "a and b", "a, b and c". */
    private static String and(List<String> words) {
        int n = words.size();
        return n <= 1 ? String.join("", words) : String.join(", ", words.subList(0, n - 1)) + " and " + words.get(n - 1);
    }

    static int commonOutside(Camera camera, double[] cam, int n) {
        int common = ~0;
        for (int k = 0; k < n; k++) {
            common &= camera.outcode(cam[3 * k], cam[3 * k + 1], cam[3 * k + 2]);
        }
        return common;
    }

    static String planes(int code) {
        String names = String.join(", ", planeNames(code));
        return names.isEmpty() ? "none" : names;
    }

    /** The planes of an outcode (Camera's bits), in the clipper's order: hither, yon, left, right, bottom, top. */
    static List<String> planeNames(int code) {
        List<String> names = new ArrayList<>();
        for (int p = 0; p < Camera.PLANES; p++) {
            if ((code & 1 << p) != 0) {
                names.add(PLANES[p]);
            }
        }
        return names;
    }

    private static Terms rows(Matrix4 m) {
        Terms rows = new Terms();
        for (int r = 0; r < 4; r++) {
            rows.put("row " + (r + 1), m.get(r, 0), m.get(r, 1), m.get(r, 2), m.get(r, 3));
        }
        return rows;
    }
}
