package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The threads that draw bands: how many, and bands that cover every row (the drawing itself: BandQueueTest). */
class DrawingThreadsTest {

    @Test
    void oneThreadHasNoWorker() {
        try (DrawingThreads threads = DrawingThreads.one()) {
            assertTrue(threads.isOne());
        }
        try (DrawingThreads two = DrawingThreads.of(2)) {
            assertFalse(two.isOne());
        }
        try (DrawingThreads everyProcessor = DrawingThreads.perProcessor()) {
            assertEquals(Runtime.getRuntime().availableProcessors(), everyProcessor.threads(), "no --threads given");
        }
    }

    /** Each thread has a processor of its own when there are no more threads than processors. */
    @Test
    void aProcessorEachWhenNoMoreThreadsThanProcessors() {
        int processors = Runtime.getRuntime().availableProcessors();
        try (DrawingThreads one = DrawingThreads.one(); DrawingThreads each = DrawingThreads.perProcessor()) {
            assertTrue(one.coreEach());
            assertTrue(each.coreEach());
        }
        try (DrawingThreads more = DrawingThreads.of(processors + 1)) {
            assertFalse(more.coreEach(), processors + 1 + " threads on " + processors + " processors");
        }
    }

    /**
     * The workers are threads of their own, named, each running a task at
     * a time; closing stops them (each found parked or spinning returns) and
     * refuses new tasks.
     */
    @Test
    void workersAreNamedThreadsThatCloseStops() throws Exception {
        DrawingThreads threads = DrawingThreads.of(3);
        Set<Thread> ran = ConcurrentHashMap.newKeySet();
        CyclicBarrier together = new CyclicBarrier(3);
        for (int k = 0; k < 2; k++) {
            threads.start(() -> {
                ran.add(Thread.currentThread());
                try {
                    together.await(10, TimeUnit.SECONDS);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
        }
        together.await(10, TimeUnit.SECONDS); // both tasks running at once: on two workers
        assertEquals(Set.of("simpview-band-1", "simpview-band-2"),
                ran.stream().map(Thread::getName).collect(Collectors.toSet()));
        threads.close();
        for (Thread worker : ran) {
            worker.join(10_000);
            assertFalse(worker.isAlive(), worker.getName() + " stopped");
        }
        assertThrows(IllegalStateException.class, () -> threads.start(() -> { }));
    }

    /** A task that throws (a fault of the queue, not a drawer's) is told to the handler, and the worker stays. */
    @Test
    void aWorkerOutlivesATaskThatThrows() throws Exception {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            AtomicReference<Throwable> told = new AtomicReference<>();
            IllegalStateException fault = new IllegalStateException("a fault of the queue");
            threads.start(() -> {
                Thread.currentThread().setUncaughtExceptionHandler((t, e) -> told.set(e));
                throw fault;
            });
            CountDownLatch ran = new CountDownLatch(1);
            threads.start(ran::countDown);
            assertTrue(ran.await(10, TimeUnit.SECONDS), "the next task ran on the same worker");
            assertSame(fault, told.get());
        }
    }

    @Test
    void keptObjectsAreHandedToOnePictureAtATime() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            assertNull(threads.takeKept(StringBuilder.class), "nothing kept yet");
            List<StringBuilder> ring = List.of(new StringBuilder("a"), new StringBuilder("b"));
            threads.keep(StringBuilder.class, ring);
            assertNull(threads.takeKept(Object.class), "kept by their own class only");
            List<StringBuilder> taken = threads.takeKept(StringBuilder.class);
            assertEquals(2, taken.size());
            assertSame(ring.get(0), taken.get(0));
            assertSame(ring.get(1), taken.get(1));
            assertNull(threads.takeKept(StringBuilder.class), "taken: the next picture makes its own");
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
            assertEquals(28, seven.bands(650, 4).count(), "a record's own bands per thread");
            assertEquals(20, seven.bands(20, 4).count(), "never more bands than rows");
        }
    }
}
