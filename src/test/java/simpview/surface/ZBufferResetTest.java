package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The reset a canvas's clear owes its z-buffer: made by the first to read or
 * test a depth, or replaced by a lit reset.
 */
class ZBufferResetTest {

    private static final int SIZE = PageCanvas.PANEL;

    @Test
    void anOwedResetIsMadeBeforeADepthIsReadOrTested() {
        ZBuffer z = new ZBuffer(SIZE, SIZE);
        ZBufferDrawable tested = new ZBufferDrawable(z, new DiscardingDrawable());
        tested.setPixel(3, 4, -50, Colors.WHITE);
        z.resetWhenNeeded(-200);
        assertFalse(z.atFarPlane(), "owed, not made");
        assertEquals(-200, z.depthAt(3, 4), "read: made first");
        assertTrue(z.atFarPlane());

        tested.setPixel(3, 4, -50, Colors.WHITE);
        z.resetWhenNeeded(-200);
        tested.setPixel(3, 4, -100, Colors.WHITE); // tested against -200, not the -50 before the clear
        assertEquals(-100, z.depthAt(3, 4));
        assertEquals(-200, z.copyDepths()[0]);
    }

    @Test
    void aLitResetReplacesTheOwedOne() {
        ZBuffer z = new ZBuffer(SIZE, SIZE);
        new ZBufferDrawable(z, new DiscardingDrawable()).setPixel(3, 4, -50, Colors.WHITE);
        z.resetWhenNeeded(-200);
        z.reset(Double.NEGATIVE_INFINITY);
        assertEquals(Double.NEGATIVE_INFINITY, z.depthAt(3, 4));

        new ZBufferDrawable(z, new DiscardingDrawable()).setPixel(3, 4, -50, Colors.WHITE);
        z.resetWhenNeeded(-200);
        z.resetByRows(Double.NEGATIVE_INFINITY);
        z.resetRows(0, SIZE / 2);
        assertEquals(Double.NEGATIVE_INFINITY, z.depthAt(3, 4), "a band's drawer reset its rows");
        assertEquals(Double.NEGATIVE_INFINITY, z.depthAt(0, 0));
        assertEquals(Double.NEGATIVE_INFINITY, z.farthest());
    }

    /**
     * A reset fills only the runs written since the row was last reset to the
     * same depth: after random writes (through the drawable, and raw as the
     * lit stage writes, each said by {@link ZBuffer#written(int, int, int)})
     * and random resets of every kind, to -200 and to -infinity, whole or by
     * rows, every depth is what a buffer filled whole at each reset holds.
     */
    @Test
    void aResetLeavesEveryDepthAsAWholeFillWould() {
        int w = 37;
        int h = 23;
        ZBuffer z = new ZBuffer(w, h);
        ZBufferDrawable tested = new ZBufferDrawable(z, new DiscardingDrawable(w, h));
        double[] plain = new double[w * h];
        Arrays.fill(plain, -200);
        Random random = new Random(20261206);
        for (int step = 0; step < 4000; step++) {
            int what = random.nextInt(10);
            if (what < 4) {
                int x = random.nextInt(w);
                int y = random.nextInt(h);
                double d = -random.nextInt(300);
                tested.setPixel(x, y, d, Colors.WHITE);
                plain[y * w + x] = Math.max(plain[y * w + x], d);
            } else if (what < 7) {
                int y = random.nextInt(h);
                int from = random.nextInt(w);
                int to = from + 1 + random.nextInt(w - from);
                double[] raw = what == 4 ? z.depths() : z.depthsToReset();
                for (int x = from; x < to; x++) {
                    raw[y * w + x] = plain[y * w + x] = -random.nextInt(300);
                }
                z.written(y, from, to);
            } else {
                double farthest = random.nextBoolean() ? -200 : Double.NEGATIVE_INFINITY;
                if (what == 7) {
                    z.reset(farthest);
                } else if (what == 8) {
                    z.resetWhenNeeded(farthest);
                    z.settle();
                } else {
                    z.resetByRows(farthest);
                    int cut = random.nextInt(h + 1);
                    z.resetRows(cut, h);
                    z.resetRows(0, cut);
                }
                Arrays.fill(plain, farthest);
            }
            for (int i = 0; i < plain.length; i++) {
                assertEquals(plain[i], z.depthAt(i % w, i / w), "step " + step + ", pixel " + i % w + ", " + i / w);
            }
        }
    }

    @Test
    void nothingIsOwedWhileEveryDepthIsStillAtTheFarPlane() {
        ZBuffer z = new ZBuffer(SIZE, SIZE);
        z.resetWhenNeeded(-200);
        assertTrue(z.atFarPlane(), "already there");
    }

    /**
     * Threads writing at once through one chain after an owed reset: the
     * first fills, the others wait for it, so no write is lost to the fill.
     */
    @Test
    void threadsWritingAtOnceLoseNoWriteToTheOwedReset() throws Exception {
        ZBuffer z = new ZBuffer(SIZE, SIZE);
        ZBufferDrawable tested = new ZBufferDrawable(z, new DiscardingDrawable());
        for (int round = 0; round < 20; round++) {
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    tested.setPixel(x, y, -10, Colors.WHITE); // nearer than what the round writes
                }
            }
            z.resetWhenNeeded(-200);
            int threads = 4;
            List<Thread> running = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                int own = t;
                Thread writer = new Thread(() -> {
                    for (int y = own; y < SIZE; y += threads) {
                        for (int x = 0; x < SIZE; x++) {
                            tested.setPixel(x, y, -100, Colors.WHITE);
                        }
                    }
                }, "zbuffer-reset-test-" + t);
                running.add(writer);
            }
            running.forEach(Thread::start);
            for (Thread writer : running) {
                writer.join();
            }
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    assertEquals(-100, z.depthAt(x, y), "round " + round + ", pixel " + x + ", " + y);
                }
            }
        }
    }
}
