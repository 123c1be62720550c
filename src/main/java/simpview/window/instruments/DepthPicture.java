package simpview.window.instruments;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;
import simpview.geometry.Camera;
import simpview.surface.Colors;
import simpview.surface.PageCanvas;

/**
 * The z-buffer shown as a page: each panel pixel grey by its stored depth,
 * white at the near plane (z = 0) to black at the far plane (z = -200),
 * {@code round(255 * (z + 200) / 200)}; a pixel no write ever reached (still
 * at the far plane it was reset to) is marked in {@link #UNTOUCHED}. Margins
 * stay white, as on the page. A lit scene's z-buffer starts at -infinity
 * and holds camera-space depths: there the nearest and farthest depths
 * written are white and black, and a pixel still at -infinity is untouched.
 */
public final class DepthPicture {

    /** The colour of pixels whose depth was never written: a dark slate blue, not a grey. */
    static final int UNTOUCHED = 0xFF203860;

    private DepthPicture() {
    }

    private static final double NEAR = Camera.PARALLEL.hither();
    private static final double FAR = Camera.PARALLEL.yon();

    /** The grey of a written depth of a depth-cued page, in 0xAARRGGBB. */
    static int grey(double z) {
        return grey(z, NEAR, FAR);
    }

    private static int grey(double z, double near, double far) {
        double t = near == far ? 1 : (z - far) / (near - far);
        int v = Colors.toByte(t);
        return 0xFF000000 | v << 16 | v << 8 | v;
    }

    /** No write reached a pixel whose depth is still where the z-buffer started ({@code start}), or beyond. */
    static boolean untouched(double z, double start) {
        return !(z > start);
    }

    /**
     * The picture of {@code depths}, the panel's z-buffer in rows from the
     * bottom (panel y up), which started at {@code start}: the far plane for
     * a depth-cued page, -infinity for a lit scene.
     */
    public static BufferedImage of(double[] depths, double start) {
        double near = NEAR;
        double far = start;
        if (start == Double.NEGATIVE_INFINITY) {
            double nearest = Double.NEGATIVE_INFINITY;
            double farthest = Double.POSITIVE_INFINITY;
            for (double z : depths) {
                if (z > start) {
                    nearest = Math.max(nearest, z);
                    farthest = Math.min(farthest, z);
                }
            }
            if (nearest >= farthest) {
                near = nearest;
                far = Math.nextDown(farthest);
            }
        }
        BufferedImage image = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        Arrays.fill(pixels, Colors.WHITE);
        int panel = PageCanvas.PANEL;
        for (int y = 0; y < panel; y++) {
            int row = (PageCanvas.MARGIN + panel - 1 - y) * PageCanvas.SIZE + PageCanvas.MARGIN;
            for (int x = 0; x < panel; x++) {
                double z = depths[y * panel + x];
                pixels[row + x] = untouched(z, far) ? UNTOUCHED : grey(z, near, far);
            }
        }
        return image;
    }
}
