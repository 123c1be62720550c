package simpview.stage;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntUnaryOperator;
import java.util.function.ObjIntConsumer;
import java.util.function.Supplier;
import simpview.surface.BandQueue;
import simpview.surface.DrawingThreads;
import simpview.surface.Provenance;
import simpview.surface.RowBands;

/**
 * How recorded batches of primitives are drawn, the same for the depth-cued
 * record ({@link CuedPrimitives}) and the lit one ({@link LitPrimitives}):
 * in recording order, band by band, while the recording thread goes on with
 * the next batch ({@link BandQueue}). A batch is handed off when the record
 * finds it full, or when it covers as many pixels as the record says is
 * worth a batch of its own, so that a page of a few large fills is drawn
 * while the rest of it is read. Each pixel sees the writes in drawing order,
 * so the picture is the same to the bit as one thread drawing the scene as
 * it reads it.
 *
 * <p>It keeps the record's ring of batches and which one is being filled,
 * and weighs each batch as it is recorded (about how many pixels its
 * primitives cover, {@link #pixels}) when the record hands batches off by
 * their pixels. Used on the one thread that records; the bands' drawers are
 * the record's own, and draw only the batch they are given.
 */
final class BatchDrawing<B extends BatchDrawing.Recorded> {

    /**
     * Batches in the ring: one being filled and two being drawn, so the
     * recording runs up to two batches ahead of the slowest band.
     */
    private static final int SLOTS = 3;

    /**
     * Primitives after which a picture's first batch is handed off, with
     * threads to draw beside the recording; each later batch may hold twice
     * as many as the one before, up to the record's own most. So the other
     * threads start drawing soon after the picture does, instead of waiting
     * for a full batch while the scene's first part is read, and a long
     * scene still goes in few batches.
     */
    private static final int FIRST_PRIMITIVES = 16;

    /** One batch of a record's primitives, in the record's own arrays. */
    interface Recorded {
        /** How many primitives it holds. */
        int size();

        /** Empties it, to be filled again. */
        void clear();
    }

    private final DrawingThreads threads;
    private final RowBands bands;
    /** The ring: batch k in slot k mod SLOTS; the last picture's, when the threads kept it. */
    private final Class<B> kind;
    private final List<B> ring;
    private final BandQueue queue;
    /** True when a batch is handed off once it covers {@link #mostPixels}: its pixels are counted. */
    private final boolean weighs;
    /** About how many pixels the batch being recorded covers ({@link #pixels}), when weighed. */
    private double pixels;
    /** A batch covering this many pixels is handed off, however few its primitives. */
    private final double mostPixels;
    /** The most primitives a batch may hold, the record's own. */
    private final int mostPrimitives;
    /** Primitives after which the batch being filled is handed off ({@link #FIRST_PRIMITIVES}). */
    private int primitivesLimit;
    /** The batch being filled. */
    private B filling;

    /**
     * For a panel {@code height} rows high, drawn by {@code threads};
     * {@code provenance} is the owners' record, or null; {@code newBatch}
     * makes the ring's batches (of class {@code kind}) when the threads kept
     * none from the last picture; a batch's band is drawn by {@code band}
     * (given the batch and the band's number); a batch is handed off once it
     * covers {@code mostPixels} (when finite) or holds
     * {@code mostPrimitives} (fewer at first, see {@link #FIRST_PRIMITIVES});
     * the panel is split into {@code bandsPerThread} bands per thread.
     */
    BatchDrawing(DrawingThreads threads, int height, Provenance provenance, Class<B> kind, Supplier<B> newBatch,
            ObjIntConsumer<B> band, double mostPixels, int mostPrimitives,
            int bandsPerThread) {
        this.threads = threads;
        this.mostPixels = mostPixels;
        this.mostPrimitives = mostPrimitives;
        this.primitivesLimit = threads.isOne() ? mostPrimitives : Math.min(FIRST_PRIMITIVES, mostPrimitives);
        this.bands = threads.bands(height, bandsPerThread);
        this.weighs = mostPixels < Double.POSITIVE_INFINITY;
        this.kind = kind;
        List<B> kept = threads.takeKept(kind);
        if (kept != null && kept.size() == SLOTS) {
            ring = kept;
            for (B b : ring) {
                b.clear();
            }
        } else {
            ring = new ArrayList<>();
            for (int k = 0; k < SLOTS; k++) {
                ring.add(newBatch.get());
            }
        }
        // The drawers reach the ring through a reference of their own, not through this object, whose weight
        // the reading thread writes for every primitive (a line shared by the two cores costs each store).
        List<B> drawnFrom = ring;
        this.queue = threads.queue(bands.count(), SLOTS, (slot, number) -> band.accept(drawnFrom.get(slot), number));
        if (provenance != null) {
            provenance.drawnFromRecords();
            provenance.useBands(bands);
        }
        this.filling = ring.get(queue.slot());
    }

    /**
     * The lowest row a recorded primitive may touch, of its n corners whose
     * y are v[y], v[y + stride], ...
     * <ul>
     * <li>A line or outline: a row below the lowest corner, so that a band
     * skips it only when all of it lies a row or more outside
     * ({@link #mayTouch}).
     * <li>A filled polygon ({@code filled}), exactly: ceil(lowest - 0.5), the
     * first row whose centre is at or above its lowest corner, as
     * {@code TriangleCoverage.firstRow} finds it for each triangle of the
     * polygon's fan from the same numbers. Each triangle's lowest corner is
     * at or above the polygon's, and the ceiling keeps the order, so no
     * triangle covers a lower row. This keeps a band from setting up a
     * triangle that only comes near its rows: on A3's tomsPageJ, 4,372
     * set-ups in 16 bands with a line's margin against 3,280 on one thread,
     * and 4,062 so.
     * </ul>
     */
    static double lowRow(double[] v, int y, int n, int stride, boolean filled) {
        double low = Double.POSITIVE_INFINITY;
        for (int k = 0; k < n; k++) {
            low = Math.min(low, v[y + k * stride]);
        }
        return filled ? Math.ceil(low - 0.5) : Math.floor(low - 1);
    }

    /**
     * The highest row a recorded primitive may touch, as {@link #lowRow}: a
     * row above its highest corner, or for a filled polygon exactly
     * floor(highest - 0.5).
     */
    static double highRow(double[] v, int y, int n, int stride, boolean filled) {
        double high = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < n; k++) {
            high = Math.max(high, v[y + k * stride]);
        }
        return filled ? Math.floor(high - 0.5) : Math.ceil(high + 1);
    }

    /**
     * True when a primitive between rows {@code low} and {@code high}
     * ({@link #lowRow}, {@link #highRow}) may touch rows from &lt;= y &lt; to:
     * it is skipped only when it surely lies outside (a NaN row never does).
     */
    static boolean mayTouch(double low, double high, int from, int to) {
        return !(high < from || low >= to);
    }

    /** Among bands equally far along, the heaviest by {@code weight} drawn first ({@link BandQueue#heavierFirst}). */
    void heavierFirst(IntUnaryOperator weight) {
        queue.heavierFirst(weight);
    }

    /** The row bands a split batch is drawn in, one drawer each. */
    RowBands bands() {
        return bands;
    }

    /**
     * Adds a primitive to the batch's weight, {@link #pixels} of its n
     * corners, when weighed; true when the batch now covers the pixels that
     * make it worth handing off.
     */
    boolean weigh(double[] v, int at, int n, int stride, boolean filled, boolean closed) {
        if (weighs) {
            pixels += pixels(v, at, n, stride, filled, closed);
        }
        return pixels >= mostPixels;
    }

    /**
     * About how many pixels a primitive covers: a filled polygon's area (the
     * shoelace formula over its n corners, corner k's x at
     * {@code v[at + k * stride]} and its y next to it), and for lines
     * ({@code filled} false) the length in pixels of its n - 1 edges, or of
     * all n when {@code closed} (an outline).
     */
    static double pixels(double[] v, int at, int n, int stride, boolean filled, boolean closed) {
        double sum = 0;
        int edges = closed || filled ? n : n - 1;
        for (int k = 0; k < edges; k++) {
            int i = at + k * stride;
            int j = k + 1 < n ? i + stride : at;
            double x0 = v[i];
            double y0 = v[i + 1];
            double x1 = v[j];
            double y1 = v[j + 1];
            sum += filled ? x0 * y1 - x1 * y0 : Math.max(Math.abs(x1 - x0), Math.abs(y1 - y0)) + 1;
        }
        return filled ? Math.abs(sum) / 2 : sum;
    }

    /** True when the batch being filled holds as many primitives as it may before it is handed off. */
    boolean full() {
        return filling.size() >= primitivesLimit;
    }

    /** The batch to record into. */
    B filling() {
        return filling;
    }

    /**
     * Hands off the batch being filled, if it holds anything, to be drawn in
     * bands by all the threads, and takes the next batch of the ring to
     * fill, once every band has drawn what was in it; the weight is back at
     * nothing.
     */
    void handOff() {
        if (filling.size() > 0) {
            publish();
        }
    }

    /**
     * Hands off the batch being filled, empty or not: a picture's last, whose
     * band drawers then finish their rows.
     */
    void handOffLast() {
        publish();
    }

    /**
     * Hands off an empty batch, before anything is recorded, to be drawn in
     * bands: the other threads start at once, and each band's drawer makes
     * its rows ready (what the record's {@code band} does before it draws)
     * while the first batch is read. The first batch's limit stays.
     */
    void prepareBands() {
        int first = primitivesLimit;
        publish();
        primitivesLimit = first;
    }

    /** Publishes the batch being filled and takes the next of the ring, empty, to fill. */
    private void publish() {
        queue.publish();
        pixels = 0;
        primitivesLimit = (int) Math.min((long) primitivesLimit * 2, mostPrimitives);
        filling = ring.get(queue.slot());
        filling.clear();
    }

    /**
     * Returns when every batch handed off is drawn (this thread helping),
     * throwing what a drawer failed with; the ring is then given back to the
     * threads for the next picture, as no thread draws from it any more.
     */
    void finish() {
        try {
            queue.finish();
        } finally {
            threads.keep(kind, ring);
        }
    }
}
