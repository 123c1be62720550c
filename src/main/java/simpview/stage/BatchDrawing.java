package simpview.stage;

import java.util.function.IntConsumer;
import simpview.surface.BandChoice;
import simpview.surface.DrawingThreads;
import simpview.surface.Provenance;
import simpview.surface.RowBands;

/**
 * How a recorded batch of primitives is drawn, the same for the depth-cued
 * record ({@link CuedPrimitives}) and the lit one ({@link LitPrimitives}):
 * split into the panel's row bands, drawn by all the threads at once, or as
 * one band on the thread that records, as {@link BandChoice} finds it pays.
 * It weighs the batch as it is recorded (about how many pixels its primitives
 * cover, counted only when the thread count is chosen per picture), says when
 * the scene's first batch is full, and tells the record's owner when that
 * batch was kept whole: the rest of the scene is then drawn as it is read.
 *
 * <p>Used on the one thread that records; the bands' drawers are the
 * record's own.
 */
final class BatchDrawing {

    private final DrawingThreads threads;
    private final RowBands bands;
    /** The whole panel as one band, for batches drawn on the recording thread. */
    private final RowBands whole;
    private final Provenance provenance;
    /** True when the band count is chosen per batch: then the pixels are counted. */
    private final boolean weighs;
    /** About how many pixels the recorded primitives cover ({@link BandChoice#pixels}), when weighed. */
    private double pixels;
    /** True until the scene's first batch is drawn, when the thread count is chosen per picture. */
    private boolean firstBatch;
    /** Told when the first batch was drawn whole. */
    private Runnable keptWhole;

    /** For a panel {@code height} rows high, drawn by {@code threads}; {@code provenance} is the owners' record, or null. */
    BatchDrawing(DrawingThreads threads, int height, Provenance provenance) {
        this.threads = threads;
        this.bands = threads.bands(height);
        this.whole = new RowBands(height, 1);
        this.provenance = provenance;
        this.weighs = threads.choosesPerPicture();
        this.firstBatch = weighs;
    }

    /** The row bands a split batch is drawn in, one drawer each. */
    RowBands bands() {
        return bands;
    }

    /** Adds a primitive to the batch's weight: {@link BandChoice#pixels} of its n corners, when weighed. */
    void weigh(double[] v, int at, int n, int stride, boolean filled, boolean closed) {
        if (weighs) {
            pixels += BandChoice.pixels(v, at, n, stride, filled, closed);
        }
    }

    /** True when a record of {@code size} primitives is the scene's first batch, full: to be drawn now. */
    boolean firstBatchFull(int size) {
        return firstBatch && size >= BandChoice.FIRST_BATCH;
    }

    /**
     * Draws a batch of {@code size} primitives: each band by {@code band}
     * (given the band's number), all the threads at once, or the whole panel
     * by {@code wholePanel} on this thread; returns when all is drawn, the
     * weight back at nothing.
     */
    void draw(int size, IntConsumer band, Runnable wholePanel) {
        boolean split = BandChoice.splits(threads, size, pixels);
        if (provenance != null) {
            provenance.useBands(split ? bands : whole);
        }
        if (split) {
            threads.forEach(bands.count(), band);
        } else {
            wholePanel.run();
        }
        pixels = 0;
        if (firstBatch) {
            firstBatch = false;
            if (!split && keptWhole != null) {
                keptWhole.run();
            }
        }
    }

    /**
     * {@code then} is run when the scene's first batch ({@link BandChoice#FIRST_BATCH}
     * primitives, or the whole scene if it has fewer) is drawn whole, with the
     * thread count chosen per picture: the record's owner then draws the rest
     * of the scene as it reads it, on its own thread, without recording it.
     */
    void whenKeptWhole(Runnable then) {
        keptWhole = then;
    }
}
