package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
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
