package simpview.raster;

import java.util.Arrays;
import simpview.geometry.ViewVolume;

/** One world-space depth per pixel; larger z is nearer. Reset to the far plane. */
public final class ZBuffer {

    private final int width;
    private final int height;
    final double[] depth;

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
        Arrays.fill(depth, ViewVolume.FAR_Z);
    }

    public double depthAt(int x, int y) {
        return depth[y * width + x];
    }
}
