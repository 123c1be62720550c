package simpview.tools.shapes;

/**
 * .obj models of simple solids for the project's lit scenes: a smooth torus
 * whose vertices carry their own normals ({@code vn}), and a faceted crystal
 * without normals (every face lit by its face normal). Faces are
 * counter-clockwise seen from outside. StrictMath keeps the output the same
 * on every machine.
 */
final class Models {

    private Models() {
    }

    /**
     * A torus around the y axis: the tube's centre circle has radius
     * {@code major}, the tube radius {@code minor}; {@code around} quads along
     * the ring, {@code tube} around the tube. Vertex k has normal k.
     */
    static String torus(double major, double minor, int around, int tube) {
        ObjWriter w = header("torus around the y axis, ring radius " + SimpWriter.number(major) + ", tube radius "
                + SimpWriter.number(minor) + ", " + around + " x " + tube + " quads with vertex normals");
        for (int i = 0; i < around; i++) {
            for (int j = 0; j < tube; j++) {
                double u = 2 * StrictMath.PI * i / around;
                double v = 2 * StrictMath.PI * j / tube;
                double[] n = {StrictMath.cos(v) * StrictMath.cos(u), StrictMath.sin(v),
                    -StrictMath.cos(v) * StrictMath.sin(u)};
                double ring = major + minor * StrictMath.cos(v);
                w.vertex(new double[] {ring * StrictMath.cos(u), minor * n[1], -ring * StrictMath.sin(u)});
                w.normal(n);
            }
        }
        w.blank();
        for (int i = 0; i < around; i++) {
            for (int j = 0; j < tube; j++) {
                int a = index(i, j, around, tube);
                int b = index(i + 1, j, around, tube);
                int c = index(i + 1, j + 1, around, tube);
                int d = index(i, j + 1, around, tube);
                w.smoothFace(a, b, c, d);
            }
        }
        return w.toString();
    }

    private static int index(int i, int j, int around, int tube) {
        return 1 + (i % around) * tube + j % tube;
    }

    /**
     * A crystal: a {@code sides}-sided prism of radius 1 from y = -0.5 to
     * y = 0.5, with a point at each end (y = -1.4 and y = 1.4). Quads on
     * the sides, triangles at the points; no normals.
     */
    static String crystal(int sides) {
        ObjWriter w = header(sides + "-sided crystal: a prism of radius 1 from y = -0.5 to 0.5, points at y = -1.4"
                + " and 1.4; faceted, no normals");
        for (int k = 0; k < sides; k++) {
            double theta = 2 * StrictMath.PI * k / sides;
            w.vertex(new double[] {StrictMath.cos(theta), -0.5, -StrictMath.sin(theta)});
            w.vertex(new double[] {StrictMath.cos(theta), 0.5, -StrictMath.sin(theta)});
        }
        int low = 2 * sides + 1;
        int high = 2 * sides + 2;
        w.vertex(new double[] {0, -1.4, 0});
        w.vertex(new double[] {0, 1.4, 0});
        w.blank();
        for (int k = 0; k < sides; k++) {
            int bottom = 2 * k + 1;
            int top = 2 * k + 2;
            int nextBottom = 2 * ((k + 1) % sides) + 1;
            int nextTop = nextBottom + 1;
            w.face(bottom, nextBottom, nextTop, top);
            w.face(top, nextTop, high);
            w.face(nextBottom, bottom, low);
        }
        return w.toString();
    }

    private static ObjWriter header(String what) {
        return new ObjWriter()
                .comment(what)
                .comment("written by simpview.tools.shapes.ShapeGenerator; regenerate rather than edit")
                .blank();
    }
}
