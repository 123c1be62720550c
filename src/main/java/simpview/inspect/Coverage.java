package simpview.inspect;

import simpview.geometry.Camera;
import simpview.stage.Painter;

/**
 * Whether a primitive that was never rasterized (culled, or clipped away)
 * would have covered a pixel had it been projected as it is: a polygon when
 * the pixel's centre is inside its projected outline, a line when SPEC's DDA
 * rule (endpoints rounded, one pixel per step of the major axis, the minor
 * coordinate rounded half up) steps on the pixel. A vertex that cannot be
 * projected (at or behind the eye) covers nothing.
 */
final class Coverage {

    private Coverage() {
    }

    static boolean covers(Camera camera, int kind, double[] p, int at, int stride, int n, int x, int y) {
        double[] sx = new double[n];
        double[] sy = new double[n];
        for (int k = 0; k < n; k++) {
            int o = at + k * stride;
            double z = p[o + 2];
            if (camera.isPerspective() && !(z < 0)) {
                return false;
            }
            sx[k] = camera.panelX(p[o], z);
            sy[k] = camera.panelY(p[o + 1], z);
            if (!Double.isFinite(sx[k]) || !Double.isFinite(sy[k])) {
                return false;
            }
        }
        if (kind == Painter.FILLED) {
            return inside(sx, sy, n, x + 0.5, y + 0.5);
        }
        if (kind == Painter.LINE) {
            return onLine(sx[0], sy[0], sx[1], sy[1], x, y);
        }
        for (int k = 0; k < n; k++) {
            int j = (k + 1) % n;
            if (onLine(sx[k], sy[k], sx[j], sy[j], x, y)) {
                return true;
            }
        }
        return false;
    }

    /** Even-odd crossing test of the point (cx, cy) against the polygon. */
    static boolean inside(double[] xs, double[] ys, int n, double cx, double cy) {
        boolean in = false;
        for (int i = 0, j = n - 1; i < n; j = i++) {
            if ((ys[i] > cy) != (ys[j] > cy)
                    && cx < (xs[j] - xs[i]) * (cy - ys[i]) / (ys[j] - ys[i]) + xs[i]) {
                in = !in;
            }
        }
        return in;
    }

    static boolean onLine(double x0, double y0, double x1, double y1, int x, int y) {
        long ax = (long) Math.floor(x0 + 0.5);
        long ay = (long) Math.floor(y0 + 0.5);
        long bx = (long) Math.floor(x1 + 0.5);
        long by = (long) Math.floor(y1 + 0.5);
        long dx = bx - ax;
        long dy = by - ay;
        if (Math.abs(dx) >= Math.abs(dy)) {
            if (ax > bx) {
                long t = ax; ax = bx; bx = t;
                t = ay; ay = by; by = t;
            }
            if (x < ax || x > bx) {
                return false;
            }
            double slope = ax == bx ? 0 : (double) (by - ay) / (bx - ax);
            return (long) Math.floor(minor(ay, slope, x - ax) + 0.5) == y;
        }
        if (ay > by) {
            long t = ax; ax = bx; bx = t;
            t = ay; ay = by; by = t;
        }
        if (y < ay || y > by) {
            return false;
        }
        double slope = (double) (bx - ax) / (by - ay);
        return (long) Math.floor(minor(ax, slope, y - ay) + 0.5) == x;
    }

    /** The minor coordinate after {@code steps} steps: the slope added once per step, as the DDA adds it. */
    private static double minor(long start, double slope, long steps) {
        if (steps > 1_000_000) {
            return start + slope * steps;
        }
        double v = start;
        for (long k = 0; k < steps; k++) {
            v += slope;
        }
        return v;
    }
}
