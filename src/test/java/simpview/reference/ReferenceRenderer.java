package simpview.reference;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A second, deliberately naive renderer of SIMP scenes, written straight from
 * SPEC and sharing no code with simpview: regex reading, recursion for
 * `file`, plain Math.sin/cos, 4x4 arrays, and brute-force rasterization that
 * tests every pixel centre of a triangle's bounding box with barycentric
 * weights. Slow and obviously correct is the point; it is the kind of
 * independent reference the pictures are judged against.
 */
final class ReferenceRenderer {

    static final int N = 650;
    private static final Pattern NUMBER = Pattern.compile("[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?");

    /** Panel pixels, row 0 at the bottom, packed 0xRRGGBB. */
    final int[] panel = new int[N * N];
    private final double[] zbuffer = new double[N * N];
    private final double[] near;
    private final double[] far;
    private boolean wire;

    ReferenceRenderer(double[] near, double[] far) {
        this.near = near;
        this.far = far;
        Arrays.fill(zbuffer, -200);
    }

    void render(Path file) throws IOException {
        run(file, identity(), new ArrayDeque<>());
    }

    /** Reads one file as if its lines stood in the including file; returns the CTM it leaves. */
    private double[][] run(Path file, double[][] start, Deque<double[][]> stack) throws IOException {
        double[][] ctm = start;
        for (String raw : Files.readAllLines(file)) {
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String word = line.split("\\s+", 2)[0];
            double[] n = numbers(line.substring(word.length()));
            switch (word) {
                case "{" -> stack.push(ctm);
                case "}" -> ctm = stack.pop();
                case "scale" -> ctm = times(ctm, diagonal(n[0], n[1], n[2]));
                case "translate" -> ctm = times(ctm, translation(n[0], n[1], n[2]));
                case "rotate" -> ctm = times(ctm, rotation(line.split("\\s+")[1].charAt(0), n[0]));
                case "wire" -> wire = true;
                case "filled" -> wire = false;
                case "line" -> primitive(ctm, n, 2);
                case "polygon" -> primitive(ctm, n, 3);
                case "file" -> {
                    String name = line.substring(4).strip().replace("\"", "");
                    ctm = run(file.resolveSibling(name + ".simp"), ctm, stack);
                }
                default -> throw new IllegalArgumentException("reference cannot read: " + line);
            }
        }
        return ctm;
    }

    private static double[] numbers(String text) {
        Matcher m = NUMBER.matcher(text);
        List<Double> values = new ArrayList<>();
        while (m.find()) {
            values.add(Double.parseDouble(m.group()));
        }
        return values.stream().mapToDouble(Double::doubleValue).toArray();
    }

    private void primitive(double[][] ctm, double[] n, int count) {
        boolean colored = n.length == 6 * count;
        double[][] v = new double[count][];
        for (int i = 0; i < count; i++) {
            int at = colored ? 6 * i : 3 * i;
            v[i] = transform(ctm, n[at], n[at + 1], n[at + 2]);
        }
        if (culled(v)) {
            return;
        }
        double[][] p = new double[count][];
        for (int i = 0; i < count; i++) {
            p[i] = new double[] {(v[i][0] + 100) * 650 / 200, (v[i][1] + 100) * 650 / 200, v[i][2]};
        }
        if (count == 2) {
            line(p[0], p[1]);
        } else if (wire) {
            line(p[0], p[1]);
            line(p[1], p[2]);
            line(p[2], p[0]);
        } else {
            triangle(p[0], p[1], p[2]);
        }
    }

    private static boolean culled(double[][] v) {
        double[] lo = {-100, -100, -200};
        double[] hi = {100, 100, 0};
        for (int axis = 0; axis < 3; axis++) {
            boolean allBelow = true;
            boolean allAbove = true;
            for (double[] p : v) {
                allBelow &= p[axis] < lo[axis];
                allAbove &= p[axis] > hi[axis];
            }
            if (allBelow || allAbove) {
                return true;
            }
        }
        return false;
    }

    /** Every pixel centre in the bounding box, barycentric weights, top-left rule on ties. */
    private void triangle(double[] a, double[] b, double[] c) {
        double area = edge(a, b, c[0], c[1]);
        if (area == 0) {
            return;
        }
        if (area < 0) {
            double[] t = b;
            b = c;
            c = t;
            area = -area;
        }
        int x0 = Math.max(0, (int) Math.floor(Math.min(a[0], Math.min(b[0], c[0]))));
        int x1 = Math.min(N - 1, (int) Math.ceil(Math.max(a[0], Math.max(b[0], c[0]))));
        int y0 = Math.max(0, (int) Math.floor(Math.min(a[1], Math.min(b[1], c[1]))));
        int y1 = Math.min(N - 1, (int) Math.ceil(Math.max(a[1], Math.max(b[1], c[1]))));
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                double px = x + 0.5;
                double py = y + 0.5;
                double wa = edge(b, c, px, py);
                double wb = edge(c, a, px, py);
                double wc = edge(a, b, px, py);
                if (covers(wa, b, c) && covers(wb, c, a) && covers(wc, a, b)) {
                    plot(x, y, (wa * a[2] + wb * b[2] + wc * c[2]) / area);
                }
            }
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

    /**
     * DDA as SPEC words it: endpoints rounded to the nearest pixel, from the
     * smaller-x end (x-major) or the smaller-y end (y-major), the minor
     * coordinate adding the slope per step, rounded half up.
     */
    private void line(double[] p, double[] q) {
        double x0 = Math.floor(p[0] + 0.5);
        double y0 = Math.floor(p[1] + 0.5);
        double x1 = Math.floor(q[0] + 0.5);
        double y1 = Math.floor(q[1] + 0.5);
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        boolean swap = xMajor ? x1 < x0 : y1 < y0;
        double[] a = swap ? q : p;
        double[] b = swap ? p : q;
        double ax = swap ? x1 : x0;
        double ay = swap ? y1 : y0;
        double bx = swap ? x0 : x1;
        double by = swap ? y0 : y1;
        double steps = xMajor ? bx - ax : by - ay;
        double slope = steps == 0 ? 0 : (xMajor ? by - ay : bx - ax) / steps;
        double minor = xMajor ? ay : ax;
        for (int k = 0; k <= steps; k++, minor += slope) {
            double t = steps == 0 ? 0 : k / steps;
            double m = Math.floor(minor + 0.5);
            plot((int) (xMajor ? ax + k : m), (int) (xMajor ? m : ay + k), a[2] + (b[2] - a[2]) * t);
        }
    }

    private void plot(int x, int y, double z) {
        if (x < 0 || x >= N || y < 0 || y >= N || z > 0 || z < -200) {
            return;
        }
        int i = y * N + x;
        if (z > zbuffer[i]) {
            zbuffer[i] = z;
            double f = (z + 200) / 200;
            int rgb = 0;
            for (int ch = 0; ch < 3; ch++) {
                double c = far[ch] + (near[ch] - far[ch]) * f;
                rgb = rgb << 8 | (int) Math.max(0, Math.min(255, Math.round(c * 255)));
            }
            panel[i] = rgb;
        }
    }

    private static double[] transform(double[][] m, double x, double y, double z) {
        double[] out = new double[3];
        for (int r = 0; r < 3; r++) {
            out[r] = m[r][0] * x + m[r][1] * y + m[r][2] * z + m[r][3];
        }
        return out;
    }

    private static double[][] identity() {
        return diagonal(1, 1, 1);
    }

    private static double[][] diagonal(double sx, double sy, double sz) {
        return new double[][] {{sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, sz, 0}, {0, 0, 0, 1}};
    }

    private static double[][] translation(double tx, double ty, double tz) {
        return new double[][] {{1, 0, 0, tx}, {0, 1, 0, ty}, {0, 0, 1, tz}, {0, 0, 0, 1}};
    }

    private static double[][] rotation(char axis, double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return switch (axis) {
            case 'X' -> new double[][] {{1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1}};
            case 'Y' -> new double[][] {{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1}};
            default -> new double[][] {{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
        };
    }

    private static double[][] times(double[][] a, double[][] b) {
        double[][] p = new double[4][4];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                for (int k = 0; k < 4; k++) {
                    p[r][c] += a[r][k] * b[k][c];
                }
            }
        }
        return p;
    }
}
