package simpview.reference;

import java.awt.image.BufferedImage;
import java.util.Arrays;

/**
 * The reference's panel, z-buffer and rasterizers, the plain way: every
 * pixel centre of a projected triangle's bounding box is tested with
 * barycentric weights (top-left rule on ties); lines are DDA between the
 * rounded endpoints, from the smaller-x (or smaller-y) end. Every attribute slot of a vertex is
 * interpolated perspective-correctly (a/z and 1/z linear on screen; linear
 * in the parallel view). The z-buffer holds camera-space z (slot 2), starts
 * at -infinity and takes only strictly nearer (greater) writes.
 */
final class RefRaster {

    static final int N = RefView.PANEL;
    static final int MARGIN = 50;
    static final int PAGE = N + 2 * MARGIN;

    /** What colour a pixel gets from its interpolated attributes: packed 0xRRGGBB. */
    interface Fragment {
        int colour(double[] attributes);
    }

    /** Panel pixels, row 0 at the bottom, packed 0xRRGGBB. */
    final int[] panel = new int[N * N];
    private final double[] zbuffer = new double[N * N];

    RefRaster() {
        Arrays.fill(zbuffer, Double.NEGATIVE_INFINITY);
    }

    void triangle(RefView view, double[] a, double[] b, double[] c, Fragment fragment) {
        double[][] v = {a, b, c};
        double[][] s = new double[3][];
        for (int i = 0; i < 3; i++) {
            s[i] = new double[] {view.panelX(v[i]), view.panelY(v[i]), view.weight(v[i])};
        }
        double area = edge(s[0], s[1], s[2][0], s[2][1]);
        if (area == 0 || Double.isNaN(area)) {
            return;
        }
        if (area < 0) {
            swap(v, 1, 2);
            swap(s, 1, 2);
            area = -area;
        }
        int x0 = Math.max(0, (int) Math.floor(Math.min(s[0][0], Math.min(s[1][0], s[2][0]))));
        int x1 = Math.min(N - 1, (int) Math.ceil(Math.max(s[0][0], Math.max(s[1][0], s[2][0]))));
        int y0 = Math.max(0, (int) Math.floor(Math.min(s[0][1], Math.min(s[1][1], s[2][1]))));
        int y1 = Math.min(N - 1, (int) Math.ceil(Math.max(s[0][1], Math.max(s[1][1], s[2][1]))));
        double[] attributes = new double[a.length];
        double[] w = new double[3];
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                double px = x + 0.5;
                double py = y + 0.5;
                w[0] = edge(s[1], s[2], px, py);
                w[1] = edge(s[2], s[0], px, py);
                w[2] = edge(s[0], s[1], px, py);
                if (covers(w[0], s[1], s[2]) && covers(w[1], s[2], s[0]) && covers(w[2], s[0], s[1])) {
                    double sum = 0;
                    for (int i = 0; i < 3; i++) {
                        w[i] = w[i] / area * s[i][2];
                        sum += w[i];
                    }
                    for (int k = 0; k < attributes.length; k++) {
                        attributes[k] = (w[0] * v[0][k] + w[1] * v[1][k] + w[2] * v[2][k]) / sum;
                    }
                    plot(x, y, attributes, fragment);
                }
            }
        }
    }

    /**
     * DDA as SPEC words it: endpoints rounded to the nearest pixel, from the
     * smaller-x end (x-major) or the smaller-y end (y-major), the minor
     * coordinate adding the slope per step, rounded half up; attributes
     * perspective-correct from the start end to the other.
     */
    void line(RefView view, double[] p, double[] q, Fragment fragment) {
        double x0 = Math.floor(view.panelX(p) + 0.5);
        double y0 = Math.floor(view.panelY(p) + 0.5);
        double x1 = Math.floor(view.panelX(q) + 0.5);
        double y1 = Math.floor(view.panelY(q) + 0.5);
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        boolean swap = xMajor ? x1 < x0 : y1 < y0;
        double[] a = swap ? q : p;
        double[] b = swap ? p : q;
        double ax = swap ? x1 : x0;
        double ay = swap ? y1 : y0;
        double bx = swap ? x0 : x1;
        double by = swap ? y0 : y1;
        double qa = view.weight(a);
        double qb = view.weight(b);
        double steps = xMajor ? bx - ax : by - ay;
        double slope = steps == 0 ? 0 : (xMajor ? by - ay : bx - ax) / steps;
        double minor = xMajor ? ay : ax;
        double[] attributes = new double[a.length];
        for (int k = 0; k <= steps; k++, minor += slope) {
            double t = steps == 0 ? 0 : k / steps;
            double wa = (1 - t) * qa;
            double wb = t * qb;
            for (int i = 0; i < attributes.length; i++) {
                attributes[i] = (wa * a[i] + wb * b[i]) / (wa + wb);
            }
            double m = Math.floor(minor + 0.5);
            plot((int) (xMajor ? ax + k : m), (int) (xMajor ? m : ay + k), attributes, fragment);
        }
    }

    private void plot(int x, int y, double[] attributes, Fragment fragment) {
        if (x < 0 || x >= N || y < 0 || y >= N) {
            return;
        }
        int i = y * N + x;
        if (attributes[2] > zbuffer[i]) {
            zbuffer[i] = attributes[2];
            panel[i] = fragment.colour(attributes);
        }
    }

    private static double edge(double[] p, double[] q, double x, double y) {
        return (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]);
    }

    /** Counter-clockwise, y up: a left edge runs down, a top edge runs toward -x. */
    private static boolean covers(double w, double[] p, double[] q) {
        double dy = q[1] - p[1];
        double dx = q[0] - p[0];
        return w > 0 || (w == 0 && (dy < 0 || (dy == 0 && dx < 0)));
    }

    private static void swap(double[][] v, int i, int j) {
        double[] t = v[i];
        v[i] = v[j];
        v[j] = t;
    }

    /** The 750x750 page: white margins around the panel (image rows run down). */
    BufferedImage page() {
        int[] rows = new int[PAGE * PAGE];
        Arrays.fill(rows, 0xFFFFFF);
        for (int y = 0; y < N; y++) {
            System.arraycopy(panel, y * N, rows, (MARGIN + N - 1 - y) * PAGE + MARGIN, N);
        }
        BufferedImage image = new BufferedImage(PAGE, PAGE, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, PAGE, PAGE, rows, 0, PAGE);
        return image;
    }
}
