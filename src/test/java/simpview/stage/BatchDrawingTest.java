package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import simpview.surface.DrawingThreads;

/** A record's ring of batches, kept by the threads from one picture to the next. */
class BatchDrawingTest {

    /** A batch that counts its primitives and says how often it was emptied. */
    private static final class Counted implements BatchDrawing.Recorded {
        int size;
        int cleared;

        @Override
        public int size() {
            return size;
        }

        @Override
        public void clear() {
            size = 0;
            cleared++;
        }
    }

    @Test
    void theNextPictureFillsTheBatchesTheLastOneGrew() {
        List<Counted> made = new ArrayList<>();
        List<Counted> drawn = new ArrayList<>();
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            BatchDrawing<Counted> first = picture(threads, made, drawn);
            Counted filled = first.filling();
            filled.size = 5;
            first.handOff();
            first.finish();
            assertEquals(3, made.size(), "the first picture makes a ring of three");
            assertTrue(drawn.contains(filled), "the batch handed off was drawn");

            BatchDrawing<Counted> second = picture(threads, made, drawn);
            assertEquals(3, made.size(), "the next picture makes none");
            assertTrue(made.contains(second.filling()), "it fills one of the first picture's");
            for (Counted b : made) {
                assertTrue(b.cleared >= 1, "each kept batch is emptied before it is filled again");
            }
            assertEquals(0, second.filling().size());
            // Not given back (a picture that never finished): the picture after it makes its own.
            BatchDrawing<Counted> third = picture(threads, made, drawn);
            assertEquals(6, made.size(), "the ring is with the unfinished picture: a new one is made");
            third.finish();
            second.finish();
        }
    }

    @Test
    void withThreadsBesideTheRecordingTheFirstBatchesAreSmallAndEachHoldsTwiceTheOneBefore() {
        List<Counted> made = new ArrayList<>();
        List<Counted> drawn = new ArrayList<>();
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            BatchDrawing<Counted> p = picture(threads, made, drawn, 100);
            List<Integer> sizes = new ArrayList<>();
            for (int k = 0; k < 6; k++) {
                sizes.add(fillUntilFull(p));
                p.handOff();
            }
            p.finish();
            assertEquals(List.of(16, 32, 64, 100, 100, 100), sizes, "16, then twice as many, up to the most");
            assertEquals(6 * threads.bands(100).count(), drawn.size(), "every batch handed off was drawn in every band");
        }
    }

    @Test
    void onOneThreadEveryBatchHoldsTheMost() {
        List<Counted> made = new ArrayList<>();
        List<Counted> drawn = new ArrayList<>();
        try (DrawingThreads threads = DrawingThreads.of(1)) {
            BatchDrawing<Counted> p = picture(threads, made, drawn, 100);
            for (int k = 0; k < 3; k++) {
                assertEquals(100, fillUntilFull(p), "batch " + k);
                p.handOff();
            }
            p.finish();
        }
    }

    /** Adds primitives to the batch being filled until the drawing says it is full: how many it took. */
    private static int fillUntilFull(BatchDrawing<Counted> p) {
        Counted b = p.filling();
        while (!p.full()) {
            b.size++;
            assertTrue(b.size <= 1000, "a batch that is never full");
        }
        return b.size;
    }

    private static BatchDrawing<Counted> picture(DrawingThreads threads, List<Counted> made, List<Counted> drawn) {
        return picture(threads, made, drawn, 4096);
    }

    private static BatchDrawing<Counted> picture(DrawingThreads threads, List<Counted> made, List<Counted> drawn,
            int mostPrimitives) {
        return new BatchDrawing<>(threads, 100, null, Counted.class, () -> {
            Counted c = new Counted();
            made.add(c);
            return c;
        }, (b, band) -> {
            synchronized (drawn) {
                drawn.add(b);
            }
        }, b -> {
            synchronized (drawn) {
                drawn.add(b);
            }
        }, Double.POSITIVE_INFINITY, mostPrimitives, DrawingThreads.BANDS_PER_THREAD);
    }
}
