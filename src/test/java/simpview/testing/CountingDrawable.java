package simpview.testing;

import simpview.surface.Drawable;

/**
 * A test surface that counts writes per pixel and remembers the last colour
 * and depth. Spans go through the interface's default, pixel by pixel. Writes
 * outside the surface are counted as strays instead of being stored.
 */
public final class CountingDrawable implements Drawable {

    private final int width;
    private final int height;
    private final int[] counts;
    private final int[] colors;
    private final double[] depths;
    private long writes;
    private long strays;

    public CountingDrawable(int width, int height) {
        this.width = width;
        this.height = height;
        this.counts = new int[width * height];
        this.colors = new int[width * height];
        this.depths = new double[width * height];
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        writes++;
        if (x < 0 || x >= width || y < 0 || y >= height) {
            strays++;
            return;
        }
        counts[y * width + x]++;
        colors[y * width + x] = argb;
        depths[y * width + x] = z;
    }

    @Override
    public int getPixel(int x, int y) {
        return colors[y * width + x];
    }

    public int count(int x, int y) {
        return counts[y * width + x];
    }

    public double depth(int x, int y) {
        return depths[y * width + x];
    }

    public long writes() {
        return writes;
    }

    public long strays() {
        return strays;
    }

    /** How many pixels were written at least once. */
    public int covered() {
        int n = 0;
        for (int c : counts) {
            n += c > 0 ? 1 : 0;
        }
        return n;
    }

    public int maxCount() {
        int max = 0;
        for (int c : counts) {
            max = Math.max(max, c);
        }
        return max;
    }
}
