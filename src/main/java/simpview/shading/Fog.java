package simpview.shading;

import simpview.surface.Colors;

/**
 * Depth fog, {@code depth near far r g b}: on a pixel's camera-space z, z >=
 * near keeps the colour I, z <= far gives the fog colour, and between them
 * {@code t I + (1 - t) fog} with {@code t = (z - far) / (near - far)}.
 * Applied to the clamped colour; the result is packed, round(c * 255) once.
 */
public record Fog(double near, double far, double r, double g, double b) {

    /** No fog: every colour is kept. */
    public static final Fog NONE = new Fog(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, 0, 0, 0);

    /** The fogged colour of (r, g, b) at depth z, packed as 0xAARRGGBB. */
    public int argb(double z, double cr, double cg, double cb) {
        if (z >= near) {
            return Colors.pack(cr, cg, cb);
        }
        if (z <= far) {
            return Colors.pack(r, g, b);
        }
        double t = (z - far) / (near - far);
        double s = 1 - t;
        return Colors.pack(t * cr + s * r, t * cg + s * g, t * cb + s * b);
    }
}
