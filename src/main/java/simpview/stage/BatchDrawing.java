package simpview.stage;

import java.util.function.Consumer;
import java.util.function.ObjIntConsumer;
import simpview.surface.BandChoice;
import simpview.surface.DrawingThreads;
import simpview.surface.Provenance;
import simpview.surface.RowBands;

/**
 * How recorded batches of primitives are drawn, the same for the depth-cued
 * record ({@link CuedPrimitives}) and the lit one ({@link LitPrimitives}):
 * one batch at a time, in recording order, each split into the panel's row
 * bands or drawn as one band, as {@link BandChoice} finds it pays, while the
 * recording thread goes on with the next batch.
 *
 * <p>The pipeline, for a record of two batches, A and B, used in turn:
 * A is filled; handed off, the workers start drawing it; B is filled
 * meanwhile; when B is handed off, A is finished first (the recording thread
 * draws the bands of A no worker has begun, then waits for the rest), and
 * only then does B start, so that A is free to be filled again. A batch
 * kept as one band is drawn by a worker alone, beside the recording: on a
 * page of many small faces the geometry stage and the rasterizers then take
 * a core each. Batches never overlap, so each pixel sees the writes in
 * drawing order and the picture is the same to the bit as one thread drawing
 * the scene as it reads it.
 *
 * <p>It weighs each batch as it is recorded (about how many pixels its
 * primitives cover, counted only when the thread count is chosen per
 * picture).
 *
 * <p>It keeps the record's two batches and which one is being filled. Used
 * on the one thread that records; the bands' drawers are the record's own,
 * and draw only the batch they are given.
 */
final class BatchDrawing<B extends BatchDrawing.Recorded> {

    /** One batch of a record's primitives, in the record's own arrays. */
    interface Recorded {
        /** How many primitives it holds. */
        int size();

        /** Empties it, to be filled again. */
        void clear();
    }

    private final DrawingThreads threads;
    private final RowBands bands;
    /** The whole panel as one band, for batches not split. */
    private final RowBands whole;
    private final Provenance provenance;
    /** True when the band count is chosen per batch: then the pixels are counted. */
    private final boolean weighs;
    /** About how many pixels the batch being recorded covers ({@link BandChoice#pixels}), when weighed. */
    private double pixels;
    /** The batch being filled, and the other: being drawn, or free. */
    private B filling;
    private B other;
    /** The drawing of the batch handed off last, or null. */
    private DrawingThreads.InFlight drawing;

    /**
     * For a panel {@code height} rows high, drawn by {@code threads};
     * {@code provenance} is the owners' record, or null; the record's two
     * batches, {@code first} filled first.
     */
    BatchDrawing(DrawingThreads threads, int height, Provenance provenance, B first, B second) {
        this.threads = threads;
        this.filling = first;
        this.other = second;
        this.bands = threads.bands(height);
        this.whole = new RowBands(height, 1);
        this.provenance = provenance;
        this.weighs = threads.choosesPerPicture();
        if (provenance != null) {
            provenance.drawnFromRecords();
        }
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

    /** The batch to record into. */
    B filling() {
        return filling;
    }

    /**
     * Hands off the batch being filled, if it holds anything, to be drawn
     * band by band by {@code band} (given the batch and the band's number), by
     * all the threads, or whole by {@code wholePanel}: the batch handed off
     * before it is finished first, then this one is started, and the other
     * batch, free now, is emptied to be filled next; the weight is back at
     * nothing.
     */
    void handOff(ObjIntConsumer<B> band, Consumer<B> wholePanel) {
        B b = filling;
        if (b.size() == 0) {
            return;
        }
        finish();
        boolean split = BandChoice.splits(threads, pixels);
        if (provenance != null) {
            provenance.useBands(split ? bands : whole);
        }
        drawing = split ? threads.start(bands.count(), i -> band.accept(b, i))
                : threads.start(1, i -> wholePanel.accept(b));
        pixels = 0;
        filling = other;
        other = b;
        filling.clear();
    }

    /** Returns when every batch handed off is drawn (this thread helping), throwing what a drawer failed with. */
    void finish() {
        if (drawing != null) {
            DrawingThreads.InFlight last = drawing;
            drawing = null;
            last.finish();
        }
    }
}
