package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;

/** The threads that draw bands: each band once, on named threads, failures passed on, bands that cover every row. */
class DrawingThreadsTest {

    @Test
    void everyTaskRunsOnceOnTheCallerOrANamedWorker() {
        try (DrawingThreads threads = DrawingThreads.of(3)) {
            AtomicIntegerArray runs = new AtomicIntegerArray(40);
            Set<String> names = ConcurrentHashMap.newKeySet();
            threads.forEach(40, i -> {
                runs.incrementAndGet(i);
                names.add(Thread.currentThread().getName());
            });
            for (int i = 0; i < 40; i++) {
                assertEquals(1, runs.get(i), "task " + i);
            }
            String caller = Thread.currentThread().getName();
            for (String name : names) {
                assertTrue(name.equals(caller) || name.matches("simpview-band-[12]"), name);
            }
        }
    }

    @Test
    void oneThreadRunsEverythingOnTheCaller() {
        try (DrawingThreads threads = DrawingThreads.one()) {
            Thread caller = Thread.currentThread();
            threads.forEach(5, i -> assertSame(caller, Thread.currentThread()));
            assertTrue(threads.isOne());
        }
    }

    @Test
    void aFailureInABandIsThrownOnceAllHaveStopped() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> threads.forEach(8, i -> {
                if (i == 5) {
                    throw new IllegalStateException("band 5");
                }
            }));
            assertEquals("band 5", e.getMessage());
            AtomicIntegerArray runs = new AtomicIntegerArray(3);
            threads.forEach(3, runs::incrementAndGet); // still usable
            assertEquals(1, runs.get(2));
        }
    }

    @Test
    void theBandsCoverEveryRowOnceInOrder() {
        for (int count : new int[] {1, 2, 6, 21, 650}) {
            RowBands bands = new RowBands(650, count);
            assertEquals(0, bands.start(0));
            assertEquals(650, bands.end(count - 1));
            for (int b = 0; b < count; b++) {
                assertTrue(bands.start(b) < bands.end(b), "band " + b + " of " + count + " has rows");
                for (int y = bands.start(b); y < bands.end(b); y++) {
                    assertEquals(b, bands.bandOf(y));
                }
            }
        }
        try (DrawingThreads seven = DrawingThreads.of(7)) {
            assertEquals(21, seven.bands(650).count());
        }
    }
}
