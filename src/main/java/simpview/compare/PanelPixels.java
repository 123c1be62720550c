package simpview.compare;

import java.util.Arrays;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/**
 * A black n x n panel to draw on, held as a comparison holds a panel: row by row from the top, each pixel
 * 0xRRGGBB; written in the panel's own coordinates (origin bottom-left, y up), a write outside it dropped. A hint
 * draws simpview's primitives onto one with a mistake put in, to see whether that mistake explains a picture.
 */
final class PanelPixels implements Drawable {

    private final int n;
    private final int[] rgb;

    PanelPixels(int n) {
        this.n = n;
        rgb = new int[n * n];
        Arrays.fill(rgb, PageCanvas.BACKGROUND & 0xFFFFFF);
    }

    /** The pixels, row by row from the top. */
    int[] pixels() {
        return rgb;
    }

    @Override
    public int width() {
        return n;
    }

    @Override
    public int height() {
        return n;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        if (x >= 0 && y >= 0 && x < n && y < n) {
            rgb[(n - 1 - y) * n + x] = argb & 0xFFFFFF;
        }
    }

    @Override
    public int getPixel(int x, int y) {
        return x >= 0 && y >= 0 && x < n && y < n ? 0xFF000000 | rgb[(n - 1 - y) * n + x] : 0;
    }
}
