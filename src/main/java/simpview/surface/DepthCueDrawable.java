package simpview.surface;

import simpview.geometry.Camera;

/**
 * Depth cueing: each write's colour is replaced by the colour of its depth,
 * {@code far + (near - far) * (z + 200) / 200} per channel, near at the
 * camera's near plane (z = 0 in Part 1) and far at its far plane (z = -200). The map is linear in z, so on a span whose z is linear the
 * colour stays linear and only the span's colour coefficients change.
 */
public final class DepthCueDrawable extends DrawableDecorator {

    // Per channel, in byte levels: colour(z) = far + slope * (z - farZ).
    private final double farR;
    private final double farG;
    private final double farB;
    private final double slopeR;
    private final double slopeG;
    private final double slopeB;
    private final double farZ;

    public DepthCueDrawable(Rgb near, Rgb far, Camera camera, Drawable delegate) {
        super(delegate);
        farZ = camera.yon();
        double depthRange = camera.hither() - farZ;
        farR = 255 * far.r();
        farG = 255 * far.g();
        farB = 255 * far.b();
        slopeR = 255 * (near.r() - far.r()) / depthRange;
        slopeG = 255 * (near.g() - far.g()) / depthRange;
        slopeB = 255 * (near.b() - far.b()) / depthRange;
    }

    /** The colour of every write is replaced, so none is needed from above. */
    @Override
    public boolean usesColour() {
        return false;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        double depth = z - farZ;
        delegate.setPixel(x, y, z, Colors.packLevels(farR + slopeR * depth,
                farG + slopeG * depth, farB + slopeB * depth));
    }

    @Override
    public void fillSpan(Span s) {
        double depth = s.z - farZ;
        s.r = farR + slopeR * depth;
        s.g = farG + slopeG * depth;
        s.b = farB + slopeB * depth;
        s.dr = slopeR * s.dz;
        s.dg = slopeG * s.dz;
        s.db = slopeB * s.dz;
        delegate.fillSpan(s);
    }
}
