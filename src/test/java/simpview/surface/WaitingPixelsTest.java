package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link WaitingPixels#runEnd} against a plain walk of {@link WaitingPixels#at}:
 * every run of a row, waiting or not, on rows filled at random.
 */
class WaitingPixelsTest {

    @Test
    void aRunEndsWhereThePixelsStopWaitingForItsSpan() {
        WaitingPixels w = new WaitingPixels(40, 3);
        w.waitRun(1, 5, 9, 2);
        w.wait(9, 1, 3);
        w.waitRun(1, 12, 15, 2);
        assertEquals(5, w.firstIn(1));
        assertEquals(15, w.endIn(1));
        assertEquals(9, w.runEnd(5, 1), "span 2's first run");
        assertEquals(9, w.runEnd(7, 1), "from its middle");
        assertEquals(10, w.runEnd(9, 1), "span 3's one pixel");
        assertEquals(12, w.runEnd(10, 1), "the pixels that wait for nothing between");
        assertEquals(15, w.runEnd(12, 1), "the last run ends with the row's waiting pixels");
        assertThrows(IndexOutOfBoundsException.class, () -> w.runEnd(4, 1));
        assertThrows(IndexOutOfBoundsException.class, () -> w.runEnd(15, 1));
        assertThrows(IndexOutOfBoundsException.class, () -> w.runEnd(0, 0), "a row with none");
    }

    @Test
    void runsFoundByTheirEndsAreThosePixelByPixel() {
        Random random = new Random(1204);
        int width = 64;
        for (int trial = 0; trial < 500; trial++) {
            WaitingPixels w = new WaitingPixels(width, 1);
            int marks = random.nextInt(20);
            for (int m = 0; m < marks; m++) {
                int x0 = random.nextInt(width);
                int x1 = Math.min(width, x0 + 1 + random.nextInt(12));
                w.waitRun(0, x0, x1, random.nextInt(3));
                if (random.nextInt(4) == 0) {
                    w.waitRun(0, x0 + random.nextInt(x1 - x0), x1, 3);
                }
            }
            for (int x = w.firstIn(0); x < w.endIn(0); x = w.runEnd(x, 0)) {
                int end = w.runEnd(x, 0);
                for (int i = x; i < end; i++) {
                    assertEquals(w.at(x, 0), w.at(i, 0), "trial " + trial + ": pixel " + i + " of the run from " + x);
                }
                assertTrue(end == w.endIn(0) || w.at(end, 0) != w.at(x, 0),
                        "trial " + trial + ": the run from " + x + " goes on past " + end);
            }
        }
    }
}
