package simpview.stage;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import simpview.geometry.Vertex;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.OwedRows;
import simpview.surface.Provenance;
import simpview.surface.RowBandDrawable;
import simpview.surface.RowBands;
import simpview.surface.ZBuffer;

/**
 * A depth-cued scene drawn by several threads: the primitives the
 * {@link Painter} is given, recorded in drawing order (panel-space vertices
 * and the primitive each is), then drawn band by band, each band of the
 * panel's rows by one thread at a time with renderers of its own, through
 * the panel behind a {@link RowBandDrawable} that keeps its writes to the
 * band. Every primitive that may touch a band is drawn there, in drawing
 * order, so each pixel sees the writes, in the order, that one thread
 * drawing the scene as it is read gives it: its colour, depth and owner are
 * the same to the bit. The renderers compute every row from the primitive
 * alone, never stepping from the row before, so a band's rows are exactly
 * the whole primitive's.
 *
 * <p>A ring of batches is kept: one is filled while the others are drawn
 * ({@link BatchDrawing}). A batch is handed off when it is full, and the
 * last at the end of the scene ({@link #flush}); filled on the one thread
 * that draws the scene.
 */
public final class CuedPrimitives {

    /** The most primitives a batch holds; a picture's first batches hold fewer ({@link BatchDrawing}). */
    private static final int MOST_PRIMITIVES = 4096;
    /**
     * Pixels after which a batch is handed off, however few its primitives:
     * never, a depth-cued batch goes by its count alone. Its pixels are cheap,
     * and handing off every 120,000 of them, as the lit record does, made A2's
     * page 7 slower (docs/performance-log.md, session 5).
     */
    private static final double MOST_PIXELS = Double.POSITIVE_INFINITY;
    /**
     * Bands per thread: fewer than a lit picture's ({@link
     * DrawingThreads#BANDS_PER_THREAD}), as A2's triangles are large (page
     * 7's 590 were set up 2,087 times in 16 bands) and each pixel cheap, so
     * a band's set-ups weigh more against what it evens out. Two threads,
     * 4 against 8, in two processes each (the builds in both orders): A2
     * page 5 0.947 and 0.961, page 7 0.970 and 0.947, page 6 0.924 and 0.968,
     * pages 3, 4 and 8 0.83-0.96 (session 14).
     */
    public static final int BANDS_PER_THREAD = 4;

    private final BatchDrawing<Batch> batches;
    private final Band[] drawers;
    private final Provenance provenance;
    private final RowBands bands;
    private final ZBuffer zbuffer;
    private final Supplier<OwedRows> panelRows;
    private final Drawable panel;
    private final DrawingThreads threads;
    /**
     * The drawers' renderers, in the order the drawers were made: taken from
     * those the threads kept from their last picture, and given back once
     * this one is drawn, as the lit record's rasterizers are.
     */
    private final List<CuedRenderers> renderers;
    /**
     * Each band's rows as the canvas's clear owes them (the z-buffer reset,
     * the panel filled): by its drawer, before it first draws. Null until the
     * first primitive: a scene that turns lit before drawing any drops its
     * depth-cued record, and what the clear owes stays owed to the canvas.
     */
    private BandPreparation preparation;

    /**
     * Draws onto {@code panel} (panel coordinates, whatever the page does per
     * pixel) with {@code threads}; {@code provenance} is the record the panel
     * writes owners into, or null. When the panel tests against {@code zbuffer}
     * (else null) and the canvas's clear owes it a reset, each band's drawer
     * resets its own rows before it first draws, and {@link #flush} the rows
     * no drawer reached: the reset is shared by the threads, not made by
     * whichever tests a depth first while the others wait. The panel's rows
     * that the clear owes (asked of {@code panelRows}) are made the same way.
     * Both are taken at the first primitive, and the drawers start on them
     * then, while the scene's first batch is read.
     */
    public CuedPrimitives(DrawingThreads threads, ZBuffer zbuffer, Supplier<OwedRows> panelRows, Drawable panel,
            Provenance provenance) {
        this.batches = new BatchDrawing<>(threads, panel.height(), provenance, Batch.class, Batch::new,
                this::drawBand, MOST_PIXELS, MOST_PRIMITIVES, BANDS_PER_THREAD);
        this.provenance = provenance;
        this.bands = batches.bands();
        this.zbuffer = zbuffer;
        this.panelRows = panelRows;
        this.panel = panel;
        this.threads = threads;
        List<CuedRenderers> kept = threads.takeKept(CuedRenderers.class);
        this.renderers = kept == null ? new ArrayList<>() : kept;
        this.drawers = new Band[bands.count()];
        for (int b = 0; b < drawers.length; b++) {
            drawers[b] = new Band(b, bands.start(b), bands.end(b), panel, renderers(b));
        }
    }

    /** The k-th drawer's renderers: kept ones, or new. */
    private CuedRenderers renderers(int k) {
        if (k == renderers.size()) {
            renderers.add(CuedRenderers.make());
        }
        return renderers.get(k);
    }

    /**
     * Takes what the canvas's clear owes, to be made band by band, makes on
     * this thread what the panel owes otherwise (a chain of a test's own onto
     * a canvas), and hands off an empty batch: the drawers start on it while
     * the first batch is read.
     */
    private void start() {
        boolean resets = zbuffer != null && zbuffer.resetOwedByRows();
        OwedRows rows = panelRows.get();
        panel.settle();
        preparation = new BandPreparation(bands.count(), b -> {
            if (resets) {
                zbuffer.resetRows(bands.start(b), bands.end(b));
            }
            rows.make(bands.start(b), bands.end(b));
        });
        batches.prepareBands();
    }

    /** Records the primitive whose numbers start at p[at] ({@link Painter#STRIDE} of them), a line's two vertices first. */
    void add(int what, double[] p, int at) {
        if (preparation == null) {
            start();
        }
        Batch b = batches.filling();
        int corners = b.add(what, p, at, provenance == null ? Provenance.BACKGROUND : provenance.current());
        boolean heavy = batches.weigh(p, at + Vertex.X, corners, Vertex.NUMBERS, what == Painter.FILLED,
                what == Painter.WIRE);
        if (heavy || batches.full()) {
            batches.handOff();
        }
    }

    private void drawBand(Batch b, int band) {
        preparation.band(band);
        drawers[band].draw(b);
    }

    /** Draws what is recorded, band by band, and returns when all is drawn. */
    public void flush() {
        if (preparation == null) {
            batches.finish(); // nothing recorded, nothing taken: the threads keep the ring
        } else {
            try {
                batches.handOff();
                batches.finish();
            } finally {
                preparation.everyBand(); // also when a drawer failed: no row keeps the last picture's depths or pixels
            }
        }
        threads.keep(CuedRenderers.class, renderers); // drawn: no drawer uses them any more
    }

    /** One batch of recorded primitives, in primitive arrays: filled by the reading thread, then read by the drawers. */
    private static final class Batch implements BatchDrawing.Recorded {
        int size;
        byte[] kind = new byte[1024];
        int[] owner = new int[1024];
        double[] lowY = new double[1024];
        double[] highY = new double[1024];
        double[] numbers = new double[1024 * Painter.STRIDE];

        @Override
        public int size() {
            return size;
        }

        @Override
        public void clear() {
            size = 0;
        }

        /** Records the primitive, drawn for primitive {@code by}; returns its corners. */
        int add(int what, double[] p, int at, int by) {
            if (size == kind.length) {
                grow();
            }
            System.arraycopy(p, at, numbers, size * Painter.STRIDE, Painter.STRIDE);
            int corners = what == Painter.LINE ? 2 : 3;
            kind[size] = (byte) what;
            owner[size] = by;
            boolean filled = what == Painter.FILLED;
            lowY[size] = BatchDrawing.lowRow(p, at + Vertex.Y, corners, Vertex.NUMBERS, filled);
            highY[size] = BatchDrawing.highRow(p, at + Vertex.Y, corners, Vertex.NUMBERS, filled);
            size++;
            return corners;
        }

        private void grow() {
            int capacity = 2 * kind.length;
            kind = Arrays.copyOf(kind, capacity);
            owner = Arrays.copyOf(owner, capacity);
            lowY = Arrays.copyOf(lowY, capacity);
            highY = Arrays.copyOf(highY, capacity);
            numbers = Arrays.copyOf(numbers, capacity * Painter.STRIDE);
        }
    }

    /** One band's drawer: renderers of its own, the panel through its rows only. */
    private final class Band {
        private final int band;
        private final int from;
        private final int to;
        private final Painter painter;

        Band(int band, int from, int to, Drawable panel, CuedRenderers renderers) {
            this.band = band;
            this.from = from;
            this.to = to;
            renderers.filled().rows(from, to);
            this.painter = renderers.painter(new RowBandDrawable(from, to, panel));
        }

        void draw(Batch b) {
            for (int k = 0; k < b.size; k++) {
                if (!BatchDrawing.mayTouch(b.lowY[k], b.highY[k], from, to)) {
                    continue;
                }
                if (provenance != null) {
                    provenance.begin(band, b.owner[k]);
                }
                painter.draw(b.kind[k], b.numbers, k * Painter.STRIDE);
            }
        }
    }
}
