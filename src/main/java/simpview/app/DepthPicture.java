package simpview.app;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import simpview.geometry.ViewVolume;
import simpview.surface.Colors;
import simpview.surface.PageCanvas;

/**
 * The z-buffer shown as a page: each panel pixel grey by its stored depth,
 * white at the near plane (z = 0) to black at the far plane (z = -200),
 * {@code round(255 * (z + 200) / 200)}; a pixel no write ever reached (still
 * at the far plane it was reset to) is marked in {@link #UNTOUCHED}. Margins
 * stay white, as on the page.
 */
final class DepthPicture {

    /** The colour of pixels whose depth was never written: a dark slate blue, not a grey. */
    static final int UNTOUCHED = 0xFF203860;

    private DepthPicture() {
    }

    /** The grey of a written depth, in 0xAARRGGBB. */
    static int grey(double z) {
        double t = (z - ViewVolume.FAR_Z) / (ViewVolume.NEAR_Z - ViewVolume.FAR_Z);
        int v = Colors.toByte(t);
        return 0xFF000000 | v << 16 | v << 8 | v;
    }

    static boolean untouched(double z) {
        return !(z > ViewVolume.FAR_Z);
    }

    /** The picture of {@code depths}, the panel's z-buffer in rows from the bottom (panel y up). */
    static BufferedImage of(double[] depths) {
        BufferedImage image = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        java.util.Arrays.fill(pixels, Colors.WHITE);
        int panel = PageCanvas.PANEL;
        for (int y = 0; y < panel; y++) {
            int row = (PageCanvas.MARGIN + panel - 1 - y) * PageCanvas.SIZE + PageCanvas.MARGIN;
            for (int x = 0; x < panel; x++) {
                double z = depths[y * panel + x];
                pixels[row + x] = untouched(z) ? UNTOUCHED : grey(z);
            }
        }
        return image;
    }
}
