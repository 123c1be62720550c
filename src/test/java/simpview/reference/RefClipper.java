package simpview.reference;

import java.util.ArrayList;
import java.util.List;

/**
 * Clipping in camera space against the view's six planes. A vertex is a
 * double[] whose first three slots are its camera-space position; every slot
 * (position, colour, normal, ...) of a new vertex is interpolated linearly
 * at the crossing.
 */
final class RefClipper {

    /** SPEC's order: hither, yon, left, right, bottom, top. */
    static final int PLANES = 6;

    private RefClipper() {
    }

    /** True when every vertex is outside one and the same plane (SPEC's culling). */
    static boolean culled(RefView view, List<double[]> vertices) {
        for (int plane = 0; plane < PLANES; plane++) {
            boolean allOutside = true;
            for (double[] v : vertices) {
                allOutside &= view.inside(plane, v) < 0;
            }
            if (allOutside) {
                return true;
            }
        }
        return false;
    }

    /**
     * Sutherland-Hodgman, plane by plane; each pass walks the edges from the
     * last vertex to the first, then on. The result may be empty.
     */
    static List<double[]> polygon(RefView view, List<double[]> vertices) {
        List<double[]> current = vertices;
        for (int plane = 0; plane < PLANES && !current.isEmpty(); plane++) {
            List<double[]> next = new ArrayList<>();
            int n = current.size();
            for (int i = 0; i < n; i++) {
                double[] from = current.get((i + n - 1) % n);
                double[] to = current.get(i);
                double dFrom = view.inside(plane, from);
                double dTo = view.inside(plane, to);
                if (dTo >= 0) {
                    if (dFrom < 0) {
                        next.add(crossing(from, to, dFrom, dTo));
                    }
                    next.add(to);
                } else if (dFrom >= 0) {
                    next.add(crossing(from, to, dFrom, dTo));
                }
            }
            current = next;
        }
        return current;
    }

    /** Parametric (Liang-Barsky) clipping of a segment; null when nothing is left. */
    static double[][] line(RefView view, double[] a, double[] b) {
        double t0 = 0;
        double t1 = 1;
        for (int plane = 0; plane < PLANES; plane++) {
            double da = view.inside(plane, a);
            double db = view.inside(plane, b);
            if (da < 0 && db < 0) {
                return null;
            }
            if (da < 0) {
                t0 = Math.max(t0, da / (da - db));
            } else if (db < 0) {
                t1 = Math.min(t1, da / (da - db));
            }
        }
        if (t0 > t1) {
            return null;
        }
        return new double[][] {t0 == 0 ? a : lerp(a, b, t0), t1 == 1 ? b : lerp(a, b, t1)};
    }

    private static double[] crossing(double[] from, double[] to, double dFrom, double dTo) {
        return lerp(from, to, dFrom / (dFrom - dTo));
    }

    static double[] lerp(double[] a, double[] b, double t) {
        double[] out = new double[a.length];
        for (int k = 0; k < a.length; k++) {
            out[k] = a[k] + (b[k] - a[k]) * t;
        }
        return out;
    }
}
