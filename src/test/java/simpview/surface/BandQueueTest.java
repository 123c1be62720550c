package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;

/**
 * The band queue: every band of every batch drawn once, each band's batches
 * in order, no wait at a batch's end, slots given back only when drawn,
 * failures passed on.
 */
class BandQueueTest {

    /** Logs what was drawn: per band, the batches in the order drawn. */
    private static final class Log implements BandQueue.Drawer {
        final int bands;
        /** The batch in each slot, set by the test before it hands the slot in. */
        final int[] batchIn;
        final List<List<Integer>> perBand = new ArrayList<>();
        final Set<String> threads = ConcurrentHashMap.newKeySet();
        /** How many threads draw each band now: never more than one. */
        final AtomicIntegerArray busy;

        Log(int bands, int slots) {
            this.bands = bands;
            this.batchIn = new int[slots];
            this.busy = new AtomicIntegerArray(bands);
            for (int b = 0; b < bands; b++) {
                perBand.add(Collections.synchronizedList(new ArrayList<>()));
            }
        }

        @Override
        public void band(int slot, int band) {
            assertEquals(1, busy.incrementAndGet(band), "band " + band + " drawn by two threads at once");
            threads.add(Thread.currentThread().getName());
            perBand.get(band).add(batchIn[slot]);
            busy.decrementAndGet(band);
        }
    }

    /**
     * Among bands equally far along, the heaviest first, the lowest of those
     * that tie; with no weight, the lowest first. On one thread, which
     * draws each batch whole as it is handed in, every band its own.
     */
    @Test
    void theHeaviestOfEquallyFarAlongIsDrawnFirst() {
        int[] weights = {1, 5, 3, 5, 0};
        for (boolean weighed : new boolean[] {true, false}) {
            try (DrawingThreads one = DrawingThreads.one()) {
                List<String> order = new ArrayList<>();
                int[] batchIn = new int[2];
                BandQueue queue = one.queue(5, 2, (slot, band) -> order.add(batchIn[slot] + "/" + band));
                if (weighed) {
                    queue.heavierFirst(band -> weights[band]);
                }
                for (int k = 0; k < 2; k++) {
                    batchIn[queue.slot()] = k;
                    queue.publish();
                }
                queue.finish();
                List<String> expected = weighed
                        ? List.of("0/1", "0/3", "0/2", "0/0", "0/4", "1/1", "1/3", "1/2", "1/0", "1/4")
                        : List.of("0/0", "0/1", "0/2", "0/3", "0/4", "1/0", "1/1", "1/2", "1/3", "1/4");
                assertEquals(expected, order, weighed ? "weighed" : "unweighed");
            }
        }
    }

    @Test
    void everyBandOfEveryBatchIsDrawnOnceInOrderOnNamedThreads() {
        for (int threadCount : new int[] {1, 2, 3, 7}) {
            try (DrawingThreads threads = DrawingThreads.of(threadCount)) {
                Log log = new Log(5, 3);
                BandQueue queue = threads.queue(5, 3, log);
                for (int k = 0; k < 60; k++) {
                    int slot = queue.slot();
                    log.batchIn[slot] = k;
                    queue.publish();
                }
                queue.finish();
                for (int b = 0; b < 5; b++) {
                    List<Integer> order = new ArrayList<>();
                    for (int k = 0; k < 60; k++) {
                        order.add(k);
                    }
                    assertEquals(order, log.perBand.get(b), threadCount + " threads, band " + b);
                }
                String caller = Thread.currentThread().getName();
                for (String name : log.threads) {
                    assertTrue(name.equals(caller) || name.startsWith("simpview-band-"), name);
                }
                assertEquals(5L * 60, threads.tasks());
            }
        }
    }

    /** A watch that keeps what it is told, each line with the thread it came on. */
    private static final class Told implements BandWatch {
        final List<String> lines = Collections.synchronizedList(new ArrayList<>());

        private void add(String what) {
            lines.add(Thread.currentThread().getName() + " " + what);
        }

        @Override
        public void handedIn(int batch) {
            add("handedIn " + batch);
        }

        @Override
        public void drawing(int batch, int band) {
            add("drawing " + batch + "/" + band);
        }

        @Override
        public void drawn(int batch, int band) {
            add("drawn " + batch + "/" + band);
        }

        @Override
        public void parked() {
            add("parked");
        }

        @Override
        public void woken() {
            add("woken");
        }
    }

    @Test
    void aWatchIsToldEveryHandOffAndEveryDrawOnTheThreadThatDrawsIt() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            Told told = new Told();
            threads.watchedBy(told);
            Log log = new Log(5, 3);
            BandQueue queue = threads.queue(5, 3, log);
            List<String> handedIn = new ArrayList<>();
            for (int k = 0; k < 40; k++) {
                int slot = queue.slot();
                log.batchIn[slot] = k;
                handedIn.add("handedIn " + k);
                queue.publish();
            }
            queue.finish();
            threads.watchedBy(null);
            String caller = Thread.currentThread().getName();
            List<String> lines = new ArrayList<>(told.lines);
            List<String> handOffs = new ArrayList<>();
            Map<String, String> drawingOn = new HashMap<>();
            Map<String, Boolean> parkedOn = new HashMap<>();
            Set<String> drawnItems = new HashSet<>();
            for (String line : lines) {
                String thread = line.substring(0, line.indexOf(' '));
                String what = line.substring(thread.length() + 1);
                if (what.startsWith("handedIn")) {
                    assertEquals(caller, thread, "batches are handed in by the caller");
                    handOffs.add(what);
                } else if (what.startsWith("drawing ")) {
                    assertEquals(null, drawingOn.put(thread, what.substring(8)), thread + " draws two at once");
                } else if (what.startsWith("drawn ")) {
                    String item = what.substring(6);
                    assertEquals(item, drawingOn.remove(thread), thread + " ended what it had not begun");
                    assertTrue(drawnItems.add(item), item + " drawn twice");
                } else if (what.equals("parked")) {
                    assertEquals(null, parkedOn.put(thread, true), thread + " parked twice");
                } else {
                    assertEquals("woken", what);
                    assertEquals(Boolean.TRUE, parkedOn.remove(thread), thread + " woke unparked");
                }
            }
            assertEquals(handedIn, handOffs);
            assertEquals(40 * 5, drawnItems.size());
            assertTrue(drawingOn.isEmpty(), "every draw ended: " + drawingOn);
            // A worker parked at the end may wake after finish returns: its last park may be unmatched.
            assertTrue(parkedOn.keySet().stream().allMatch(t -> t.startsWith("simpview-band-")), "" + parkedOn);
        }
    }

    @Test
    void aBandGoesOnToTheNextBatchWhileAnotherBandIsStillOnTheLast() throws InterruptedException {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            CountDownLatch nextBatchDrawn = new CountDownLatch(1);
            int[] batchIn = new int[3];
            boolean[] waited = new boolean[1];
            BandQueue queue = threads.queue(2, 3, (slot, band) -> {
                if (batchIn[slot] == 0 && band == 0) {
                    try {
                        // With a wait at each batch's end, band 1 of batch 1 could not be drawn before this returns.
                        waited[0] = nextBatchDrawn.await(20, TimeUnit.SECONDS);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }
                if (batchIn[slot] == 1 && band == 1) {
                    nextBatchDrawn.countDown();
                }
            });
            for (int k = 0; k < 2; k++) {
                batchIn[queue.slot()] = k;
                queue.publish();
            }
            queue.finish();
            assertTrue(waited[0], "band 1 of batch 1 was drawn while band 0 of batch 0 was being drawn");
        }
    }

    @Test
    void aSlotIsGivenBackOnlyOnceEveryBandHasDrawnIt() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            Log log = new Log(4, 2);
            BandQueue queue = threads.queue(4, 2, log);
            for (int k = 0; k < 30; k++) {
                int slot = queue.slot();
                for (int b = 0; b < 4; b++) {
                    // The batch that was in the slot, k - 2, is drawn by every band before the slot is given back.
                    assertTrue(log.perBand.get(b).size() >= k - 1, "batch " + k + ", band " + b);
                }
                log.batchIn[slot] = k;
                queue.publish();
            }
            queue.finish();
        }
    }

    @Test
    void oneThreadDrawsEachBatchAsItIsHandedIn() {
        try (DrawingThreads threads = DrawingThreads.one()) {
            Log log = new Log(3, 2);
            BandQueue queue = threads.queue(3, 2, log);
            log.batchIn[queue.slot()] = 0;
            queue.publish();
            for (int b = 0; b < 3; b++) {
                assertEquals(List.of(0), log.perBand.get(b));
            }
            assertEquals(Set.of(Thread.currentThread().getName()), log.threads);
            queue.finish();
        }
    }

    @Test
    void aFailureIsThrownOnceAllHaveStoppedAndTheQueueIsUsableAgain() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            int[] batchIn = new int[2];
            AtomicIntegerArray drawn = new AtomicIntegerArray(16);
            BandQueue queue = threads.queue(8, 2, (slot, band) -> {
                drawn.incrementAndGet(batchIn[slot]);
                if (batchIn[slot] == 1 && band == 5) {
                    throw new IllegalStateException("band 5 of batch 1");
                }
            });
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> {
                for (int k = 0; k < 10; k++) {
                    batchIn[queue.slot()] = k;
                    queue.publish();
                }
                queue.finish();
            });
            assertEquals("band 5 of batch 1", e.getMessage());
            int before = drawn.get(15);
            batchIn[queue.slot()] = 15;
            queue.publish();
            queue.finish();
            assertEquals(before + 8, drawn.get(15), "drawn again after the failure, every band");
        }
    }
}
