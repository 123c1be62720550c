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
            threads.start(40, i -> {
                runs.incrementAndGet(i);
                names.add(Thread.currentThread().getName());
            }).finish();
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
            threads.start(5, i -> assertSame(caller, Thread.currentThread())).finish();
            assertTrue(threads.isOne());
        }
    }

    @Test
    void aFailureInABandIsThrownOnceAllHaveStopped() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> threads.start(8, i -> {
                if (i == 5) {
                    throw new IllegalStateException("band 5");
                }
            }).finish());
            assertEquals("band 5", e.getMessage());
            AtomicIntegerArray runs = new AtomicIntegerArray(3);
            threads.start(3, runs::incrementAndGet).finish(); // still usable
            assertEquals(1, runs.get(2));
        }
    }

    @Test
    void startedTasksRunOnAWorkerWhileTheCallerGoesOn() throws InterruptedException {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            java.util.concurrent.CountDownLatch ran = new java.util.concurrent.CountDownLatch(1);
            Set<String> names = ConcurrentHashMap.newKeySet();
            DrawingThreads.InFlight run = threads.start(1, i -> {
                names.add(Thread.currentThread().getName());
                ran.countDown();
            });
            ran.await(); // the caller has not finished it: a worker must run it
            run.finish();
            assertEquals(Set.of("simpview-band-1"), names);
            assertEquals(1, threads.tasks());
        }
    }

    @Test
    void finishTakesTheTasksNoWorkerBeganAndThrowsTheirFailure() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            AtomicIntegerArray runs = new AtomicIntegerArray(30);
            DrawingThreads.InFlight run = threads.start(30, i -> {
                runs.incrementAndGet(i);
                if (i == 20) {
                    throw new IllegalArgumentException("task 20");
                }
            });
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, run::finish);
            assertEquals("task 20", e.getMessage());
            for (int i = 0; i <= 20; i++) {
                assertEquals(1, runs.get(i), "task " + i + " ran once, before the failure stopped the rest");
            }
            run.finish(); // a second call does nothing
            threads.start(3, i -> runs.incrementAndGet(i)).finish(); // still usable
            assertEquals(2, runs.get(2));
        }
    }

    @Test
    void oneThreadRunsStartedTasksBeforeStartReturns() {
        try (DrawingThreads threads = DrawingThreads.one()) {
            AtomicIntegerArray runs = new AtomicIntegerArray(4);
            DrawingThreads.InFlight run = threads.start(4, runs::incrementAndGet);
            for (int i = 0; i < 4; i++) {
                assertEquals(1, runs.get(i));
            }
            run.finish();
        }
    }

    @Test
    void theBandsCoverEveryRowOnceInOrder() {
        for (int count : new int[] {1, 2, 6, 16, 56, 650}) {
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
            assertEquals(56, seven.bands(650).count());
        }
    }
}
