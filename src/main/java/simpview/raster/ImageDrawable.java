package simpview.raster;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * The end of every chain: a BufferedImage written through its int[] raster.
 * Image coordinates: origin top-left, y down. Writes outside are dropped.
 */
public final class ImageDrawable implements Drawable {

    private final BufferedImage image;
    private final int[] pixels;
    private final int width;
    private final int height;

    public ImageDrawable(BufferedImage image) {
        int type = image.getType();
        if (type != BufferedImage.TYPE_INT_RGB && type != BufferedImage.TYPE_INT_ARGB) {
            throw new IllegalArgumentException("needs an INT_RGB or INT_ARGB image, got type " + type);
        }
        this.image = image;
        this.pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        this.width = image.getWidth();
        this.height = image.getHeight();
    }

    public BufferedImage image() {
        return image;
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
        if (x >= 0 && x < width && y >= 0 && y < height) {
            pixels[y * width + x] = argb;
        }
    }

    @Override
    public int getPixel(int x, int y) {
        if (x >= 0 && x < width && y >= 0 && y < height) {
            return pixels[y * width + x] | 0xFF000000;
        }
        return 0;
    }

    @Override
    public void fillSpan(Span s) {
        if (s.y < 0 || s.y >= height) {
            return;
        }
        int from = Math.max(s.x0, 0);
        int to = Math.min(s.x1, width);
        int row = s.y * width;
        double r = s.r;
        double dr = s.dr;
        double g = s.g;
        double dg = s.dg;
        double b = s.b;
        double db = s.db;
        for (int x = from; x < to; x++) {
            int k = x - s.xBase;
            pixels[row + x] = Colors.packLevels(r + k * dr, g + k * dg, b + k * db);
        }
    }

    /** Fills the rectangle [x0, x1) x [y0, y1) with one colour. */
    public void fillRect(int x0, int y0, int x1, int y1, int argb) {
        for (int y = Math.max(y0, 0); y < Math.min(y1, height); y++) {
            java.util.Arrays.fill(pixels, y * width + Math.max(x0, 0), y * width + Math.min(x1, width), argb);
        }
    }
}
