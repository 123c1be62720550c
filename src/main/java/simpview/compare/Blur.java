package simpview.compare;

/**
 * The small blur of the perceptual metric: each channel convolved with the
 * 3x3 binomial kernel (1 2 1)/4 across and the same down, the panel's edge
 * pixels repeated outward. It is the lowest-pass filter that joins a pixel to
 * its eight neighbours, about what the eye does to one-pixel detail at 1:1,
 * so two valid antialiasings of one edge (a coverage ramp here, a different
 * ramp there) come out nearly the same, while a missing or moved shape does
 * not. Integer arithmetic, rounded to nearest: the result is deterministic.
 */
public final class Blur {

    private Blur() {
    }

    /** A blurred copy of a 650x650 panel of 0xRRGGBB pixels. */
    public static int[] of(int[] panel) {
        return of(panel, PanelPlace.SIZE);
    }

    /** A blurred copy of a square panel of n x n 0xRRGGBB pixels (the first assignment's are 300x300). */
    public static int[] of(int[] panel, int n) {
        int[] across = new int[n * n * 3];
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int left = panel[y * n + Math.max(0, x - 1)];
                int centre = panel[y * n + x];
                int right = panel[y * n + Math.min(n - 1, x + 1)];
                int o = (y * n + x) * 3;
                for (int c = 0; c < 3; c++) {
                    int shift = 16 - 8 * c;
                    across[o + c] = (left >> shift & 0xFF) + 2 * (centre >> shift & 0xFF) + (right >> shift & 0xFF);
                }
            }
        }
        int[] out = new int[n * n];
        for (int y = 0; y < n; y++) {
            int up = Math.max(0, y - 1) * n;
            int down = Math.min(n - 1, y + 1) * n;
            for (int x = 0; x < n; x++) {
                int rgb = 0;
                for (int c = 0; c < 3; c++) {
                    int sum = across[(up + x) * 3 + c] + 2 * across[(y * n + x) * 3 + c] + across[(down + x) * 3 + c];
                    rgb |= ((sum + 8) >> 4) << (16 - 8 * c);
                }
                out[y * n + x] = rgb;
            }
        }
        return out;
    }
}
