package simpview.reference;

import java.awt.image.BufferedImage;
import simpview.testing.Images;

/**
 * How much of one 650x650 panel agrees with another: a pixel of the first
 * agrees when the second has a colour within `tolerance` (per channel, of
 * 255) at the same place or, with slack, at one of the 8 pixels around it.
 * Panels are packed 0xRRGGBB, in image order (row 0 at the top).
 */
final class PanelAgreement {

    static final int N = RefView.PANEL;

    private PanelAgreement() {
    }

    /** The panel whose top-left pixel is at (left, top) of the image. */
    static int[] panel(BufferedImage image, int left, int top) {
        return Images.rgb(image, left, top, N, N);
    }

    /** The panel of a 750x750 page. */
    static int[] pagePanel(BufferedImage page) {
        return panel(page, RefRaster.MARGIN, RefRaster.MARGIN);
    }

    /** The share in [0, 1] of `ours`'s pixels that agree with `theirs`. */
    static double share(int[] ours, int[] theirs, int tolerance, boolean slack) {
        long agreeing = 0;
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                agreeing += agrees(ours[y * N + x], theirs, x, y, tolerance, slack ? 1 : 0) ? 1 : 0;
            }
        }
        return agreeing / (double) (N * N);
    }

    private static boolean agrees(int colour, int[] theirs, int x, int y, int tolerance, int reach) {
        for (int dy = -reach; dy <= reach; dy++) {
            for (int dx = -reach; dx <= reach; dx++) {
                int tx = x + dx;
                int ty = y + dy;
                if (tx >= 0 && tx < N && ty >= 0 && ty < N && close(colour, theirs[ty * N + tx], tolerance)) {
                    return true;
                }
            }
        }
        return false;
    }

    static boolean close(int a, int b, int tolerance) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)) > tolerance) {
                return false;
            }
        }
        return true;
    }

    /** Pixels of `ours` that do not agree, for pictures of where two panels differ. */
    static boolean[] disagreeing(int[] ours, int[] theirs, int tolerance, boolean slack) {
        boolean[] out = new boolean[N * N];
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                out[y * N + x] = !agrees(ours[y * N + x], theirs, x, y, tolerance, slack ? 1 : 0);
            }
        }
        return out;
    }
}
