package simpview.shading;

import java.util.Arrays;

/**
 * The pixels of short phong spans that passed the depth test and wait, with
 * the numbers their point is lit with, to be lit at the picture's end if the
 * pixel is still theirs ({@link FragmentStage#shadeWaiting}): where each is,
 * its z, kd, P and N as the pixel's fragment resolved them, who drew it and
 * its look (an index into the stage's looks).
 *
 * <p>Why the pixel is still theirs exactly when its depth is still their z: a
 * later fragment wins a pixel only when strictly nearer, so each later winner
 * left a larger depth there (a NaN z never wins), and no two winners of one
 * pixel have one z.
 *
 * <p>Primitive arrays, grown as needed and kept from picture to picture; not
 * for two threads (a stage's own).
 */
final class WaitingPoints {

    int count;
    int[] x = new int[256];
    int[] y = new int[256];
    int[] owner = new int[256];
    int[] look = new int[256];
    double[] z = new double[256];
    double[] kdRed = new double[256];
    double[] kdGreen = new double[256];
    double[] kdBlue = new double[256];
    double[] px = new double[256];
    double[] py = new double[256];
    double[] nx = new double[256];
    double[] ny = new double[256];
    double[] nz = new double[256];

    /** Room for one more point: its index. */
    int add() {
        int i = count;
        if (i == x.length) {
            grow(2 * i);
        }
        count = i + 1;
        return i;
    }

    private void grow(int capacity) {
        x = Arrays.copyOf(x, capacity);
        y = Arrays.copyOf(y, capacity);
        owner = Arrays.copyOf(owner, capacity);
        look = Arrays.copyOf(look, capacity);
        z = Arrays.copyOf(z, capacity);
        kdRed = Arrays.copyOf(kdRed, capacity);
        kdGreen = Arrays.copyOf(kdGreen, capacity);
        kdBlue = Arrays.copyOf(kdBlue, capacity);
        px = Arrays.copyOf(px, capacity);
        py = Arrays.copyOf(py, capacity);
        nx = Arrays.copyOf(nx, capacity);
        ny = Arrays.copyOf(ny, capacity);
        nz = Arrays.copyOf(nz, capacity);
    }

    /** None wait. */
    void clear() {
        count = 0;
    }
}
