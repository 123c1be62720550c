package simpview.inspect;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import simpview.geometry.Clipper;
import simpview.raster.FragmentLayout;
import simpview.shading.Fog;
import simpview.shading.LitState;
import simpview.stage.Painter;
import simpview.surface.Colors;

/**
 * The colour of a lit fragment, made by the same code as the fragment stage
 * makes it and in the same order: the colour channels as resolved, or under
 * phong the scene's own lighting ({@link LitState#shade}) of the resolved P,
 * N and kd; then the scene's fog ({@link Fog#apply}); then
 * {@link Colors#pack}. So its bytes are the pixel's bytes. Around that it
 * writes out what went in: the lighting's terms and where kd came from
 * (phong: interpolated, or one kd as it is), the lit vertex
 * colours and the pixel's perspective-correct weights (gouraud), the
 * polygon's one colour (flat), the fog.
 */
final class LitExplainer implements PixelWatch.Explainer {

    private final LitState state;

    LitExplainer(LitState state) {
        this.state = state;
    }

    @Override
    public int colour(PixelWatch watch, double z, double[] ch, int drawnArgb, boolean drawn, Terms terms) {
        double[] lit = new double[3];
        boolean phong = ch.length == FragmentLayout.PHONG_CHANNELS;
        if (terms == null) {
            if (phong) {
                state.shade(ch[FragmentLayout.PX], ch[FragmentLayout.PY], z, ch[FragmentLayout.NX], ch[FragmentLayout.NY],
                        ch[FragmentLayout.NZ], ch[FragmentLayout.R], ch[FragmentLayout.G], ch[FragmentLayout.B], lit);
            } else {
                lit[0] = ch[FragmentLayout.R];
                lit[1] = ch[FragmentLayout.G];
                lit[2] = ch[FragmentLayout.B];
            }
            state.fog().apply(z, lit, 0);
            return Colors.pack(lit[0], lit[1], lit[2]);
        }
        int kind = watch.kind();
        terms.put("z", z);
        if (phong) {
            terms.put("shading", "phong");
            double[] p = {ch[FragmentLayout.PX], ch[FragmentLayout.PY], z};
            double[] n = {ch[FragmentLayout.NX], ch[FragmentLayout.NY], ch[FragmentLayout.NZ]};
            double[] kd = {ch[FragmentLayout.R], ch[FragmentLayout.G], ch[FragmentLayout.B]};
            String kdFrom = watch.carriesOneColour()
                    ? "every vertex of the clipped polygon has this kd, so it is every pixel's kd as it is, to the "
                    + "bit (a lerp between one value and itself is that value); P and N are interpolated"
                    : "interpolated perspective-correct from the clipped polygon's vertices, (kd q) / q at the pixel, "
                    + "as P and N are (SPEC Part 2)";
            double[] sum = LightingTerms.explain(state, p, n, watch.hasFaceNormalOnly(), kd, kdFrom, terms);
            state.shade(p[0], p[1], p[2], n[0], n[1], n[2], kd[0], kd[1], kd[2], lit);
            terms.put("clamped", clamp(sum));
            terms.put("lit", lit.clone());
        } else {
            lit[0] = ch[FragmentLayout.R];
            lit[1] = ch[FragmentLayout.G];
            lit[2] = ch[FragmentLayout.B];
            if (kind == Painter.LINE || kind == Painter.WIRE) {
                terms.put("shading", kind == Painter.LINE ? "none (a line carries kd)" : "none (a wire polygon's edges carry kd)");
                Terms along = along(watch, z);
                if (along != null) {
                    terms.put("along", along);
                }
                terms.put("kd", lit.clone());
            } else if (state.shading() == LitState.ShadingMode.FLAT) {
                terms.put("shading", "flat");
                double[] once = watch.litOnce();
                if (once != null) {
                    boolean face = faceNormal(watch, once);
                    terms.put("lit_at", "the polygon's centroid, once, with the mean of its vertices' kd and "
                            + (face ? "its face normal (p2 - p1) x (p3 - p1), made unit, as some vertex has no "
                            + "normal of its own" : "the sum of its vertices' own unit normals") + ": SPEC Part 2");
                    double[] sum = LightingTerms.explain(state, new double[] {once[0], once[1], once[2]},
                            new double[] {once[3], once[4], once[5]}, face ? "N_face" : "N_summed", face,
                            new double[] {once[6], once[7], once[8]}, terms);
                    terms.put("clamped", clamp(sum));
                }
                terms.put("centroid_colour", lit.clone());
            } else {
                terms.put("shading", "gouraud");
                gouraud(watch, state, terms);
                terms.put("interpolated", lit.clone());
            }
        }
        double[] fogged = lit.clone();
        Fog fog = state.fog();
        fog.apply(z, fogged, 0);
        if (fog.isNone()) {
            terms.put("fog", "none");
        } else {
            double t = (z - fog.far()) / (fog.near() - fog.far());
            terms.put("fog", new Terms().put("near", fog.near()).put("far", fog.far())
                    .put("colour", fog.r(), fog.g(), fog.b()).put("t", Math.max(0, Math.min(1, t)))
                    .put("why", fogWhy(z, fog, t)));
        }
        terms.put("fogged", fogged);
        int argb = Colors.pack(fogged[0], fogged[1], fogged[2]);
        terms.put("final_rgb", argb >>> 16 & 0xFF, argb >>> 8 & 0xFF, argb & 0xFF);
        return argb;
    }

    /**
     * Why the fog's t is what it is at depth z, in SPEC's words and with the
     * numbers put in: no fog at or nearer than near, the fog's colour alone at
     * or beyond far, between them the share of the way from far to near.
     */
    static String fogWhy(double z, Fog fog, double t) {
        if (!(z < fog.near())) {
            return "z " + Json.number(z) + " is at or nearer than near " + Json.number(fog.near())
                    + ": no fog (t = 1), the colour stays as it is";
        }
        if (z <= fog.far()) {
            return "z " + Json.number(z) + " is at or beyond far " + Json.number(fog.far())
                    + ": the fog's colour alone (t = 0)";
        }
        return "t = (z - far) / (near - far) = " + difference(z, fog.far()) + " / " + difference(fog.near(), fog.far())
                + " = " + Json.number(t) + "; fogged = t (the colour before fog) + (1 - t) (the fog's colour)";
    }

    /** "(a - b)", written "(a + |b|)" when b is negative. */
    private static String difference(double a, double b) {
        return "(" + Json.number(a) + (b < 0 ? " + " + Json.number(-b) : " - " + Json.number(b)) + ")";
    }

    /**
     * A line's (or a wire polygon's edge's) pixel: the edge the DDA walked
     * (of a wire outline, the edge that steps on the pixel at the fragment's
     * depth z), its ends in the order the walk takes them (from the smaller
     * x of an x-major line, else the smaller y), the step that reached the
     * pixel and the screen-space share of the way there, t, as the walk
     * works it out; then SPEC's perspective-correct lerp: q = 1 / -z (1 in
     * the parallel view) and kd q lerped by t, so the ends weigh
     * (1 - t) q_start / q and t q_end / q, q = (1 - t) q_start + t q_end.
     * Null when no edge of the outline steps on the pixel.
     */
    private static Terms along(PixelWatch watch, double z) {
        double[] o = watch.outline();
        int s = watch.stride();
        int n = watch.vertices();
        int x = watch.x();
        int y = watch.y();
        int edges = watch.kind() == Painter.LINE ? 1 : n;
        Terms best = null;
        double nearest = Double.POSITIVE_INFINITY;
        for (int k = 0; k < edges && n >= 2; k++) {
            int a = k;
            int b = (k + 1) % n;
            if (!Coverage.onLine(o[a * s], o[a * s + 1], o[b * s], o[b * s + 1], x, y)) {
                continue;
            }
            DdaSteps dda = DdaSteps.of(o[a * s], o[a * s + 1], o[b * s], o[b * s + 1]);
            int start = dda.reversed() ? b : a;
            int end = dda.reversed() ? a : b;
            long step = dda.stepAt(x, y);
            double t = dda.t(step);
            int ps = start * s;
            int pe = end * s;
            double qStart = o[ps + FragmentLayout.Q];
            double qEnd = o[pe + FragmentLayout.Q];
            double q = (1 - t) * qStart + t * qEnd;
            int c = FragmentLayout.CHANNEL;
            double zHere = ((1 - t) * o[ps + c + FragmentLayout.Z] + t * o[pe + c + FragmentLayout.Z]) / q;
            double gap = Math.abs(zHere - z);
            if (!(gap < nearest)) {
                continue;
            }
            nearest = gap;
            double wStart = (1 - t) * qStart / q;
            double wEnd = t * qEnd / q;
            double[] weighted = new double[3];
            Terms[] ends = new Terms[2];
            int[] at = {ps, pe};
            int[] vertex = {start, end};
            for (int e = 0; e < 2; e++) {
                double qe = o[at[e] + FragmentLayout.Q];
                double[] kd = watch.colourAt(vertex[e]);
                double w = e == 0 ? wStart : wEnd;
                for (int j = 0; j < 3; j++) {
                    weighted[j] += w * kd[j];
                }
                ends[e] = new Terms().put("vertex", vertex[e]).put("panel", o[at[e]], o[at[e] + 1])
                        .put("z", o[at[e] + c + FragmentLayout.Z] / qe).put("q", qe).put("kd", kd);
            }
            best = new Terms();
            if (watch.kind() == Painter.WIRE) {
                best.put("edge", a + "-" + b);
            }
            best.put("start", ends[0]).put("end", ends[1])
                    .put("step", (double) step).put("steps", (double) dda.steps())
                    .put("t", t)
                    .put("q", q)
                    .put("weights", wStart, wEnd)
                    .put("weighted", weighted)
                    .put("rule", (watch.camera().isPerspective()
                            ? "q = 1 / -z is lerped by t, and so is kd q: the ends weigh (1 - t) q_start / q and "
                            + "t q_end / q (SPEC Part 2, perspective-correct)"
                            : "the parallel view: q = 1, kd is lerped by t, the ends weigh 1 - t and t")
                            + (watch.carriesOneColour() ? "; both ends carry the same kd, so every pixel's kd is that "
                            + "kd, to the bit (a lerp between one value and itself is that value)" : ""));
        }
        return best;
    }

    /**
     * Gouraud at the pixel. SPEC Part 2 lights each vertex of the polygon
     * before clipping; clipping lerps those lit colours to the clipped
     * vertices, and the fan triangle of the clipped polygon that holds the
     * pixel's centre interpolates them perspective-correct:
     * {@code w_i = b_i q_i / sum_j b_j q_j} for the screen-space barycentric b.
     * So the terms are the polygon's own vertices with their lit colours, and
     * the pixel's weights against them, {@code u_k = sum_i w_i W_ik}, where
     * row i of W says how much of each original vertex clipped vertex i is:
     * found by clipping, with the same {@link Clipper} and camera, the
     * polygon's positions carrying one-hot weights instead of colours (the
     * same distances and crossings, so the same clipped vertices). Where the
     * polygon was cut, the fan piece is shown too. The colour the drawing
     * interpolated ("interpolated") is what the bytes come from; the weighted
     * sum of the vertex colours is shown beside it ("weighted"), equal up to
     * rounding. Each vertex's colour is explained term by term where the
     * trace was told the kd it was lit with ({@link PixelWatch#litEach}).
     */
    private static void gouraud(PixelWatch watch, LitState state, Terms terms) {
        double[] o = watch.outline();
        int s = watch.stride();
        int n = watch.vertices();
        double cx = watch.x() + 0.5;
        double cy = watch.y() + 0.5;
        for (int i = 1; i + 1 < n; i++) {
            int[] v = {0, i, i + 1};
            double[] b = barycentric(o, s, v, cx, cy);
            if (b == null) {
                continue;
            }
            double[] w = new double[3];
            double total = 0;
            for (int k = 0; k < 3; k++) {
                w[k] = b[k] * o[v[k] * s + 2];
                total += w[k];
            }
            List<Terms> piece = new ArrayList<>();
            for (int k = 0; k < 3; k++) {
                w[k] /= total;
                int at = v[k] * s;
                double q = o[at + 2];
                piece.add(new Terms().put("vertex", v[k]).put("panel", o[at], o[at + 1])
                        .put("z", o[at + 3] / q)
                        .put("colour", watch.colourAt(v[k])));
            }
            double[][] rows = originals(watch, n);
            if (rows == null) {
                terms.put("lit_at", "the vertices of the fan triangle holding the pixel");
                terms.put("vertex_colours", piece);
                terms.put("weights", w);
                return;
            }
            int m = watch.unclippedCount();
            double[] p = watch.unclippedVertices();
            int ps = watch.unclippedStride();
            double[] u = new double[m];
            double[] weighted = new double[3];
            for (int k = 0; k < m; k++) {
                for (int j = 0; j < 3; j++) {
                    u[k] += w[j] * rows[v[j]][k];
                }
            }
            double[] kd = watch.litEach();
            List<Terms> vertices = new ArrayList<>();
            for (int k = 0; k < m; k++) {
                int at = k * ps;
                double[] c = {p[at + 3], p[at + 4], p[at + 5]};
                for (int j = 0; j < 3; j++) {
                    weighted[j] += u[k] * c[j];
                }
                Terms vertex = new Terms().put("vertex", k).put("camera", p[at], p[at + 1], p[at + 2]);
                if (kd != null && kd.length >= 3 * m) {
                    Terms lighting = new Terms();
                    double[] sum = LightingTerms.explain(state, new double[] {p[at], p[at + 1], p[at + 2]},
                            new double[] {p[at + 6], p[at + 7], p[at + 8]}, "N_vertex", watch.hasFaceNormalOnly(),
                            new double[] {kd[3 * k], kd[3 * k + 1], kd[3 * k + 2]}, lighting);
                    lighting.put("clamped", clamp(sum));
                    vertex.put("lighting", lighting);
                }
                vertices.add(vertex.put("colour", c));
            }
            terms.put("lit_at", "each vertex of the polygon, before clipping (SPEC Part 2)");
            terms.put("vertex_colours", vertices);
            terms.put("weights", u);
            terms.put("weighted", weighted);
            if (cut(watch, m)) {
                for (int k = 0; k < 3; k++) {
                    piece.get(k).put("of_the_vertices", rows[v[k]]);
                }
                terms.put("fan_piece", new Terms().put("why", "the clipper cut the polygon: the pixel is in this "
                        + "triangle of the clipped polygon's fan, whose vertices' colours are lerped from the lit ones")
                        .put("vertices", piece).put("weights", w));
            } else if (m > 3) {
                terms.put("fan_triangle", new Terms().put("vertices", piece).put("weights", w));
            }
            return;
        }
    }

    /**
     * Row i: clipped vertex i as weights of the polygon's m vertices before
     * clipping; null when the primitive's vertices before clipping were not
     * told or do not clip to the drawn outline's n vertices.
     */
    private static double[][] originals(PixelWatch watch, int n) {
        int m = watch.unclippedCount();
        if (m < 3) {
            return null;
        }
        double[] p = watch.unclippedVertices();
        int ps = watch.unclippedStride();
        int stride = 3 + m;
        double[] marked = new double[stride * m];
        for (int k = 0; k < m; k++) {
            System.arraycopy(p, k * ps, marked, k * stride, 3);
            marked[k * stride + 3 + k] = 1;
        }
        Clipper clipper = new Clipper(stride);
        int kept = clipper.clipPolygon(watch.camera(), marked, 0, m);
        if (kept != n) {
            return null;
        }
        double[] out = clipper.vertices();
        double[][] rows = new double[n][];
        for (int i = 0; i < n; i++) {
            rows[i] = Arrays.copyOfRange(out, i * stride + 3, i * stride + 3 + m);
        }
        return rows;
    }

    /**
     * Whether a flat polygon was lit with its face normal rather than the sum
     * of its vertices' own normals: the drawing gives the face normal to every
     * vertex without a normal of its own, and lights with it when there is
     * one such vertex, so the normal it lit with is then some vertex's, to
     * the bit (a sum of unit normals equals one of them only when the others
     * cancel).
     */
    private static boolean faceNormal(PixelWatch watch, double[] once) {
        double[] p = watch.unclippedVertices();
        int ps = watch.unclippedStride();
        for (int k = 0; k < watch.unclippedCount() && ps >= 9; k++) {
            int at = k * ps;
            if (p[at + 6] == once[3] && p[at + 7] == once[4] && p[at + 8] == once[5]) {
                return true;
            }
        }
        return false;
    }

    /** Whether some vertex of the polygon before clipping was outside the view. */
    private static boolean cut(PixelWatch watch, int m) {
        double[] p = watch.unclippedVertices();
        int ps = watch.unclippedStride();
        for (int k = 0; k < m; k++) {
            if (watch.camera().outcode(p[k * ps], p[k * ps + 1], p[k * ps + 2]) != 0) {
                return true;
            }
        }
        return false;
    }

    /** Screen-space barycentric coordinates of (cx, cy) in triangle v of the outline, or null when outside. */
    private static double[] barycentric(double[] o, int s, int[] v, double cx, double cy) {
        double x0 = o[v[0] * s], y0 = o[v[0] * s + 1];
        double x1 = o[v[1] * s], y1 = o[v[1] * s + 1];
        double x2 = o[v[2] * s], y2 = o[v[2] * s + 1];
        double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        if (area == 0) {
            return null;
        }
        double b0 = ((x1 - cx) * (y2 - cy) - (x2 - cx) * (y1 - cy)) / area;
        double b1 = ((x2 - cx) * (y0 - cy) - (x0 - cx) * (y2 - cy)) / area;
        double b2 = 1 - b0 - b1;
        double slack = -1e-9;
        return b0 >= slack && b1 >= slack && b2 >= slack ? new double[] {b0, b1, b2} : null;
    }

    private static double[] clamp(double[] c) {
        double[] out = new double[3];
        for (int k = 0; k < 3; k++) {
            out[k] = c[k] > 0 ? Math.min(c[k], 1) : 0;
        }
        return out;
    }
}
