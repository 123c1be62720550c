package simpview.tools.shapes;

/**
 * Triangle meshes of simple solids, written as SIMP polygons. Each solid sits
 * in a unit frame so a scene places it with scale and translate:
 * the sphere has radius 1 around the origin; cylinder, cone and pyramid
 * stand on y = 0 with radius (or half-width) 1 and height 1.
 * StrictMath keeps the output the same on every machine.
 */
final class Solids {

    private Solids() {
    }

    /** The unit cube, every coordinate 0 or 1: two triangles per face. */
    static String cube() {
        SimpWriter w = header("unit cube, corners at 0 and 1");
        int[][] faces = {
            {0, 1, 3, 2}, {4, 6, 7, 5}, // x = 0, x = 1
            {0, 4, 5, 1}, {2, 3, 7, 6}, // y = 0, y = 1
            {0, 2, 6, 4}, {1, 5, 7, 3}, // z = 0, z = 1
        };
        for (int[] f : faces) {
            // Corner index bits are x, y, z: 4 = x, 2 = y, 1 = z.
            w.polygon(corner(f[0]), corner(f[1]), corner(f[2]));
            w.polygon(corner(f[0]), corner(f[2]), corner(f[3]));
        }
        return w.toString();
    }

    private static double[] corner(int bits) {
        return new double[] {bits >> 2 & 1, bits >> 1 & 1, bits & 1};
    }

    /** A UV sphere: {@code slices} around the y axis, {@code stacks} from pole to pole. */
    static String sphere(int slices, int stacks) {
        SimpWriter w = header("sphere of radius 1 around the origin, " + slices + " slices, " + stacks + " stacks");
        for (int j = 0; j < stacks; j++) {
            for (int i = 0; i < slices; i++) {
                double[] a = onSphere(i, j, slices, stacks);
                double[] b = onSphere(i + 1, j, slices, stacks);
                double[] c = onSphere(i + 1, j + 1, slices, stacks);
                double[] d = onSphere(i, j + 1, slices, stacks);
                if (j > 0) {
                    w.polygon(a, b, c); // not at the south pole, where a and b coincide
                }
                if (j < stacks - 1) {
                    w.polygon(a, c, d); // not at the north pole, where c and d coincide
                }
            }
        }
        return w.toString();
    }

    private static double[] onSphere(int i, int j, int slices, int stacks) {
        double theta = 2 * StrictMath.PI * (i % slices) / slices;
        double phi = StrictMath.PI * j / stacks - StrictMath.PI / 2;
        double r = StrictMath.cos(phi);
        return new double[] {r * StrictMath.cos(theta), StrictMath.sin(phi), -r * StrictMath.sin(theta)};
    }

    /** A closed cylinder of radius 1 from y = 0 to y = 1. */
    static String cylinder(int slices) {
        SimpWriter w = header("cylinder of radius 1 from y = 0 to y = 1, " + slices + " slices, closed");
        for (int i = 0; i < slices; i++) {
            double[] a = onCircle(i, slices, 0);
            double[] b = onCircle(i + 1, slices, 0);
            double[] c = onCircle(i + 1, slices, 1);
            double[] d = onCircle(i, slices, 1);
            w.polygon(a, b, c);
            w.polygon(a, c, d);
            w.polygon(new double[] {0, 0, 0}, b, a);
            w.polygon(new double[] {0, 1, 0}, d, c);
        }
        return w.toString();
    }

    /** A closed circular cone: base of radius 1 on y = 0, apex at (0, 1, 0). */
    static String cone(int slices) {
        SimpWriter w = header("circular cone, base radius 1 on y = 0, apex at (0, 1, 0), " + slices + " slices");
        double[] apex = {0, 1, 0};
        double[] centre = {0, 0, 0};
        for (int i = 0; i < slices; i++) {
            double[] a = onCircle(i, slices, 0);
            double[] b = onCircle(i + 1, slices, 0);
            w.polygon(a, b, apex);
            w.polygon(centre, b, a);
        }
        return w.toString();
    }

    /** A square pyramid: base from -1 to 1 in x and z on y = 0, apex at (0, 1, 0). */
    static String pyramid() {
        SimpWriter w = header("square pyramid, base -1..1 in x and z on y = 0, apex at (0, 1, 0)");
        double[][] base = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
        double[] apex = {0, 1, 0};
        for (int i = 0; i < 4; i++) {
            w.polygon(base[i], base[(i + 1) % 4], apex);
        }
        w.polygon(base[0], base[2], base[1]);
        w.polygon(base[0], base[3], base[2]);
        return w.toString();
    }

    private static double[] onCircle(int i, int slices, double y) {
        double theta = 2 * StrictMath.PI * (i % slices) / slices;
        return new double[] {StrictMath.cos(theta), y, -StrictMath.sin(theta)};
    }

    static SimpWriter header(String what) {
        return new SimpWriter()
                .comment(what)
                .comment("written by simpview.tools.shapes.ShapeGenerator; regenerate rather than edit")
                .blank();
    }
}
