package simpview.window;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * The page made smaller than 1:1 without losing a line. Each screen pixel
 * stands for a box of more than one page pixel; a nearest-neighbour scale
 * shows one of them and drops the rest, so 1-px lines break or vanish. Here
 * each screen pixel shows the page pixel of its box that stands out most from
 * its surroundings: the one farthest (in the sum of its channels' distances)
 * from the mean colour of the box widened by one page pixel on every side.
 * A lone line pixel in a dark or light box is that pixel; a box of one
 * colour stays that colour. Every page pixel lies in at least one box, and
 * every shown colour is a page pixel's own colour (nothing is blended).
 *
 * <p>A filter over the finished image, written here: it picks among the
 * picture's pixels and makes none. The windows' means come from summed-area
 * tables of the three channels (four looks a window). It runs on the EDT
 * once per picture and zoom (the view keeps the result).
 */
public final class LineKeepingDownscale {

    private LineKeepingDownscale() {
    }

    /** The side of {@code size} page pixels shown at {@code zoom} (below 1). */
    public static int shownSide(int size, double zoom) {
        return (int) Math.ceil(size * zoom);
    }

    /**
     * The image at {@code zoom} (0 &lt; zoom &lt; 1): pixel (i, j) of the
     * result stands for page columns [i/zoom, (i+1)/zoom) and rows likewise.
     */
    public static BufferedImage of(BufferedImage page, double zoom) {
        if (!(zoom > 0 && zoom < 1)) {
            throw new IllegalArgumentException("a downscale needs a zoom between 0 and 1, not " + zoom);
        }
        int width = page.getWidth();
        int height = page.getHeight();
        int[] source = pixels(page);
        int outWidth = shownSide(width, zoom);
        int outHeight = shownSide(height, zoom);
        int[] colFrom = new int[outWidth];
        int[] colTo = new int[outWidth];
        spans(width, zoom, colFrom, colTo);
        int[] rowFrom = new int[outHeight];
        int[] rowTo = new int[outHeight];
        spans(height, zoom, rowFrom, rowTo);
        // Summed-area tables of the three channels: any window's sum in four looks.
        int stride = width + 1;
        int[] sumR = new int[stride * (height + 1)];
        int[] sumG = new int[sumR.length];
        int[] sumB = new int[sumR.length];
        for (int y = 0; y < height; y++) {
            int r = 0;
            int g = 0;
            int b = 0;
            int row = y * width;
            int above = y * stride;
            int here = above + stride;
            for (int x = 0; x < width; x++) {
                int c = source[row + x];
                r += (c >> 16) & 0xFF;
                g += (c >> 8) & 0xFF;
                b += c & 0xFF;
                sumR[here + x + 1] = sumR[above + x + 1] + r;
                sumG[here + x + 1] = sumG[above + x + 1] + g;
                sumB[here + x + 1] = sumB[above + x + 1] + b;
            }
        }
        int[] out = new int[outWidth * outHeight];
        for (int j = 0; j < outHeight; j++) {
            int y0 = rowFrom[j];
            int y1 = rowTo[j];
            int top = Math.max(0, y0 - 1) * stride;
            int bottom = Math.min(height, y1 + 1) * stride;
            int rows = (bottom - top) / stride;
            for (int i = 0; i < outWidth; i++) {
                int x0 = colFrom[i];
                int x1 = colTo[i];
                int left = Math.max(0, x0 - 1);
                int right = Math.min(width, x1 + 1);
                int n = rows * (right - left);
                // The window's sums: n times its mean; the distances are compared at n times their size.
                long mr = sumR[bottom + right] - sumR[bottom + left] - sumR[top + right] + sumR[top + left];
                long mg = sumG[bottom + right] - sumG[bottom + left] - sumG[top + right] + sumG[top + left];
                long mb = sumB[bottom + right] - sumB[bottom + left] - sumB[top + right] + sumB[top + left];
                int best = source[y0 * width + x0];
                long bestDistance = -1;
                for (int y = y0; y < y1; y++) {
                    int row = y * width;
                    for (int x = x0; x < x1; x++) {
                        int c = source[row + x];
                        long distance = Math.abs(n * ((c >> 16) & 0xFF) - mr) + Math.abs(n * ((c >> 8) & 0xFF) - mg)
                                + Math.abs(n * (c & 0xFF) - mb);
                        if (distance > bestDistance) {
                            bestDistance = distance;
                            best = c;
                        }
                    }
                }
                out[j * outWidth + i] = best;
            }
        }
        BufferedImage result = new BufferedImage(outWidth, outHeight, BufferedImage.TYPE_INT_RGB);
        System.arraycopy(out, 0, ((DataBufferInt) result.getRaster().getDataBuffer()).getData(), 0, out.length);
        return result;
    }

    /**
     * The page's pixels, 0xRRGGBB row by row: read straight from an int RGB
     * picture's raster (only read here), else converted (getRGB through the
     * colour model costs tens of nanoseconds a pixel).
     */
    private static int[] pixels(BufferedImage page) {
        int width = page.getWidth();
        int height = page.getHeight();
        if ((page.getType() == BufferedImage.TYPE_INT_RGB || page.getType() == BufferedImage.TYPE_INT_ARGB)
                && page.getRaster().getDataBuffer() instanceof DataBufferInt ints && ints.getNumBanks() == 1
                && ints.getOffset() == 0 && page.getRaster().getParent() == null
                && ints.getData().length == width * height) {
            return ints.getData();
        }
        return page.getRGB(0, 0, width, height, null, 0, width);
    }

    /** For each shown pixel k, the page pixels [from[k], to[k]) whose extent meets [k/zoom, (k+1)/zoom). */
    private static void spans(int size, double zoom, int[] from, int[] to) {
        for (int k = 0; k < from.length; k++) {
            int a = (int) Math.floor(k / zoom);
            int b = (int) Math.ceil((k + 1) / zoom);
            from[k] = Math.min(size - 1, a);
            to[k] = Math.max(from[k] + 1, Math.min(size, b));
        }
    }
}
