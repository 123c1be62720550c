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

    private static BatchDrawing<Counted> picture(DrawingThreads threads, List<Counted> made, List<Counted> drawn) {
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
        }, Double.POSITIVE_INFINITY);
    }
}
