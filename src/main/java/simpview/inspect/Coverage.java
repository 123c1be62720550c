package simpview.inspect;

import java.util.Arrays;
import simpview.geometry.Camera;
import simpview.stage.Painter;

/**
 * Whether a primitive that did not reach a pixel (culled, clipped away, or
 * drawn but cut by the clipper elsewhere) would have covered it had it not
 * been culled or clipped: its part in front of the eye, projected as the
 * camera projects, covers the pixel's centre (a polygon: the centre inside
 * the projected outline; a line or a wire polygon's edge: SPEC's DDA rule,
 * endpoints rounded, one pixel per step of the major axis, the minor
 * coordinate rounded half up, steps the pixel).
 *
 * <p>"In front of the eye" for a perspective camera is the part with
 * {@code z <= -|hither| / 2^20}: the primitive is clipped against that plane
 * (parallel to the eye's plane z = 0, a millionth of the near distance in
 * front of it) before it is projected, so a primitive through the eye's
 * plane covers what its visible half would cover on a screen of unbounded
 * size, and a vertex at or behind the eye never makes the test fail or
 * project mirrored. A parallel camera projects every point as it is.
 */
final class Coverage {

    /** The eye plane's offset in front of the eye, as a share of the near distance. */
    static final double EYE_PLANE = 0x1p-20;

    private Coverage() {
    }

    static boolean covers(Camera camera, int kind, double[] p, int at, int stride, int n, int x, int y) {
        double[][] projected = projected(camera, kind, p, at, stride, n);
        if (projected == null) {
            return false;
        }
        double[] sx = projected[0];
        double[] sy = projected[1];
        int m = sx.length;
        if (kind == Painter.FILLED) {
            return m >= 3 && inside(sx, sy, m, x + 0.5, y + 0.5);
        }
        if (kind == Painter.LINE) {
            return onLine(sx[0], sy[0], sx[1], sy[1], x, y);
        }
        for (int k = 0; k < m; k++) {
            int j = (k + 1) % m;
            if (onLine(sx[k], sy[k], sx[j], sy[j], x, y)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The primitive's part in front of the eye, projected: its panel x and y
     * ({@code [0]} and {@code [1]}), or null when nothing of it is in front
     * of the eye or a vertex does not project to a finite point.
     */
    static double[][] projected(Camera camera, int kind, double[] p, int at, int stride, int n) {
        double[] xs = new double[n + 1];
        double[] ys = new double[n + 1];
        double[] zs = new double[n + 1];
        int m = n;
        for (int k = 0; k < n; k++) {
            int o = at + k * stride;
            xs[k] = p[o];
            ys[k] = p[o + 1];
            zs[k] = p[o + 2];
        }
        boolean closed = kind != Painter.LINE;
        if (camera.isPerspective()) {
            double eye = -Math.abs(camera.hither()) * EYE_PLANE;
            double[][] front = inFront(xs, ys, zs, n, closed, eye);
            if (front == null) {
                return null;
            }
            xs = front[0];
            ys = front[1];
            zs = front[2];
            m = xs.length;
        }
        double[] sx = new double[m];
        double[] sy = new double[m];
        for (int k = 0; k < m; k++) {
            sx[k] = camera.panelX(xs[k], zs[k]);
            sy[k] = camera.panelY(ys[k], zs[k]);
            if (!Double.isFinite(sx[k]) || !Double.isFinite(sy[k])) {
                return null;
            }
        }
        return new double[][] {sx, sy};
    }

    /**
     * The part of the polygon (closed) or line with {@code z <= eye}: its vertices'
     * x, y and z, or null when nothing of it is there. One Sutherland-Hodgman
     * pass; a line keeps its two ends, the one behind moved to the plane.
     */
    private static double[][] inFront(double[] xs, double[] ys, double[] zs, int n, boolean closed, double eye) {
        if (!closed) {
            boolean a = zs[0] <= eye;
            boolean b = zs[1] <= eye;
            if (!a && !b) {
                return null;
            }
            double[][] out = {{xs[0], xs[1]}, {ys[0], ys[1]}, {zs[0], zs[1]}};
            if (!a || !b) {
                int behind = a ? 1 : 0;
                int front = 1 - behind;
                double t = (eye - zs[front]) / (zs[behind] - zs[front]);
                out[0][behind] = xs[front] + t * (xs[behind] - xs[front]);
                out[1][behind] = ys[front] + t * (ys[behind] - ys[front]);
                out[2][behind] = eye;
            }
            return out;
        }
        double[] ox = new double[2 * n];
        double[] oy = new double[2 * n];
        double[] oz = new double[2 * n];
        int m = 0;
        for (int k = 0, j = n - 1; k < n; j = k++) {
            boolean in = zs[k] <= eye;
            if (in != (zs[j] <= eye)) {
                double t = (eye - zs[j]) / (zs[k] - zs[j]);
                ox[m] = xs[j] + t * (xs[k] - xs[j]);
                oy[m] = ys[j] + t * (ys[k] - ys[j]);
                oz[m++] = eye;
            }
            if (in) {
                ox[m] = xs[k];
                oy[m] = ys[k];
                oz[m++] = zs[k];
            }
        }
        if (m < 3) {
            return null;
        }
        return new double[][] {Arrays.copyOf(ox, m), Arrays.copyOf(oy, m),
            Arrays.copyOf(oz, m)};
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
        DdaSteps dda = DdaSteps.of(x0, y0, x1, y1);
        long step = dda.stepAt(x, y);
        if (step < 0 || step > dda.steps()) {
            return false;
        }
        int minor = dda.xMajor() ? y : x;
        return near(dda.minorStart(), dda.slope(), step, minor) && (long) Math.floor(dda.minorAt(step) + 0.5) == minor;
    }

    /** Whether the line's minor coordinate after that many steps is within a pixel of {@code at}: else no DDA walk is needed. */
    private static boolean near(long start, double slope, long steps, int at) {
        return Math.abs(start + slope * steps - at) < 2;
    }

    /** The minor coordinate after {@code steps} steps: the slope added once per step, as the DDA adds it. */
    static double minor(long start, double slope, long steps) {
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
