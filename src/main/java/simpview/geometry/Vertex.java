package simpview.geometry;

/**
 * A point with a colour. Where it lives depends on the stage: SIMP files give
 * it in object space, the CTM takes it to world space, and the renderers take
 * it in panel space (x, y in pixels, y up; z still world depth).
 * Colour channels are in [0, 1].
 */
public record Vertex(double x, double y, double z, double r, double g, double b) {

    public static Vertex of(double x, double y, double z) {
        return new Vertex(x, y, z, 1, 1, 1);
    }

    public Vertex withPosition(double nx, double ny, double nz) {
        return new Vertex(nx, ny, nz, r, g, b);
    }

    public Vertex withColor(double nr, double ng, double nb) {
        return new Vertex(x, y, z, nr, ng, nb);
    }

    /** True when every coordinate is a finite number. */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }
}
