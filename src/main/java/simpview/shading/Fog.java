package simpview.shading;

/**
 * The {@code depth near far r g b} command's fog, on a pixel's camera-space z:
 * z &gt;= near keeps the colour I, z &lt;= far gives the fog colour, between them
 * t I + (1 - t) fog with t = (z - far) / (near - far). It is applied to the
 * lit colour after clamping, before each channel becomes round(c * 255).
 * {@link #NONE} (no {@code depth} yet) keeps every colour.
 */
public record Fog(double near, double far, double r, double g, double b) {

    /** No fog: every z is at or beyond near = -infinity. */
    public static final Fog NONE = new Fog(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, 0, 0, 0);

    public boolean isNone() {
        return near == Double.NEGATIVE_INFINITY;
    }

    /**
     * Fogs the colour at colour[at], colour[at + 1], colour[at + 2] in place
     * for depth z. A NaN z keeps the colour; t is kept in [0, 1], so the
     * result lies between the colour and the fog colour.
     */
    public void apply(double z, double[] colour, int at) {
        if (!(z < near)) {
            return;
        }
        if (z <= far) {
            colour[at] = r;
            colour[at + 1] = g;
            colour[at + 2] = b;
            return;
        }
        double t = (z - far) / (near - far);
        if (!(t < 1)) {
            return;
        }
        if (!(t > 0)) {
            t = 0;
        }
        double s = 1 - t;
        colour[at] = t * colour[at] + s * r;
        colour[at + 1] = t * colour[at + 1] + s * g;
        colour[at + 2] = t * colour[at + 2] + s * b;
    }
}
