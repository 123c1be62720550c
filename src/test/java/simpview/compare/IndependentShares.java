package simpview.compare;

import java.awt.image.BufferedImage;
import simpview.testing.Images;

/**
 * The shares computed again for the tests, the plainest way: each panel's
 * pixels as getRGB gives them, given by their top-left corners, and nested
 * loops over the 3x3 neighbours. Written apart from {@link Comparison},
 * sharing no code.
 */
public final class IndependentShares {

    static final int N = 650;

    private IndependentShares() {
    }

    /** The share of pixels whose every channel is within {@code tolerance}, without slack. */
    public static double direct(BufferedImage a, int ax, int ay, BufferedImage b, int bx, int by, int tolerance) {
        int[] pa = Images.rgb(a, ax, ay, N, N);
        int[] pb = Images.rgb(b, bx, by, N, N);
        long count = 0;
        for (int i = 0; i < N * N; i++) {
            if (close(pa[i], pb[i], tolerance)) {
                count++;
            }
        }
        return count / (double) (N * N);
    }

    /** The share with slack: a's colour found near the pixel in b, and b's found near it in a. */
    public static double withSlack(BufferedImage a, int ax, int ay, BufferedImage b, int bx, int by, int tolerance) {
        int[] pa = Images.rgb(a, ax, ay, N, N);
        int[] pb = Images.rgb(b, bx, by, N, N);
        long count = 0;
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                boolean aInB = foundNear(pa[y * N + x], pb, x, y, tolerance);
                boolean bInA = foundNear(pb[y * N + x], pa, x, y, tolerance);
                if (aInB && bInA) {
                    count++;
                }
            }
        }
        return count / (double) (N * N);
    }

    private static boolean foundNear(int colour, int[] other, int x, int y, int tolerance) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int nx = x + dx;
                int ny = y + dy;
                if (nx >= 0 && ny >= 0 && nx < N && ny < N && close(colour, other[ny * N + nx], tolerance)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean close(int p, int q, int tolerance) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs((p >> shift & 0xFF) - (q >> shift & 0xFF)) > tolerance) {
                return false;
            }
        }
        return true;
    }
}
