package simpview.geometry;

/**
 * A point with a colour. Where it lives depends on the stage: SIMP files give
 * it in object space, the CTM takes it to world space, and the renderers take
 * it in panel space (x, y in pixels, y up; z still world depth).
 * Colour channels are in [0, 1].
 */
public record Vertex(double x, double y, double z, double r, double g, double b) {

    /**
     * Numbers per vertex where vertices are kept in a double[] (x, y, z, r,
     * g, b, in that order): how the renderers take primitives without an
     * object per vertex.
     */
    public static final int NUMBERS = 6;
    // Where each number stands among a vertex's NUMBERS.
    public static final int X = 0;
    public static final int Y = 1;
    public static final int Z = 2;
    public static final int R = 3;
    public static final int G = 4;
    public static final int B = 5;

    public static Vertex of(double x, double y, double z) {
        return new Vertex(x, y, z, 1, 1, 1);
    }

    public Vertex withPosition(double nx, double ny, double nz) {
        return new Vertex(nx, ny, nz, r, g, b);
    }

    public Vertex withColor(double nr, double ng, double nb) {
        return new Vertex(x, y, z, nr, ng, nb);
    }

    /** The vertex whose {@link #NUMBERS} numbers start at p[at]. */
    public static Vertex readFrom(double[] p, int at) {
        return new Vertex(p[at + X], p[at + Y], p[at + Z], p[at + R], p[at + G], p[at + B]);
    }

    /** Writes this vertex's {@link #NUMBERS} numbers to p from p[at]. */
    public void writeTo(double[] p, int at) {
        p[at + X] = x;
        p[at + Y] = y;
        p[at + Z] = z;
        p[at + R] = r;
        p[at + G] = g;
        p[at + B] = b;
    }

    /** True when every coordinate is a finite number. */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    /** {@link #isFinite()} for the vertex whose numbers start at p[at]. */
    public static boolean isFinite(double[] p, int at) {
        return Double.isFinite(p[at + X]) && Double.isFinite(p[at + Y]) && Double.isFinite(p[at + Z]);
    }
}
