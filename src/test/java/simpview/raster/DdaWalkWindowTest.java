package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A DDA walk kept to a window of rows visits exactly the whole walk's pixels
 * on those rows, with the same t, to the bit: lines along x and y, either
 * way, starting on and off the surface, against windows of every size.
 */
class DdaWalkWindowTest {

    private static final int SIZE = 200;

    /** x, y and the bits of t of every pixel visited, in order. */
    private static List<String> visits(DdaWalk walk, double[] line, int from, int to) {
        List<String> out = new ArrayList<>();
        if (walk.start(line[0], line[1], line[2], line[3], SIZE, SIZE)) {
            while (walk.next()) {
                if (walk.y() >= from && walk.y() < to) {
                    out.add(walk.x() + "," + walk.y() + "," + Double.doubleToLongBits(walk.t()));
                }
            }
        }
        return out;
    }

    @Test
    void aWindowedWalkVisitsTheWholeWalksPixelsOnItsRows() {
        Random random = new Random(5);
        int[][] windows = {{0, 1}, {0, 13}, {13, 14}, {40, 97}, {97, 200}, {199, 200}, {0, 200}};
        for (int i = 0; i < 3000; i++) {
            // Ends from well off the surface to inside it, some along an axis.
            double[] line = new double[4];
            for (int c = 0; c < 4; c++) {
                line[c] = -150 + 500 * random.nextDouble();
            }
            if (i % 10 == 0) {
                line[3] = line[1];
            } else if (i % 10 == 1) {
                line[2] = line[0];
            }
            for (int[] w : windows) {
                DdaWalk windowed = new DdaWalk();
                windowed.rows(w[0], w[1]);
                assertEquals(visits(new DdaWalk(), line, w[0], w[1]), visits(windowed, line, 0, SIZE),
                        "line " + Arrays.toString(line) + ", rows " + w[0] + " to " + w[1]);
            }
        }
    }
}
