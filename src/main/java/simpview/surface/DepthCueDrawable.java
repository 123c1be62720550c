package simpview.surface;

import simpview.geometry.Camera;

/**
 * Depth cueing: each write's colour is replaced by the colour of its depth,
 * {@code far + (near - far) * (z + 200) / 200} per channel, near at the
 * camera's near plane (z = 0 in Part 1) and far at its far plane (z = -200). The map is linear in z, so on a span whose z is linear the
 * colour stays linear and only the span's colour coefficients change.
 */
public final class DepthCueDrawable extends DrawableDecorator {

    /*
     * In byte levels, per channel: level(z) = (far * range + rise * (z - farZ)) / range,
     * far and rise = near - far in levels (255 times the colour), range the
     * depth range (200 in Part 1). The division comes last, so that a level
     * the formula puts exactly on a half is computed as that half, and
     * rounds up as SPEC's round(c * 255) does: z = -100 from white to black
     * is 255 * 100 / 200 = 127.5 exactly, level 128. (With the slope
     * 255 / 200 = 1.275 taken first, which no double holds, it came out
     * 127.49999999999999, level 127, and z = -20 229.49999999999997, level
     * 229; the other halves, at z = -60, -140 and -180, happened to come out
     * exact.) For colours whose levels are whole numbers, as
     * 0 and 1 give, the numerator is exact and so is every half. A span's
     * steps along x keep the slope: only its first pixel is placed so.
     */
    /** far times range, per channel: the numerator's constant part. */
    private final double farRangeR;
    private final double farRangeG;
    private final double farRangeB;
    private final double riseR;
    private final double riseG;
    private final double riseB;
    private final double slopeR;
    private final double slopeG;
    private final double slopeB;
    private final double farZ;
    private final double range;

    public DepthCueDrawable(Rgb near, Rgb far, Camera camera, Drawable delegate) {
        super(delegate);
        farZ = camera.yon();
        range = camera.hither() - farZ;
        farRangeR = 255 * far.r() * range;
        farRangeG = 255 * far.g() * range;
        farRangeB = 255 * far.b() * range;
        riseR = 255 * (near.r() - far.r());
        riseG = 255 * (near.g() - far.g());
        riseB = 255 * (near.b() - far.b());
        slopeR = riseR / range;
        slopeG = riseG / range;
        slopeB = riseB / range;
    }

    /** The colour of every write is replaced, so none is needed from above. */
    @Override
    public boolean usesColour() {
        return false;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        double depth = z - farZ;
        delegate.setPixel(x, y, z, Colors.packLevels((farRangeR + riseR * depth) / range,
                (farRangeG + riseG * depth) / range, (farRangeB + riseB * depth) / range));
    }

    @Override
    public void fillSpan(Span s) {
        double depth = s.z - farZ;
        s.r = (farRangeR + riseR * depth) / range;
        s.g = (farRangeG + riseG * depth) / range;
        s.b = (farRangeB + riseB * depth) / range;
        s.dr = slopeR * s.dz;
        s.dg = slopeG * s.dz;
        s.db = slopeB * s.dz;
        delegate.fillSpan(s);
    }
}
