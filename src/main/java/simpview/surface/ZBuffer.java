package simpview.surface;

import java.util.Arrays;
import simpview.geometry.ViewVolume;

/**
 * One world-space depth per pixel; larger z is nearer. Reset to the far plane.
 *
 * <p>Only a {@link ZBufferDrawable} writes the depths, and it says so
 * ({@link #written}) before it returns from a write. So the buffer knows when
 * every entry is still at the far plane, and a reset then costs nothing: the
 * pages that draw without depth (1 and 2) do not pay for filling 3.4 MB.
 */
public final class ZBuffer {

    private final int width;
    private final int height;
    final double[] depth;
    /** True only while every entry is FAR_Z. */
    private boolean atFarPlane;

    public ZBuffer(int width, int height) {
        this.width = width;
        this.height = height;
        this.depth = new double[width * height];
        reset();
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Every entry back to the far plane, z = -200. */
    public void reset() {
        if (!atFarPlane) {
            Arrays.fill(depth, ViewVolume.FAR_Z);
            atFarPlane = true;
        }
    }

    /** Some entry may now differ from the far plane. */
    void written() {
        atFarPlane = false;
    }

    /** True when no depth has been written since the last reset. */
    boolean atFarPlane() {
        return atFarPlane;
    }

    /** A copy of every depth, row by row (row y at y * width). */
    public double[] copyDepths() {
        return depth.clone();
    }

    public double depthAt(int x, int y) {
        return depth[y * width + x];
    }
}
