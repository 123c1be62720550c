package simpview.testing;

import simpview.surface.ZBuffer;

/** A z-buffer's depths as their bits, so that two drawings compare to the bit (-0 and +0, NaNs, apart). */
public final class DepthBits {

    private DepthBits() {
    }

    /** Every depth of {@code zbuffer}, row by row, as {@link Double#doubleToRawLongBits} gives it. */
    public static long[] of(ZBuffer zbuffer) {
        double[] depths = zbuffer.copyDepths();
        long[] bits = new long[depths.length];
        for (int i = 0; i < depths.length; i++) {
            bits[i] = Double.doubleToRawLongBits(depths[i]);
        }
        return bits;
    }
}
