package simpview.inspect;

import java.util.ArrayList;
import java.util.List;
import simpview.shading.Lights;
import simpview.shading.LitState;

/**
 * SPEC's lighting formula written out term by term for one point, for the
 * reader: {@code I = kd Ia + sum_i (Ii fi) (kd (N . Li) + ks max(0, V . Ri)^p)}.
 * The colour the pixel got is {@link simpview.shading.Lighting}'s, which the
 * explanation reports beside these terms; these are the same formula in
 * plain steps, so a reader can follow each number.
 */
final class LightingTerms {

    private LightingTerms() {
    }

    /**
     * Puts P, N, kd and where it came from ({@code kdFrom}), V, the ambient term, every light's terms and their
     * sum into {@code terms}; returns the sum.
     */
    static double[] explain(LitState state, double[] point, double[] normal, boolean faceNormal, double[] kd,
            String kdFrom, Terms terms) {
        return explain(state, point, normal, "N_interpolated", faceNormal, kd, kdFrom, terms);
    }

    /**
     * The same, the normal before it is made unit named {@code normalName} ("N_interpolated", "N_summed",
     * "N_face", "N_vertex"); {@code faceNormal} when it is the polygon's face normal, no vertex having its own.
     */
    static double[] explain(LitState state, double[] point, double[] normal, String normalName, boolean faceNormal,
            double[] kd, Terms terms) {
        return explain(state, point, normal, normalName, faceNormal, kd, null, terms);
    }

    /**
     * What N . V &lt; 0 means for a polygon's face normal ({@code faceNormal}; interpolated or not, it is the
     * same at every vertex), or for its vertices' own normals: a face normal faces away only from a polygon seen
     * from its back; the vertices' own normals (summed, at a vertex, interpolated) may point away near an outline
     * of a polygon that faces the eye.
     */
    static String facingAway(boolean faceNormal) {
        String behind = "a light on the eye's side of it is behind it";
        if (faceNormal) {
            return "away from the eye (N . V < 0): the eye sees the polygon's back (its face normal faces away where "
                    + "its vertices run clockwise on the panel), and " + behind;
        }
        return "away from the eye (N . V < 0): N, made from the vertices' own normals, points away from the eye, and "
                + behind + "; such normals may point away near an outline (a silhouette) even where the polygon faces "
                + "the eye, its vertices running counter-clockwise on the panel";
    }

    private static double[] explain(LitState state, double[] point, double[] normal, String normalName,
            boolean faceNormal, double[] kd, String kdFrom, Terms terms) {
        double[] n = unit(normal);
        boolean perspective = state.camera().isPerspective();
        double[] v = perspective ? unit(new double[] {-point[0], -point[1], -point[2]}) : new double[] {0, 0, 1};
        terms.put("P", point);
        terms.put(normalName, normal);
        terms.put("N_length", length(normal));
        terms.put("N", n);
        terms.put("kd", kd);
        if (kdFrom != null) {
            terms.put("kd_from", kdFrom);
        }
        terms.put("V", v);
        double nv = dot(n, v);
        if (nv < 0) {
            terms.put("N_dot_V", nv);
            terms.put("facing", facingAway(faceNormal));
        }
        terms.put("ks", state.ks());
        terms.put("p", state.p());
        double[] ia = {state.ambientR(), state.ambientG(), state.ambientB()};
        double[] sum = {kd[0] * ia[0], kd[1] * ia[1], kd[2] * ia[2]};
        terms.put("ambient", new Terms().put("Ia", ia).put("kd_Ia", sum.clone()));
        List<Terms> lights = new ArrayList<>();
        Lights all = state.lights();
        boolean usable = length(normal) > 0 && Double.isFinite(length(normal));
        for (int i = 0; i < state.lightCount(); i++) {
            Terms t = new Terms();
            double[] at = {all.x(i), all.y(i), all.z(i)};
            double[] intensity = {all.red(i), all.green(i), all.blue(i)};
            double[] toLight = {at[0] - point[0], at[1] - point[1], at[2] - point[2]};
            double d = length(toLight);
            double f = 1 / (all.a(i) + all.b(i) * d);
            double[] l = unit(toLight);
            double nl = dot(n, l);
            t.put("position", at).put("intensity", intensity).put("A", all.a(i)).put("B", all.b(i));
            t.put("L", l).put("distance", d).put("f", f).put("N_dot_L", nl);
            if (!usable || !(nl > 0)) {
                t.put("behind_surface", true);
                t.put("diffuse", 0, 0, 0).put("specular", 0, 0, 0);
            } else {
                double[] r = {2 * nl * n[0] - l[0], 2 * nl * n[1] - l[1], 2 * nl * n[2] - l[2]};
                double vr = dot(v, r);
                double power = Math.pow(Math.max(0, Math.min(vr, 1)), state.p());
                double[] diffuse = new double[3];
                double[] specular = new double[3];
                for (int c = 0; c < 3; c++) {
                    diffuse[c] = intensity[c] * f * kd[c] * nl;
                    specular[c] = intensity[c] * f * state.ks() * power;
                    sum[c] += diffuse[c] + specular[c];
                }
                t.put("behind_surface", false);
                t.put("R", r).put("V_dot_R", vr).put("V_dot_R_pow_p", power);
                t.put("diffuse", diffuse).put("specular", specular);
            }
            lights.add(t);
        }
        terms.put("lights", lights);
        terms.put("sum", sum);
        return sum;
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double length(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    /** a / |a|, or zero for a zero (or not finite) vector. */
    static double[] unit(double[] a) {
        double s = length(a);
        if (!(s > 0) || !Double.isFinite(s)) {
            return new double[3];
        }
        return new double[] {a[0] / s, a[1] / s, a[2] / s};
    }
}
