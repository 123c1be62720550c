package simpview.stage;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import simpview.raster.FragmentLayout;
import simpview.raster.LitLineRasterizer;
import simpview.raster.LitPolygonRasterizer;
import simpview.shading.Fog;
import simpview.shading.LitState;
import simpview.shading.FragmentStage;
import simpview.shading.FragmentStages;
import simpview.shading.PointShader;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.OwedRows;
import simpview.surface.Provenance;
import simpview.surface.RowBands;
import simpview.surface.WaitingPixels;
import simpview.surface.ZBuffer;

/**
 * A lit scene drawn by several threads: the primitives its geometry stage
 * hands to the rasterizers, recorded in drawing order (projected vertices,
 * how they are shaded and fogged, which primitive each is), then drawn band
 * by band, each band of the panel's rows by one thread at a time with its
 * own rasterizers and {@link FragmentStage}, every primitive that may touch
 * the band in drawing order. Each pixel therefore sees the same writes in
 * the same order as when one thread draws the scene as it is read, and its
 * colour, depth and owner are the same to the bit.
 *
 * <p>A ring of batches is kept: one is filled while the others are drawn
 * ({@link BatchDrawing}). A batch is handed off when it is full or covers
 * many pixels, and the last at the end of the scene ({@link #flush}), so a
 * scene of any size takes bounded room. Filled on the one thread that reads
 * the scene.
 */
public final class LitPrimitives {

    /** What a recorded primitive is; each is drawn by its own case below, so a new one does not build without it. */
    enum Kind {
        /** A filled polygon. */
        FILL,
        /** A line. */
        LINE,
        /** A wire polygon: its edges as lines. */
        OUTLINE
    }

    /**
     * The most primitives, or numbers, a batch holds; a picture's first
     * batches hold fewer primitives ({@link BatchDrawing}).
     */
    private static final int MOST_PRIMITIVES = 4096;
    private static final int MOST_NUMBERS = 1 << 18;
    /**
     * Pixels after which a batch is handed off, however few its primitives:
     * the first large fills of a page are drawn while its later primitives
     * are read. Measured on the course's fill-bound pages (docs/performance-log.md,
     * session 5).
     */
    private static final double MOST_PIXELS = 120_000;

    private final BatchDrawing<Batch> batches;
    private final Band[] drawers;
    private final Provenance provenance;
    private final RowBands bands;
    /**
     * Each band's rows of the z-buffer reset, their waits ended and the
     * panel's rows the canvas's clear owes made: by its drawer, before it
     * first draws.
     */
    private final BandPreparation preparation;
    /** True once a look's lights make its pixels wait ({@link FragmentStage#paysToWait}): the bands' stages may then hold some. */
    private boolean shadesLater;
    /**
     * The drawers' rasterizers, in the order the drawers were made: taken
     * from those the threads kept from their last picture, and given back
     * once this one is drawn, as the fragment stages are. Seventeen pairs
     * made anew took the reading thread about 3 % of a two-thread picture of
     * A4 page-h before any band could start (session 13).
     */
    private final List<LitRasterizers> rasterizers;
    private final DrawingThreads threads;
    /**
     * True once the picture's last batch is handed in ({@link #flush}): from
     * then on the bands with the most waiting pixels to shade are drawn
     * first. Not before: the reading thread draws bands while it waits for
     * a free slot, and a long band kept it from reading the next batch
     * (A4 page-f1 0.987 of its time weighed so from the start, a copy
     * 0.992; once the last batch was in, 0.974 and 0.954 in two runs of
     * three processes, copies 0.992 and 0.994; session 50).
     */
    private boolean lastHandedIn;

    /**
     * Draws on {@code panel} (panel coordinates), depth-tested against
     * {@code zbuffer}, with {@code threads}; {@code provenance} is the
     * record the panel writes owners into, or null. The z-buffer starts at
     * -infinity: each band's drawer resets its rows before it first draws
     * (whatever the rows held before), and {@link #flush} the rows no drawer
     * reached. The panel's rows that the canvas's clear owes
     * ({@code panelRows}) are made the same way; the drawers start on them at
     * once, while the scene's first batch is read. Lit phong spans wait in
     * {@code waiting} (the panel's) and each band's drawer shades its rows'
     * at the end ({@link FragmentStage#shadeLater}). The drawers' fragment
     * stages come from {@code stages}.
     */
    public LitPrimitives(DrawingThreads threads, ZBuffer zbuffer, OwedRows panelRows, Drawable panel,
            Provenance provenance, WaitingPixels waiting, FragmentStages stages) {
        this.batches = new BatchDrawing<>(threads, zbuffer.height(), provenance, Batch.class, Batch::new,
                this::drawBand, MOST_PIXELS, MOST_PRIMITIVES, DrawingThreads.BANDS_PER_THREAD);
        this.provenance = provenance;
        this.threads = threads;
        zbuffer.resetByRows(Double.NEGATIVE_INFINITY);
        this.bands = batches.bands();
        this.drawers = new Band[bands.count()];
        List<LitRasterizers> kept = threads.takeKept(LitRasterizers.class);
        this.rasterizers = kept == null ? new ArrayList<>() : kept;
        for (int b = 0; b < drawers.length; b++) {
            drawers[b] = new Band(b, bands.start(b), bands.end(b), stages.next(panel), rasterizers(b));
            drawers[b].fragments.shadeLater(waiting, provenance);
        }
        this.preparation = new BandPreparation(bands.count(), b -> {
            zbuffer.resetRows(bands.start(b), bands.end(b));
            panelRows.make(bands.start(b), bands.end(b));
            drawers[b].fragments.clearWaits();
        });
        batches.heavierFirst(b -> lastHandedIn ? drawers[b].fragments.waitingMarks() : 0);
        panel.settle(); // what the panel owes besides the rows taken (nothing, drawn on a canvas)
        batches.prepareBands();
    }

    /** The k-th drawer's rasterizers: a kept pair, or a new one. */
    private LitRasterizers rasterizers(int k) {
        if (k == rasterizers.size()) {
            rasterizers.add(LitRasterizers.make());
        }
        return rasterizers.get(k);
    }

    /**
     * The look of the primitives recorded next: their colours known, fogged
     * by {@code fog} ({@code phong} null; {@code oneColour}: each primitive's
     * one colour, as it is, {@link FragmentStage#oneColour}), or lit at every pixel as
     * {@code phong} lights now, then fogged ({@code oneColour}: each
     * primitive's one kd, as it is, {@link FragmentStage#phong(PointShader, Fog, boolean)}).
     * Looks are made again only when one of these changed.
     */
    int look(Fog fog, LitState phong, boolean oneColour) {
        // Written once, not stored again for every primitive: the band drawers read this object's fields, and
        // each store made the reading thread fetch the line back from the drawing core (session 34).
        if (!shadesLater && phong != null && FragmentStage.paysToWait(phong)) {
            shadesLater = true;
        }
        return batches.filling().look(fog, phong == null ? null : phong.frozenShader(), oneColour);
    }

    /**
     * Records a primitive: its n vertices from v[0] (layout of {@link FragmentLayout}),
     * its channels, kind and look, and the primitive the provenance record
     * says is being read (the owner of what it draws).
     */
    void add(Kind what, double[] v, int n, int channelCount, int look) {
        System.arraycopy(v, 0, room(n, channelCount), roomAt(), n * FragmentLayout.stride(channelCount));
        addInRoom(what, n, channelCount, look, 0);
    }

    /**
     * Room in the batch being filled for a primitive of n vertices and these
     * channels: the array its vertices are to be written to, from
     * {@link #roomAt}, before {@link #addInRoom} records them.
     */
    double[] room(int n, int channelCount) {
        return batches.filling().room(n * FragmentLayout.stride(channelCount));
    }

    /** Where in {@link #room}'s array the primitive's first vertex goes. */
    int roomAt() {
        Batch b = batches.filling();
        return b.start[b.size];
    }

    /**
     * Records the primitive whose n vertices were written to the room, as
     * {@link #add} does (which copies them there first), and hands the batch
     * off once it is full or covers {@link #MOST_PIXELS}. An outline's edge k
     * (from vertex k to k + 1, the last to the first) is left out when bit k
     * of {@code edgesLeftOut} is set (the first 64 edges; see LitGeometry's
     * edgesKnown); 0 draws every edge.
     */
    void addInRoom(Kind what, int n, int channelCount, int look, long edgesLeftOut) {
        Batch b = batches.filling();
        int at = b.start[b.size];
        b.addInPlace(what, n, channelCount, look, provenance == null ? Provenance.BACKGROUND : provenance.current(),
                bands, edgesLeftOut);
        boolean heavy = batches.weigh(b.numbers, at + FragmentLayout.X, n, FragmentLayout.stride(channelCount),
                what == Kind.FILL, what == Kind.OUTLINE);
        if (heavy || batches.full() || b.start[b.size] >= MOST_NUMBERS) {
            batches.handOff();
        }
    }

    private void drawBand(Batch b, int band) {
        drawers[band].draw(b);
    }

    /** Draws what is recorded, band by band, and returns when all is drawn. */
    public void flush() {
        if (shadesLater) {
            lastHandedIn = true; // before the hand-off, whose lock makes it seen by every claim after
            batches.filling().last = true;
            batches.handOffLast(); // in bands: each band's drawer then shades its rows' waiting pixels
        } else {
            batches.handOff();
        }
        try {
            batches.finish();
        } finally {
            preparation.everyBand(); // also when a drawer failed: no row keeps the last picture's depths or pixels
        }
        threads.keep(LitRasterizers.class, rasterizers); // drawn: no drawer uses them any more
    }

    /**
     * One batch of recorded primitives and the looks they use, in primitive
     * arrays: filled by the reading thread, then read by the band drawers
     * while the other batch is filled.
     */
    private static final class Batch implements BatchDrawing.Recorded {
        int size;
        Kind[] kind = new Kind[1024];
        int[] vertices = new int[1024];
        byte[] channels = new byte[1024];
        int[] start = new int[1025];
        int[] owner = new int[1024];
        int[] lookOf = new int[1024];
        /** An outline's edges left out, one bit each ({@link LitPrimitives#addInRoom}). */
        long[] leftOut = new long[1024];
        double[] lowY = new double[1024];
        double[] highY = new double[1024];
        double[] numbers = new double[1 << 14];
        /** How primitives are shaded: the fog, and for phong the lighting as it was at the primitive. */
        final List<Fog> fogs = new ArrayList<>();
        final List<Supplier<PointShader>> shaders = new ArrayList<>();
        /** Whether a look's colours (under phong, its kd) are each primitive's one colour, as it is. */
        final List<Boolean> oneColours = new ArrayList<>();
        int lastLook = -1;
        /** The parts of look lastLook (when it is not -1). */
        private Fog lastFog;
        private Supplier<PointShader> lastShader;
        private boolean lastOneColour;
        /**
         * For each band, the primitives that may touch its rows
         * ({@link BatchDrawing#mayTouch}), in drawing order: a band's drawer
         * reads its own list, not every primitive of the batch.
         */
        int[][] inBand = new int[0][];
        int[] inBandCount = new int[0];
        /** True for a picture's last batch (drawn in bands, maybe empty): its drawers then shade their rows' waiting pixels. */
        boolean last;

        @Override
        public int size() {
            return size;
        }

        @Override
        public void clear() {
            size = 0;
            last = false;
            fogs.clear();
            shaders.clear();
            oneColours.clear();
            lastLook = -1;
            Arrays.fill(inBandCount, 0);
        }

        int look(Fog fog, Supplier<PointShader> shader, boolean oneColour) {
            // asked for every primitive: the last look's parts are compared as fields, not read from the lists
            if (lastLook < 0 || fog != lastFog || shader != lastShader || oneColour != lastOneColour) {
                fogs.add(fog);
                shaders.add(shader);
                oneColours.add(oneColour);
                lastLook = fogs.size() - 1;
                lastFog = fog;
                lastShader = shader;
                lastOneColour = oneColour;
            }
            return lastLook;
        }

        /** The numbers array, with room for {@code count} more numbers from start[size]. */
        double[] room(int count) {
            int at = start[size];
            if (at + count > numbers.length) {
                numbers = Arrays.copyOf(numbers, Math.max(2 * numbers.length, at + count));
            }
            return numbers;
        }

        /** Records the primitive whose n vertices are in numbers from start[size] (written to its room). */
        void addInPlace(Kind what, int n, int channelCount, int look, int by, RowBands bands, long edgesLeftOut) {
            int stride = FragmentLayout.stride(channelCount);
            int count = n * stride;
            if (size == kind.length) {
                grow();
            }
            int at = start[size];
            double[] v = numbers;
            kind[size] = what;
            vertices[size] = n;
            channels[size] = (byte) channelCount;
            owner[size] = by;
            lookOf[size] = look;
            leftOut[size] = edgesLeftOut;
            double low = BatchDrawing.lowRow(v, at + FragmentLayout.Y, n, stride, what == Kind.FILL);
            double high = BatchDrawing.highRow(v, at + FragmentLayout.Y, n, stride, what == Kind.FILL);
            lowY[size] = low;
            highY[size] = high;
            start[size + 1] = at + count;
            bin(size, low, high, bands);
            size++;
        }

        /**
         * Primitive k in the list of every band it may touch: the bands b
         * with mayTouch(low, high, start(b), end(b)), which are one run, as
         * the bands are rows in order. low and high are whole numbers or
         * infinite; a NaN one never skips a band.
         */
        private void bin(int k, double low, double high, RowBands bands) {
            int count = bands.count();
            if (inBandCount.length != count) {
                inBand = new int[count][256];
                inBandCount = new int[count];
            }
            int rows = bands.rows();
            int first;
            int last;
            if (low != low || high != high) {
                first = 0;
                last = count - 1;
            } else if (!(low < rows) || high < 0) {
                return; // wholly below or above the panel
            } else {
                first = low < 0 ? 0 : bands.bandOf((int) low);
                last = high >= rows - 1 ? count - 1 : bands.bandOf((int) high);
            }
            for (int b = first; b <= last; b++) {
                int m = inBandCount[b];
                if (m == inBand[b].length) {
                    inBand[b] = Arrays.copyOf(inBand[b], 2 * m);
                }
                inBand[b][m] = k;
                inBandCount[b] = m + 1;
            }
        }

        private void grow() {
            int capacity = 2 * kind.length;
            kind = Arrays.copyOf(kind, capacity);
            vertices = Arrays.copyOf(vertices, capacity);
            channels = Arrays.copyOf(channels, capacity);
            start = Arrays.copyOf(start, capacity + 1);
            owner = Arrays.copyOf(owner, capacity);
            lookOf = Arrays.copyOf(lookOf, capacity);
            lowY = Arrays.copyOf(lowY, capacity);
            leftOut = Arrays.copyOf(leftOut, capacity);
            highY = Arrays.copyOf(highY, capacity);
        }
    }

    /** One band's drawer: its own rasterizers and fragment stage, its rows only. */
    private final class Band {
        private final int band;
        private final FragmentStage fragments;
        private final LitPolygonRasterizer fill;
        private final LitLineRasterizer lines;
        /** The look (of the batch at hand) the fragment stage is set to, and the shader this band made for it. */
        private int look = -1;
        private Supplier<PointShader> madeFrom;
        private PointShader shader;

        Band(int band, int from, int to, FragmentStage fragments, LitRasterizers rasterizers) {
            this.band = band;
            this.fragments = fragments;
            this.fill = rasterizers.fill();
            this.lines = rasterizers.lines();
            fragments.rows(from, to);
            fill.rows(from, to);
            lines.rows(from, to);
        }

        void draw(Batch b) {
            look = -1;
            preparation.band(band);
            if (b.size > 0) { // an empty batch may never have been binned
                int[] mine = b.inBand[band];
                int m = b.inBandCount[band];
                for (int j = 0; j < m; j++) {
                    draw(b, mine[j]);
                }
            }
            if (b.last) {
                fragments.shadeWaiting();
            }
        }

        /** Primitive k of the batch, in this band's rows. */
        private void draw(Batch b, int k) {
            if (provenance != null) {
                provenance.begin(band, b.owner[k]);
            }
            setLook(b, b.lookOf[k]);
            int width = fragments.width();
            int height = fragments.height();
            double[] numbers = b.numbers;
            int at = b.start[k];
            int n = b.vertices[k];
            int ch = b.channels[k];
            // A switch expression (its value unused) so that a new Kind does not build without its case.
            Kind drawn = switch (b.kind[k]) {
                case FILL -> {
                    fill.fill(numbers, at, n, ch, width, height, fragments);
                    yield Kind.FILL;
                }
                case LINE -> {
                    lines.draw(numbers, at, at + FragmentLayout.stride(ch), ch, width, height, fragments);
                    yield Kind.LINE;
                }
                case OUTLINE -> {
                    lines.outline(numbers, at, n, ch, b.leftOut[k], width, height, fragments);
                    yield Kind.OUTLINE;
                }
            };
        }

        private void setLook(Batch b, int l) {
            if (l == look) {
                return;
            }
            look = l;
            Supplier<PointShader> s = b.shaders.get(l);
            if (s == null) {
                if (b.oneColours.get(l)) {
                    fragments.oneColour(b.fogs.get(l));
                } else {
                    fragments.colours(b.fogs.get(l));
                }
                return;
            }
            if (s != madeFrom) {
                madeFrom = s;
                shader = s.get();
            }
            fragments.phong(shader, b.fogs.get(l), b.oneColours.get(l));
        }
    }
}
