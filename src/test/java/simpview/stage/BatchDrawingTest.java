package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.raster.FragmentLayout;
import simpview.raster.FragmentSink;
import simpview.raster.LitPolygonRasterizer;
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

    @Test
    void pixelsAreAreasOfFillsAndLengthsOfLines() {
        // x, y and one more number per corner (stride 3): a right triangle of legs 10 and 20, either winding.
        double[] v = {5, 5, 0, 15, 5, 0, 5, 25, 0};
        assertEquals(100, BatchDrawing.pixels(v, 0, 3, 3, true, false), 1e-12);
        double[] w = {5, 5, 0, 5, 25, 0, 15, 5, 0};
        assertEquals(100, BatchDrawing.pixels(w, 0, 3, 3, true, false), 1e-12);
        // The line from the first corner to the second: 10 steps along x, both ends: 11 pixels.
        assertEquals(11, BatchDrawing.pixels(v, 0, 2, 3, false, false), 1e-12);
        // The outline: 11 + 21 + 21 (the hypotenuse's longer side is 20).
        assertEquals(53, BatchDrawing.pixels(v, 0, 3, 3, false, true), 1e-12);
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

    /**
     * A filled polygon's rows as the bands are told them (lowRow and
     * highRow, filled) hold every row the rasterizer covers, so a band that
     * skips it misses no pixel: random polygons of 3 to 6 corners, on and
     * near pixel centres and edges; and they are narrower than the rows
     * kept for lines, by a row or more at each end.
     */
    @Test
    void aFilledPolygonsRowsHoldEveryRowItCovers() {
        Random random = new Random(14);
        LitPolygonRasterizer rasterizer = new LitPolygonRasterizer();
        int stride = FragmentLayout.stride(1);
        int[] rows = new int[2];
        FragmentSink sink = new FragmentSink() {
            @Override
            public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
                rows[0] = Math.min(rows[0], y);
                rows[1] = Math.max(rows[1], y);
            }

            @Override
            public void pixel(int x, int y, double q, double[] v) {
                span(y, x, x + 1, q, 0, v, v);
            }
        };
        for (int k = 0; k < 20_000; k++) {
            int n = 3 + random.nextInt(4);
            double[] v = new double[n * stride];
            double cx = 20 + 60 * random.nextDouble();
            double cy = 20 + 60 * random.nextDouble();
            double size = random.nextInt(3) == 0 ? 2 : 25;
            for (int i = 0; i < n; i++) {
                double angle = 2 * Math.PI * (i + random.nextDouble() * 0.9) / n;
                double x = cx + size * Math.cos(angle);
                double y = cy + size * Math.sin(angle);
                if (random.nextBoolean()) { // on a pixel centre's line or a pixel edge
                    y = Math.floor(y) + (random.nextBoolean() ? 0.5 : 0);
                }
                v[i * stride + FragmentLayout.X] = x;
                v[i * stride + FragmentLayout.Y] = y;
                v[i * stride + FragmentLayout.Q] = 1;
            }
            double low = BatchDrawing.lowRow(v, FragmentLayout.Y, n, stride, true);
            double high = BatchDrawing.highRow(v, FragmentLayout.Y, n, stride, true);
            assertTrue(low > BatchDrawing.lowRow(v, FragmentLayout.Y, n, stride, false)
                    && high < BatchDrawing.highRow(v, FragmentLayout.Y, n, stride, false), "polygon " + k);
            rows[0] = Integer.MAX_VALUE;
            rows[1] = Integer.MIN_VALUE;
            rasterizer.fill(v, n, 1, 100, 100, sink);
            if (rows[0] > rows[1]) {
                continue; // no pixel centre inside
            }
            assertTrue(low <= rows[0] && rows[1] <= high, "polygon " + k + ": rows " + rows[0] + "-" + rows[1]
                    + " outside " + low + "-" + high);
            for (int b = 0; b < 10; b++) {
                boolean touches = rows[0] < 10 * b + 10 && rows[1] >= 10 * b;
                assertTrue(!touches || BatchDrawing.mayTouch(low, high, 10 * b, 10 * b + 10), "polygon " + k);
            }
        }
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
        }, Double.POSITIVE_INFINITY, mostPrimitives, DrawingThreads.BANDS_PER_THREAD);
    }
}
