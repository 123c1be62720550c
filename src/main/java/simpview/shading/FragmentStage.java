package simpview.shading;

import static simpview.raster.FragmentLayout.B;
import static simpview.raster.FragmentLayout.G;
import static simpview.raster.FragmentLayout.NX;
import static simpview.raster.FragmentLayout.NY;
import static simpview.raster.FragmentLayout.NZ;
import static simpview.raster.FragmentLayout.PX;
import static simpview.raster.FragmentLayout.PY;
import static simpview.raster.FragmentLayout.R;
import static simpview.raster.FragmentLayout.Z;

import java.util.Arrays;
import simpview.raster.FragmentLayout;
import simpview.raster.FragmentSink;
import simpview.surface.Colors;
import simpview.surface.Drawable;
import simpview.surface.Provenance;
import simpview.surface.WaitingPixels;
import simpview.surface.ZBuffer;

/**
 * The fragment stage of lit scenes, per pixel, in this order: resolve depth
 * (z = (z q) / q), test it against the z-buffer (strictly nearer wins, then
 * stored), resolve the attributes (a = (a q) / q: perspective-correct; a
 * colour, or phong's kd, that every vertex of the primitive shares is taken
 * as it is: {@link #oneColour}, {@link #phong(PointShader, Fog, boolean)}),
 * shade (phong only: the colour of the lit point; flat and gouraud colours
 * arrive already lit), fog on camera-space z, and write round(c * 255) once
 * to the panel. Hidden pixels stop at the depth test and cost no shading.
 *
 * <p>Channels as {@link FragmentLayout} lays them out, the geometry stage's
 * layout too.
 *
 * <p>One stage may draw only a band of the panel's rows ({@link #rows}): a
 * picture drawn by several threads has one stage per band.
 *
 * <p>State set per primitive; the per-pixel loop allocates nothing. A
 * stage can draw picture after picture ({@link FragmentStages}: kept by the
 * drawing threads), its arrays kept at the size they grew to.
 */
public final class FragmentStage implements FragmentSink {

    /** Pixels of a span done together. */
    static final int BATCH = 64;
    /**
     * The fewest lights for which a phong span's pixels wait to be shaded at
     * the end ({@link #shadeLater}): a long span's for the span, kept; a
     * short span's as {@link #LIGHTS_TO_KEEP_SHORT_SPANS} has it. What the
     * wait saves is the shading of the pixels overwritten later, which grows
     * with the lights, and at the end a look's pixels are lit in full batches
     * ({@link #WAITING_BATCH}) where a primitive's short spans make batches
     * of a few. Long spans, one light, one thread, against shading at once
     * (session 15): A4 page-f1 0.86, page-b3 0.81-0.83, page-a3 0.85, page-d
     * and page-g 0.97-1.00.
     */
    static final int LIGHTS_TO_WAIT = 1;
    /**
     * The fewest lights for which a short phong span waits as a long one
     * does, kept, its pixels marked as waiting for it
     * ({@link #keptShortSpan}); with fewer (but {@link #LIGHTS_TO_WAIT} or
     * more) each pixel that passes waits on its own, with the numbers it is
     * lit with ({@link #waitingShortSpan}, {@link WaitingPoints}). A kept
     * span costs its numbers and, at the end, finding its run and resolving
     * it; a waiting point costs its numbers at once, whether or not it is
     * overwritten later. Against short spans lit with their primitive
     * (session 19, {@code Interleaved}, copies of the old build within
     * 0.95-1.03): one light, one thread, A4 page-f1 0.93, page-d 0.93, page-g
     * 0.97; two threads, page-f1 0.95, page-d 0.94, page-c3 0.96, page-g
     * 0.97, page-a3, page-b3 and page-c1 0.99-1.02. Every one-light short span
     * kept instead: page-f1 0.88-0.89, page-a3 0.91, page-b3 0.95, but page-g
     * 1.05-1.09, its cylinders' spans of two pixels on average each a span
     * to keep and a run to find; every one waiting as points: page-g 0.99-1.01
     * and page-f1 0.94-0.95, but with two lights or more page-e 1.05, page-f2
     * 1.03-1.04 and page-h 1.07. Two lights and more, kept and tested pixel by
     * pixel, with {@link #SMALL_PIECE}, against kept and tested a batch at a
     * time: page-f2 0.97, page-e 0.99, page-h 1.03 (its copy 1.03).
     */
    static final int LIGHTS_TO_KEEP_SHORT_SPANS = 2;
    /**
     * With fewer lights than {@link #LIGHTS_TO_KEEP_SHORT_SPANS}, a stage
     * keeps its short spans too (as with more) for a picture after one whose
     * short spans that passed had this many pixels that passed each or more
     * on average: a span to keep and a run to find then cost less than the
     * points. How pixels wait never changes what they become, so the choice
     * is made from the stage's last picture, each picture's short spans
     * waiting one way. Against points for every one-light short span (session
     * 21, one thread): every one kept, A4 page-f1 (5.7 pixels a passing short
     * span) 0.950, but page-g (2.2) 1.105 and page-d (2.7) 1.053; chosen so,
     * on one and two threads, page-f1 0.966 and 0.981, page-a3 0.947 and
     * 0.943, page-b3 0.944 and 0.962, page-g, page-d and page-c3 within
     * their copies.
     */
    static final int PIXELS_TO_KEEP_SHORT_SPANS = 4;
    /** Numbers kept per phong span: q0, dq, and the phong channels' starts and slopes. */
    private static final int SPAN_NUMBERS = 2 + 2 * FragmentLayout.PHONG_CHANNELS;
    /**
     * Phong spans shorter than this are not a batch of their own: a batch's
     * steps cost more to set up than they save on a few pixels (small
     * triangles, as dummy.obj's, measured slower by batches). Their pixels
     * wait with the rest of the primitive's short spans to be lit, fogged and
     * written together ({@link #phongPixels}), so that a small triangle's few
     * pixels a row make one batch. The ambient term alone, one thread, against
     * pixel by pixel below 6 (session 14): A3 tomsPageJ (spans of 2.3 pixels
     * on average) 0.83-0.85 of its time with 16, 0.87 with 6, 0.83 with 64;
     * pageE 0.94-0.99 with 16 and 1.04 with 64, pageF 0.99 and 1.08 (their
     * longer spans are better a batch of their own, written in runs); with
     * {@link #FEWEST_LIT_TOGETHER} as it is, tomsPageJ 0.86, pageH 0.95,
     * pageE 0.97, pageC, pageG and pageI 0.99-1.01. With one light (session
     * 15, against lighting each pixel alone): A4 page-g 0.95-0.96, page-d,
     * page-a3, page-b3, page-c3 and page-f1 0.98-1.00. (Session 14 measured
     * page-d 1.015 that way, before the lighting's loops were compiled for
     * the full batches at the end.)
     */
    static final int SHORT_SPAN = 16;
    /**
     * Fewer waiting short-span pixels than this are lit one by one when their
     * primitive is done, as a batch's loops cost more than they save on so
     * few; and after a primitive with fewer, the next one's are lit one by
     * one as they pass (a mesh's faces are alike). A3 pageI's dummy, 28,716
     * faces of a few pixels each, took 1.058-1.074 of its time on one thread
     * with every short span's pixels waiting, and 0.99-1.01 so (session 14).
     */
    static final int FEWEST_LIT_TOGETHER = 6;
    /**
     * Waiting pixels lit together at the picture's end ({@link #shadeWaiting}):
     * the most in one batch, made of the runs of every span of one look. C2
     * compiles a batch's loops by how many points they saw: at about 64 and
     * fewer into 256-bit vectors, one a turn, with scalar starts and ends;
     * beyond into 512-bit vectors, unrolled. Three lights took 10.4 ns a
     * point in batches of 64, 8.1 in batches of 128 and 7.7 in batches of 256
     * (one process each, this host, session 15); the runs of the course's
     * pages averaged 33-38 pixels. Batches of 256 cost page-g 2-5 % while
     * the lighting had 31 arrays a batch (session 19); with its 23 (session
     * 21), A4 page-f2, page-e and page-f1 took 0.90-0.96 of their time
     * against batches of 128, and the other pages measured the same within
     * their copies (docs/performance-log.md).
     */
    static final int WAITING_BATCH = 256;
    /**
     * Pieces of a batch at the end shorter than this are resolved pixel by
     * pixel ({@link #addSmallPiece}), not by the loops over the batch that C2
     * packs, which cost more to enter than a few pixels take (the runs of
     * kept short spans: with every one-light short span kept, A4 page-g took
     * 1.12 of the time of short spans lit with their primitive so, and 1.16
     * by the loops; session 19).
     */
    private static final int SMALL_PIECE = 8;
    /**
     * Looks searched for a kept span's before it is given a new one
     * ({@link #lookOf}): a scene of many looks, each drawn once, costs no
     * more a span.
     */
    private static final int LOOKS_SEARCHED = 8;
    /** What {@link #polygonUnlit} found of the polygon at hand, or that it has not looked yet. */
    private static final int NOT_GUESSED = 0;
    private static final int GUESS_UNLIT = 1;
    private static final int GUESS_LIT = 2;
    /** 0, 1, 2, ...: k0 + RAMP[j] is k0 + j, exactly. */
    private static final double[] RAMP = new double[WAITING_BATCH];

    static {
        for (int j = 0; j < WAITING_BATCH; j++) {
            RAMP[j] = j;
        }
    }

    // The picture's: set anew for each (startPicture), on a canvas of this stage's size.
    private ZBuffer zbuffer;
    private double[] depth;
    private final int width;
    private final int height;
    private Drawable panel;
    private final double[] lit = new double[3];
    // A batch of a span's pixels: k (as double), 1 / q and z at each, then
    // moved up in place to those that pass the depth test, with their x (z
    // is P's z under phong, so the same array as points'); their packed
    // colours, and the fog's t at each. Their colours and phong attributes
    // are in points.
    // A span's batches use the first BATCH places; the waiting pixels lit at
    // the end, WAITING_BATCH.
    private final double[] fogT = new double[WAITING_BATCH];
    private final LitPoints points = new LitPoints(WAITING_BATCH);
    private final int[] batchX = new int[BATCH];
    private final double[] batchK = new double[WAITING_BATCH];
    private final double[] batchInverse = new double[WAITING_BATCH];
    private final double[] batchZ = points.pz;
    private final int[] colours = new int[WAITING_BATCH];
    // Whether every pixel of the batch last gathered passed the depth test.
    private boolean whole;
    // The pixels of short phong spans that passed the depth test (their
    // depths stored) and wait in points' arrays to be lit, fogged and written
    // together ({@link #writePending}): pendingCount of them, at
    // (pendingX[i], pendingY[i]), z in batchZ.
    private int pendingCount;
    private final int[] pendingX = new int[BATCH];
    private final int[] pendingY = new int[BATCH];
    // Whether short spans' pixels wait (else each is lit as it
    // passes): they do while the last primitive done had FEWEST_LIT_TOGETHER
    // of them or more; and how many the primitive at hand had so far.
    private boolean shortPixelsWait = true;
    private int shortPixels;
    // Whether this picture's one-light short spans are kept as long ones
    // (PIXELS_TO_KEEP_SHORT_SPANS), and this picture's short spans that
    // waited and passed, with their pixels that passed, for the next one's.
    private boolean keepShortSpans;
    private int waitedShortSpans;
    private int waitedShortPixels;
    /** Pixels marked as waiting since the waits last ended ({@link #waitingMarks}). */
    private int marks;
    private PointShader shader;
    /**
     * Whether the primitives at hand have one colour each, in their colour channels as it is: their colour
     * ({@link #oneColour}), or under phong their kd ({@link #phong(PointShader, Fog, boolean)}).
     */
    private boolean oneColour;
    /**
     * Whether the phong primitives at hand are lit by the ambient term alone and have one kd each: each is then
     * one colour, its kd's ambient term, drawn as a primitive of one colour is ({@link #phongSpan}).
     */
    private boolean ambientOneKd;
    private Fog fog = Fog.NONE;
    // The polygon whose spans come (told by polygon(), until primitiveDone):
    // its corners in polygonNumbers, null for none; and whether no light is
    // guessed to reach it (GUESS_UNLIT, GUESS_LIT, or not guessed yet).
    private double[] polygonNumbers;
    private int polygonAt;
    private int polygonCorners;
    private int polygonStride;
    private int polygonGuess;
    // The rows written: all of them, or one band's.
    private int rowFrom;
    private int rowTo;

    // Phong shading deferred ({@link #shadeLater}): the pixels that wait, by
    // the index of the kept span each waits for, told of every write of a
    // known colour (writtenOver); null when every pixel is shaded as it
    // passes the depth test.
    private WaitingPixels waiting;
    private Provenance owners;
    // The kept phong spans that won a pixel: q0, dq, then v0 and dv of the
    // phong channels; where k counts from; who drew them; their look (an
    // index into lookShader and lookFog).
    private int spanCount;
    private double[] spanNumbers = new double[64 * SPAN_NUMBERS];
    private int[] spanFrom = new int[64];
    private int[] spanOwner = new int[64];
    private int[] spanLook = new int[64];
    // Whether a kept span's kd is one kd, as it is in its numbers (its slopes
    // zero): then its pixels' kd is that kd, not resolved (oneKd).
    private boolean[] spanOneKd = new boolean[64];
    // The kept spans' looks, each shader and fog once (but see lookOf), and
    // whether the polygons of the look's spans were guessed unlit (see
    // polygonUnlit): their pixels are lit in batches of their own.
    private int lookCount;
    private PointShader[] lookShader = new PointShader[8];
    private Fog[] lookFog = new Fog[8];
    private boolean[] lookUnlit = new boolean[8];
    // The look last given to a span guessed lit, and to one guessed unlit:
    // asked first, as a mesh's spans take turns between the two.
    private int lastLitLook = -1;
    private int lastUnlitLook = -1;
    // The runs of waiting pixels at the picture's end, in row order: row,
    // first x, end x and span, RUN_NUMBERS to a run; then their indices by
    // look (runOrder), each look's from lookStart[look].
    private static final int RUN_NUMBERS = 4;
    private int[] runNumbers = new int[256 * RUN_NUMBERS];
    private int[] runOrder = new int[256];
    private int[] lookStart = new int[9];
    // A batch of waiting pixels: its pieces of runs, each at x, y, so long,
    // from place at in the batch, of span pieceSpan.
    private int pieceCount;
    private final int[] pieceX = new int[WAITING_BATCH];
    private final int[] pieceY = new int[WAITING_BATCH];
    private final int[] pieceLength = new int[WAITING_BATCH];
    private final int[] pieceAt = new int[WAITING_BATCH];
    private final int[] pieceSpan = new int[WAITING_BATCH];
    // The pixels of short spans that wait (their points), and a batch of
    // them at the end: where each is and who drew it.
    private final WaitingPoints waitingPoints = new WaitingPoints();
    private final int[] pointX = new int[WAITING_BATCH];
    private final int[] pointY = new int[WAITING_BATCH];
    private final int[] pointOwner = new int[WAITING_BATCH];

    /**
     * Writes to {@code panel} (panel coordinates, y up), depth-tested against
     * {@code zbuffer}, which its user resets ({@link ZBuffer#reset} or
     * {@link ZBuffer#resetByRows}) before the first fragment: a reset the
     * canvas's clear owes is not made for it, as a lit scene replaces it.
     */
    public FragmentStage(ZBuffer zbuffer, Drawable panel) {
        if (zbuffer.width() != panel.width() || zbuffer.height() != panel.height()) {
            throw new IllegalArgumentException("z-buffer and panel differ in size");
        }
        this.zbuffer = zbuffer;
        this.depth = zbuffer.depthsToReset();
        this.width = zbuffer.width();
        this.height = zbuffer.height();
        this.panel = panel;
        this.rowTo = height;
    }

    /**
     * Ready for a new picture on {@code zbuffer} (this stage's size), writing
     * to {@code panel}: what the last picture set (rows, look, waits, kept
     * spans) is dropped, and the stage is as a new one made for them, but
     * for how its one-light short spans wait ({@link #PIXELS_TO_KEEP_SHORT_SPANS}),
     * which draws the same.
     */
    void startPicture(ZBuffer newZbuffer, Drawable newPanel) {
        if (newZbuffer.width() != width || newZbuffer.height() != height || newPanel.width() != width
                || newPanel.height() != height) {
            throw new IllegalArgumentException("a stage for a panel of another size");
        }
        zbuffer = newZbuffer;
        depth = newZbuffer.depthsToReset();
        panel = newPanel;
        rowFrom = 0;
        rowTo = height;
        whole = false;
        pendingCount = 0;
        shortPixelsWait = true;
        shortPixels = 0;
        polygonNumbers = null;
        polygonGuess = NOT_GUESSED;
        // The one setting kept from the last picture: how short spans wait, not what they draw.
        keepShortSpans = waitedShortSpans > 0 && waitedShortPixels >= PIXELS_TO_KEEP_SHORT_SPANS * waitedShortSpans;
        waitedShortSpans = 0;
        waitedShortPixels = 0;
        shader = null;
        fog = Fog.NONE;
        waiting = null;
        owners = null;
        forgetSpans();
    }

    /** True when {@code z} is of this stage's size, so that a picture on it can be drawn by this stage. */
    boolean drawsOn(ZBuffer z) {
        return z.width() == width && z.height() == height;
    }

    /** From now on writes only the rows {@code from <= y < to}, within the panel (one band of a picture). */
    public void rows(int from, int to) {
        rowFrom = Math.max(from, 0);
        rowTo = Math.min(to, height);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /**
     * From now on a phong pixel that passes the depth test is not shaded at
     * once: it waits, in {@code waiting} (the panel's) or, of a short span
     * lit by fewer than {@link #LIGHTS_TO_KEEP_SHORT_SPANS} lights (unless
     * the stage keeps those, {@link #PIXELS_TO_KEEP_SHORT_SPANS}), as a
     * point of its own ({@link WaitingPoints}), for {@link #shadeWaiting} at
     * the picture's end, which shades each pixel the last span or point that
     * won it still holds: one whose depth is still the z it gave it. A later
     * write there was nearer, so it left a larger depth; it only marks its
     * row, so that the depths are looked at there alone (a waiting point's
     * depth is always looked at). The
     * owner each waiting pixel gets is the one {@code owners} (or null) has
     * for its row when it wins. The picture is the same to the bit: a pixel's
     * colour is its last winning fragment's, and a point is lit the same
     * alone or in a batch of any size.
     */
    public void shadeLater(WaitingPixels waiting, Provenance owners) {
        if (waiting.width() != width || waiting.height() != height) {
            throw new IllegalArgumentException("waiting pixels for another panel");
        }
        this.waiting = waiting;
        this.owners = owners;
    }

    /** Row y was written with a known colour: a pixel there that waits may be taken from its span. */
    private void wroteOver(int y) {
        if (waiting != null) {
            waiting.writtenOver(y);
        }
    }

    /** True when a stage that shades later keeps phong spans {@code shader} lights, the long ones at least. */
    public static boolean paysToWait(PointShader shader) {
        return shader.lightCount() >= LIGHTS_TO_WAIT;
    }

    /** True when this stage's phong pixels wait to be shaded at the picture's end ({@link #shadeLater}). */
    public boolean shadesLater() {
        return waiting != null;
    }

    /**
     * Pixels of this stage's rows marked as waiting to be shaded since the
     * waits last ended, a pixel marked again counted again: at most the
     * work {@link #shadeWaiting} will have, a measure of it that costs an
     * add a span. Read by another thread only once this one's drawing is
     * handed back (the band queue's lock).
     */
    public int waitingMarks() {
        return marks;
    }

    /** Ends every wait in this stage's rows, whatever an earlier picture left there: before its first fragment. */
    public void clearWaits() {
        marks = 0;
        if (waiting != null) {
            waiting.clearRows(rowFrom, rowTo);
        }
    }

    /**
     * Shades every pixel of this stage's rows that waits ({@link #shadeLater})
     * and ends the waits: after the last fragment of the picture, on the
     * thread that draws these rows. The pixels are lit a look at a time, in
     * batches of up to {@link #WAITING_BATCH} made of the runs of that look's
     * spans, row after row, and each run is written where it is; then the
     * waiting points, each pixel written alone. No two
     * waiting pixels are the same pixel, so the order of the writes cannot
     * change the picture or the owners; and a point is lit to the same bits
     * in a batch of any size.
     */
    public void shadeWaiting() {
        writePending();
        if (waiting == null) {
            return;
        }
        PointShader shaderBefore = shader;
        Fog fogBefore = fog;
        findRuns();
        for (int look = 0; look < lookCount; look++) {
            shader = lookShader[look];
            fog = lookFog[look];
            int filled = 0;
            for (int r = lookStart[look]; r < lookStart[look + 1]; r++) {
                int o = runOrder[r] * RUN_NUMBERS;
                int y = runNumbers[o];
                int span = runNumbers[o + 3];
                for (int x = runNumbers[o + 1], stop = runNumbers[o + 2]; x < stop;) {
                    int n = Math.min(stop - x, WAITING_BATCH - filled);
                    filled = addPiece(span, y, x, n, filled);
                    x += n;
                    if (filled == WAITING_BATCH) {
                        shadePieces(filled, lookUnlit[look]);
                        filled = 0;
                    }
                }
            }
            if (filled > 0) {
                shadePieces(filled, lookUnlit[look]);
            }
        }
        shadeWaitingPoints();
        clearWaits();
        forgetSpans();
        shader = shaderBefore;
        fog = fogBefore;
    }

    /**
     * The runs of waiting pixels of this stage's rows (neighbours that wait
     * for one span), found row by row, and their order by look
     * (runOrder, lookStart).
     */
    private void findRuns() {
        WaitingPixels w = waiting;
        int count = 0;
        for (int y = rowFrom; y < rowTo; y++) {
            for (int first = w.firstIn(y), end = w.endIn(y), x; first < end; first = x) {
                int span = w.at(first, y);
                x = w.runEnd(first, y);
                if (span == WaitingPixels.NONE) {
                    continue;
                }
                if (count == runOrder.length) {
                    runOrder = Arrays.copyOf(runOrder, 2 * count);
                    runNumbers = Arrays.copyOf(runNumbers, 2 * count * RUN_NUMBERS);
                }
                int o = count * RUN_NUMBERS;
                runNumbers[o] = y;
                runNumbers[o + 1] = first;
                runNumbers[o + 2] = x;
                runNumbers[o + 3] = span;
                count++;
            }
        }
        // A counting sort by look, each look's runs in row order.
        if (lookStart.length < lookCount + 1) {
            lookStart = new int[lookCount + 1];
        }
        Arrays.fill(lookStart, 0, lookCount + 1, 0);
        for (int r = 0; r < count; r++) {
            lookStart[spanLook[runNumbers[r * RUN_NUMBERS + 3]] + 1]++;
        }
        for (int look = 0; look < lookCount; look++) {
            lookStart[look + 1] += lookStart[look];
        }
        for (int r = 0; r < count; r++) {
            int look = spanLook[runNumbers[r * RUN_NUMBERS + 3]];
            runOrder[lookStart[look]++] = r;
        }
        // Each start was moved on to the next look's start: moved back.
        for (int look = lookCount; look > 0; look--) {
            lookStart[look] = lookStart[look - 1];
        }
        lookStart[0] = 0;
    }

    /**
     * Pixels x &lt;= x' &lt; x + n of row y, marked as waiting for the kept
     * span, put in the batch from place {@code at} on, those the span still
     * holds: k, 1 / q, z, kd and, where the look reads them, P and N, each as
     * pixel() has it; returns the place after the last. The span holds them
     * all unless the row was written over ({@link WaitingPixels#writtenOver});
     * then those whose depth is still the z it gave them: a later write there
     * was nearer, so its depth is larger (a NaN z never won), and a later
     * span that waits marked the pixel as its own.
     */
    private int addPiece(int span, int y, int x, int n, int at) {
        if (n < SMALL_PIECE) {
            return addSmallPiece(span, y, x, n, at);
        }
        int o = span * SPAN_NUMBERS;
        double[] numbers = spanNumbers;
        double q0 = numbers[o];
        double dq = numbers[o + 1];
        int v0 = o + 2;
        int dv = v0 + FragmentLayout.PHONG_CHANNELS;
        double z0 = numbers[v0 + Z];
        double dz = numbers[dv + Z];
        // gather's first loop, written out again: the two calling one shared
        // method measured 1.02-1.04x slower on page-e, one thread (session 9).
        double k0 = x - spanFrom[span];
        int stop = at + n;
        for (int j = at; j < stop; j++) {
            double k = k0 + RAMP[j - at];
            double w = 1 / (q0 + k * dq);
            batchK[j] = k;
            batchInverse[j] = w;
            batchZ[j] = (z0 + k * dz) * w;
        }
        if (waiting.mayBeWrittenOver(y)) {
            stop = keptPieces(span, y, x, n, at);
        } else {
            addPieceRun(span, y, x, n, at);
        }
        LitPoints t = points;
        if (shader.usesPoint()) {
            resolve(numbers[v0 + PX], numbers[dv + PX], t.px, numbers[v0 + PY], numbers[dv + PY], t.py, at, stop);
            resolve(numbers[v0 + NX], numbers[dv + NX], t.nx, numbers[v0 + NY], numbers[dv + NY], t.ny,
                    numbers[v0 + NZ], numbers[dv + NZ], t.nz, at, stop);
        }
        if (spanOneKd[span]) {
            oneKd(numbers[v0 + R], numbers[v0 + G], numbers[v0 + B], at, stop);
        } else {
            resolve(numbers[v0 + R], numbers[dv + R], t.kdRed, numbers[v0 + G], numbers[dv + G], t.kdGreen,
                    numbers[v0 + B], numbers[dv + B], t.kdBlue, at, stop);
        }
        return stop;
    }

    /**
     * As {@link #addPiece}, pixel by pixel, for a piece of fewer than
     * {@link #SMALL_PIECE} pixels: each pixel's k, 1 / q and z as there (and
     * as pixel() has them), the depth looked at where the row was written
     * over, and kd, P and N of each the span still holds; each run of those
     * one piece. A span of one kd ({@link #spanOneKd}) takes its kd as it is.
     */
    private int addSmallPiece(int span, int y, int x, int n, int at) {
        int o = span * SPAN_NUMBERS;
        double[] numbers = spanNumbers;
        double q0 = numbers[o];
        double dq = numbers[o + 1];
        int v0 = o + 2;
        int dv = v0 + FragmentLayout.PHONG_CHANNELS;
        double z0 = numbers[v0 + Z];
        double dz = numbers[dv + Z];
        double r0 = numbers[v0 + R];
        double dr = numbers[dv + R];
        double g0 = numbers[v0 + G];
        double dg = numbers[dv + G];
        double b0 = numbers[v0 + B];
        double db = numbers[dv + B];
        double px0 = numbers[v0 + PX];
        double dpx = numbers[dv + PX];
        double py0 = numbers[v0 + PY];
        double dpy = numbers[dv + PY];
        double nx0 = numbers[v0 + NX];
        double dnx = numbers[dv + NX];
        double ny0 = numbers[v0 + NY];
        double dny = numbers[dv + NY];
        double nz0 = numbers[v0 + NZ];
        double dnz = numbers[dv + NZ];
        boolean overwritten = waiting.mayBeWrittenOver(y);
        boolean point = shader.usesPoint();
        LitPoints t = points;
        double[] d = depth;
        int row = y * width;
        int from = spanFrom[span];
        boolean oneKd = spanOneKd[span];
        int j = at;
        int runStart = -1; // the first x of the run of kept pixels at hand, -1 for none
        int runAt = at;
        for (int col = x, end = x + n; col < end; col++) {
            double k = col - from;
            double w = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * w;
            if (overwritten && z != d[row + col]) {
                if (runStart >= 0) {
                    addPieceRun(span, y, runStart, col - runStart, runAt);
                    runStart = -1;
                }
                continue;
            }
            if (runStart < 0) {
                runStart = col;
                runAt = j;
            }
            batchZ[j] = z;
            double kw = oneKd ? 1 : w; // one kd: r0 + k * 0 times 1, r0 to the bit
            t.kdRed[j] = (r0 + k * dr) * kw;
            t.kdGreen[j] = (g0 + k * dg) * kw;
            t.kdBlue[j] = (b0 + k * db) * kw;
            if (point) {
                t.px[j] = (px0 + k * dpx) * w;
                t.py[j] = (py0 + k * dpy) * w;
                t.nx[j] = (nx0 + k * dnx) * w;
                t.ny[j] = (ny0 + k * dny) * w;
                t.nz[j] = (nz0 + k * dnz) * w;
            }
            j++;
        }
        if (runStart >= 0) {
            addPieceRun(span, y, runStart, x + n - runStart, runAt);
        }
        return j;
    }

    /**
     * Of the n pixels from x on just put in the batch at {@code at}, those
     * whose depth is still their z: kept as pieces to be written, each run
     * of them one piece, moved up in place (k, 1 / q and z); returns the
     * place after the last kept.
     */
    private int keptPieces(int span, int y, int x, int n, int at) {
        double[] d = depth;
        int i = y * width + x - at; // the depth index of place j is i + j
        int stop = at + n;
        int kept = at;
        int j = at;
        while (j < stop) {
            while (j < stop && batchZ[j] != d[i + j]) {
                j++; // overwritten since it waited
            }
            int first = j;
            while (j < stop && batchZ[j] == d[i + j]) {
                j++;
            }
            if (first == j) {
                break;
            }
            addPieceRun(span, y, x + first - at, j - first, kept);
            if (kept == first) {
                kept = j; // the usual: nothing before it was dropped
                continue;
            }
            for (int m = first; m < j; m++, kept++) {
                batchK[kept] = batchK[m];
                batchInverse[kept] = batchInverse[m];
                batchZ[kept] = batchZ[m];
            }
        }
        return kept;
    }

    /** A piece of the batch: n pixels from (x, y), from place {@code at}, of the kept span. */
    private void addPieceRun(int span, int y, int x, int n, int at) {
        int p = pieceCount++;
        pieceX[p] = x;
        pieceY[p] = y;
        pieceLength[p] = n;
        pieceAt[p] = at;
        pieceSpan[p] = span;
    }

    /**
     * The batch's first n points lit by the look, fogged, packed and written,
     * a piece at a time; {@code unlit}: the look's polygons were guessed unlit.
     */
    private void shadePieces(int n, boolean unlit) {
        lightAndPack(n, unlit);
        for (int p = 0; p < pieceCount; p++) {
            int y = pieceY[p];
            if (owners != null) {
                owners.beginAt(y, spanOwner[pieceSpan[p]]);
            }
            panel.setRun(pieceX[p], y, pieceLength[p], batchZ, colours, pieceAt[p]);
        }
        pieceCount = 0;
    }

    /**
     * A phong span whose pixels wait: the depth test at each, a batch at a
     * time ({@link #gather}, as a span shaded at once), and each that passes
     * marked as waiting for this span (kept at its first such pixel).
     */
    private boolean waitingSpan(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        int span = WaitingPixels.NONE;
        for (int first = start; first < end; first += BATCH) {
            int n = gather(y, from, first, Math.min(first + BATCH, end), q0, dq, v0[Z], dv[Z], false);
            if (n == 0) {
                continue;
            }
            if (span == WaitingPixels.NONE) {
                span = keepSpan(y, from, q0, dq, v0, dv, polygonUnlit());
            }
            marks += n;
            if (whole) {
                waiting.waitRun(y, first, first + n, span);
            } else {
                for (int i = 0; i < n; i++) {
                    waiting.wait(batchX[i], y, span);
                }
            }
        }
        return span != WaitingPixels.NONE;
    }

    /**
     * A short phong span whose pixels wait for the span, kept as a long one
     * is: pixel by pixel, as {@link #phongPixels} tests them, each that
     * passes marked as waiting for this span (kept at its first such pixel).
     */
    private boolean keptShortSpan(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        double z0 = v0[Z];
        double dz = dv[Z];
        int row = y * width;
        int span = WaitingPixels.NONE;
        int passed = 0;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!nearer(row + x, z)) {
                continue;
            }
            if (span == WaitingPixels.NONE) {
                span = keepSpan(y, from, q0, dq, v0, dv, polygonGuess == GUESS_UNLIT);
            }
            waiting.wait(x, y, span);
            passed++;
        }
        if (span == WaitingPixels.NONE) {
            return false;
        }
        waitedShortSpans++;
        waitedShortPixels += passed;
        marks += passed;
        return true;
    }

    /**
     * A short phong span whose pixels wait: pixel by pixel, as
     * {@link #phongPixels} tests them and resolves kd, P and N, each pixel
     * that passes put with them in {@link #waitingPoints}, with its owner and
     * look, to be lit at the end if it is still its own
     * ({@link #shadeWaitingPoints}). True when a pixel passed. (A loop of its
     * own: as a choice in phongPixels' loop, page-g took 1.04 of its time on
     * one thread and 1.09 on two; session 19.)
     */
    private boolean waitingShortSpan(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        double z0 = v0[Z];
        double dz = dv[Z];
        double r0 = v0[R];
        double dr = dv[R];
        double g0 = v0[G];
        double dg = dv[G];
        double b0 = v0[B];
        double db = dv[B];
        double px0 = v0[PX];
        double dpx = dv[PX];
        double py0 = v0[PY];
        double dpy = dv[PY];
        double nx0 = v0[NX];
        double dnx = dv[NX];
        double ny0 = v0[NY];
        double dny = dv[NY];
        double nz0 = v0[NZ];
        double dnz = dv[NZ];
        WaitingPoints w = waitingPoints;
        int before = w.count;
        int row = y * width;
        int look = -1; // found at the first pixel that passes
        int owner = Provenance.BACKGROUND;
        boolean oneKd = oneColour;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!nearer(row + x, z)) {
                continue;
            }
            if (look < 0) {
                look = lookOf(shader, fog, false);
                owner = owners == null ? Provenance.BACKGROUND : owners.drawingAt(y);
            }
            int i = w.add();
            w.x[i] = x;
            w.y[i] = y;
            w.owner[i] = owner;
            w.look[i] = look;
            w.z[i] = z;
            double kw = oneKd ? 1 : inv; // one kd: r0 + k * 0 times 1, r0 to the bit
            w.kdRed[i] = (r0 + k * dr) * kw;
            w.kdGreen[i] = (g0 + k * dg) * kw;
            w.kdBlue[i] = (b0 + k * db) * kw;
            w.px[i] = (px0 + k * dpx) * inv;
            w.py[i] = (py0 + k * dpy) * inv;
            w.nx[i] = (nx0 + k * dnx) * inv;
            w.ny[i] = (ny0 + k * dny) * inv;
            w.nz[i] = (nz0 + k * dnz) * inv;
        }
        if (look < 0) {
            return false;
        }
        waitedShortSpans++;
        waitedShortPixels += w.count - before;
        marks += w.count - before;
        wroteOver(y); // a long span's pixel that waits here may be taken
        return true;
    }

    /**
     * The waiting points ({@link #waitingShortSpan}) whose pixel is still
     * theirs (its depth still their z), lit in the order they came, in
     * batches of up to {@link #WAITING_BATCH} of one look (a batch ends where
     * the look changes: a look's points come together, as its primitives
     * do), fogged, packed and written, each with its owner; none wait after.
     * (Sorted by look first, page-g took 1.03-1.05 of its time on one
     * thread; session 19.) Of the points and runs that waited at one
     * pixel, only the last to win it still holds it, so each pixel is
     * written once at most and the order of the writes cannot change the
     * picture. Each run of points still theirs, of one look, is copied into
     * the batch at once, array by array: A4 page-g 0.96-0.97 of its time
     * (session 23).
     */
    private void shadeWaitingPoints() {
        WaitingPoints w = waitingPoints;
        LitPoints t = points;
        double[] d = depth;
        int filled = 0;
        int batchLook = -1;
        int n = w.count;
        int i = 0;
        while (i < n) {
            if (w.z[i] != d[w.y[i] * width + w.x[i]]) {
                i++;
                continue; // taken since it passed
            }
            int look = w.look[i];
            if (look != batchLook) {
                if (filled > 0) {
                    shadePoints(filled);
                    filled = 0;
                }
                batchLook = look;
                shader = lookShader[look];
                fog = lookFog[look];
            }
            // The run of points from i on still theirs, of this look, that fits: copied at once.
            int stop = Math.min(n, i + WAITING_BATCH - filled);
            int j = i + 1;
            while (j < stop && w.look[j] == look && w.z[j] == d[w.y[j] * width + w.x[j]]) {
                j++;
            }
            int m = j - i;
            System.arraycopy(w.x, i, pointX, filled, m);
            System.arraycopy(w.y, i, pointY, filled, m);
            System.arraycopy(w.owner, i, pointOwner, filled, m);
            System.arraycopy(w.z, i, batchZ, filled, m);
            System.arraycopy(w.kdRed, i, t.kdRed, filled, m);
            System.arraycopy(w.kdGreen, i, t.kdGreen, filled, m);
            System.arraycopy(w.kdBlue, i, t.kdBlue, filled, m);
            System.arraycopy(w.px, i, t.px, filled, m);
            System.arraycopy(w.py, i, t.py, filled, m);
            System.arraycopy(w.nx, i, t.nx, filled, m);
            System.arraycopy(w.ny, i, t.ny, filled, m);
            System.arraycopy(w.nz, i, t.nz, filled, m);
            filled += m;
            i = j;
            if (filled == WAITING_BATCH) {
                shadePoints(filled);
                filled = 0;
            }
        }
        if (filled > 0) {
            shadePoints(filled);
        }
        w.clear();
    }

    /** The batch's first n points lit by the look, fogged, packed and written, each with its owner. */
    private void shadePoints(int n) {
        lightAndPack(n, false);
        for (int i = 0; i < n; i++) {
            if (owners != null) {
                owners.beginAt(pointY[i], pointOwner[i]);
            }
            panel.setPixel(pointX[i], pointY[i], batchZ[i], colours[i]);
        }
    }

    /** No span kept, and the looks of those that were let go. */
    private void forgetSpans() {
        Arrays.fill(lookShader, 0, lookCount, null);
        Arrays.fill(lookFog, 0, lookCount, null);
        lookCount = 0;
        lastLitLook = -1;
        lastUnlitLook = -1;
        spanCount = 0;
        waitingPoints.clear();
    }

    /** Keeps the phong span being drawn on row y (its set-up, look and owner); returns its index. */
    private int keepSpan(int y, int from, double q0, double dq, double[] v0, double[] dv, boolean unlit) {
        int k = spanCount;
        if (k == spanFrom.length) {
            int capacity = 2 * k;
            spanNumbers = Arrays.copyOf(spanNumbers, capacity * SPAN_NUMBERS);
            spanFrom = Arrays.copyOf(spanFrom, capacity);
            spanOwner = Arrays.copyOf(spanOwner, capacity);
            spanLook = Arrays.copyOf(spanLook, capacity);
            spanOneKd = Arrays.copyOf(spanOneKd, capacity);
        }
        int o = k * SPAN_NUMBERS;
        spanNumbers[o] = q0;
        spanNumbers[o + 1] = dq;
        System.arraycopy(v0, 0, spanNumbers, o + 2, FragmentLayout.PHONG_CHANNELS);
        System.arraycopy(dv, 0, spanNumbers, o + 2 + FragmentLayout.PHONG_CHANNELS, FragmentLayout.PHONG_CHANNELS);
        spanFrom[k] = from;
        spanOwner[k] = owners == null ? Provenance.BACKGROUND : owners.drawingAt(y);
        spanLook[k] = lookOf(shader, fog, unlit);
        spanOneKd[k] = oneColour;
        spanCount = k + 1;
        return k;
    }

    /**
     * The index of the look drawn with this shader and fog, the same
     * objects, and guessed unlit or not; a new one when it is none of the
     * last {@link #LOOKS_SEARCHED} (two indices for one look light its runs
     * in two batches, to the same bits).
     */
    private int lookOf(PointShader s, Fog f, boolean unlit) {
        int last = unlit ? lastUnlitLook : lastLitLook;
        if (last >= 0 && lookShader[last] == s && lookFog[last] == f) {
            return last;
        }
        int found = newLook(s, f, unlit);
        if (unlit) {
            lastUnlitLook = found;
        } else {
            lastLitLook = found;
        }
        return found;
    }

    /** As {@link #lookOf}, searched for among the last looks or made. */
    private int newLook(PointShader s, Fog f, boolean unlit) {
        for (int look = lookCount - 1; look >= 0 && look >= lookCount - LOOKS_SEARCHED; look--) {
            if (lookShader[look] == s && lookFog[look] == f && lookUnlit[look] == unlit) {
                return look;
            }
        }
        if (lookCount == lookShader.length) {
            lookShader = Arrays.copyOf(lookShader, 2 * lookCount);
            lookFog = Arrays.copyOf(lookFog, 2 * lookCount);
            lookUnlit = Arrays.copyOf(lookUnlit, 2 * lookCount);
        }
        lookShader[lookCount] = s;
        lookFog[lookCount] = f;
        lookUnlit[lookCount] = unlit;
        return lookCount++;
    }

    /**
     * Whether no light is guessed to reach the polygon at hand: the shader's
     * {@link PointShader#unlitAt} at each of its corners (P and N over q, as
     * a pixel there would have them), asked once per polygon, by its first
     * long span that is kept or lit at once. False with no polygon told, or
     * one without P and N. Only how its pixels are grouped for lighting
     * depends on it ({@link LitPoints#unlit}): a batch of pixels on faces
     * turned from every light takes 3 + lights loops, not some 16 a light,
     * and on a flat face none of them is lit alone. A4 page-f1's cubes: 45 %
     * of the pixels lit at the picture's end, 0.94-0.96 of its time on one
     * thread (session 22). A short span only takes what a long one of its
     * polygon found (as {@link #polygonGuess}): asked by short spans too, the
     * small faces of A4 page-c3's bowling pin paid for guesses hardly ever
     * unlit, 1.03-1.06 of its time.
     */
    private boolean polygonUnlit() {
        if (polygonGuess == NOT_GUESSED) {
            polygonGuess = guessUnlit() ? GUESS_UNLIT : GUESS_LIT;
        }
        return polygonGuess == GUESS_UNLIT;
    }

    private boolean guessUnlit() {
        double[] v = polygonNumbers;
        PointShader s = shader;
        if (v == null || s == null || polygonStride < FragmentLayout.stride(FragmentLayout.PHONG_CHANNELS)) {
            return false;
        }
        for (int k = 0; k < polygonCorners; k++) {
            int o = polygonAt + k * polygonStride;
            double w = 1 / v[o + FragmentLayout.Q];
            int c = o + FragmentLayout.CHANNEL;
            if (!s.unlitAt(v[c + PX] * w, v[c + PY] * w, v[c + Z] * w, v[c + NX] * w, v[c + NY] * w,
                    v[c + NZ] * w)) {
                return false;
            }
        }
        return true;
    }

    /** Keeps where the polygon is, for {@link #polygonUnlit}, until the primitive is done. */
    @Override
    public void polygon(double[] v, int at, int n, int stride) {
        polygonNumbers = v;
        polygonAt = at;
        polygonCorners = n;
        polygonStride = stride;
        polygonGuess = NOT_GUESSED;
    }

    /** The next primitives carry their colour (gouraud, wire, lines), fogged by {@code fog}. */
    public void colours(Fog fog) {
        writePending(); // lit and fogged by the look they were drawn with
        this.shader = null;
        this.oneColour = false;
        this.ambientOneKd = false;
        this.fog = fog;
    }

    /**
     * The next primitives have one colour each, fogged by {@code fog}: a flat polygon, or a line, wire outline or
     * gouraud polygon whose vertices all carry the same colour. Each carries that colour in its colour channels as
     * it is, not times q, and it is every pixel's colour, to the bit (SPEC Part 2: a flat polygon has "one colour";
     * a lerp between one value and itself is that value). A colour interpolated perspective-correct, (c q) / q,
     * can miss it by a last bit, and so a byte where c * 255 is a half: a flat polygon lit to 0.5 came out 127 at
     * some pixels and 128 at others, and so did the wire cubes of A3's pageB, of kd (1, 0.5, 0.5). Its channels'
     * planes have no slope, so a span's first values are the colour itself ({@code Plane}: the base, plus zero),
     * and a line's lerp keeps a value both ends share.
     */
    public void oneColour(Fog fog) {
        writePending(); // lit and fogged by the look they were drawn with
        this.shader = null;
        this.oneColour = true;
        this.ambientOneKd = false;
        this.fog = fog;
    }

    /**
     * Whether the primitives at hand have one colour each, as it is ({@link #oneColour}), or under phong one kd
     * each ({@link #phong(PointShader, Fog, boolean)}): their colour channels are then that, not times q.
     */
    public boolean oneColours() {
        return oneColour;
    }

    /** The next primitives are phong-shaded by {@code shader} at every pixel, then fogged; their kd interpolated. */
    public void phong(PointShader shader, Fog fog) {
        phong(shader, fog, false);
    }

    /**
     * The next primitives are phong-shaded by {@code shader} at every pixel, then fogged. With {@code oneKd},
     * every vertex of each has the same kd, carried in its colour channels as it is, not times q (as
     * {@link #oneColour} carries a colour), and that kd is every pixel's, to the bit; P and N are interpolated
     * perspective-correct as ever. Resolved as (kd q) / q, kd 0.5 missed by a last bit at some pixels, and under
     * the ambient light alone came out 127 beside 128. The choice is made here, once: a batch's kd is filled
     * with it (oneKd), and a short span's or piece's pixels go through the loops of interpolated kd, their kd's
     * slopes zero and the factor 1, not 1 / q (r0 + k * 0 times 1 is r0), chosen by a test that is the same for
     * every pixel of the loop. (Loops of their own for one kd measured 3-6 % slower on PhongFill's
     * interpolated path, session 33.)
     */
    public void phong(PointShader shader, Fog fog, boolean oneKd) {
        writePending(); // lit and fogged by the look they were drawn with
        this.shader = shader;
        this.oneColour = oneKd;
        this.ambientOneKd = oneKd && !shader.usesPoint();
        this.fog = fog;
    }

    /*
     * Per pixel every span path below (colour spans, short phong spans,
     * phong batches) does exactly what pixel() does, with k = x - from:
     * inv = 1 / (q0 + k dq), each channel (v0[c] + k dv[c]) * inv, so every
     * bit is the same; but the colour channels of a primitive of one colour
     * (or one kd) are v0's as they are, as pixel() takes v's then. A phong span is done BATCH pixels at a time,
     * each step over every pixel of the batch in a small loop of plain
     * arithmetic, which C2 compiles to packed operations: first 1 / q and z
     * for every pixel, then the depth test, gathering the pixels that pass,
     * then their attributes, their colour (lit together), and the write, one
     * call per run of neighbours (k is taken to double exactly, as k0 + j).
     * Each pixel is still written once, and only the panel's own pixels, so
     * the order of the writes cannot change the picture. A short phong span's
     * pixels are tested one at a time, and those that pass wait, with their
     * attributes, until the primitive is done (or BATCH of them wait), to be
     * lit, fogged and written together ({@link #writePending}); no two of
     * one primitive's pixels are the same pixel, and every other write of
     * this stage, and every change of look, comes after they are written.
     */
    @Override
    public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
        if (y < rowFrom || y >= rowTo) {
            return;
        }
        int end = Math.min(to, width);
        boolean wrote = shader == null ? colourSpan(y, from, Math.max(from, 0), end, q0, dq, v0, dv)
                : phongSpan(y, from, end, q0, dq, v0, dv);
        if (wrote) {
            zbuffer.written(y, Math.max(from, 0), end);
        }
    }

    /**
     * The depth test of {@link #span}, the same z at each pixel to the bit,
     * until a pixel passes; nothing is written. Every span's pixel that
     * passes passes the depth test first, so a span none of whose pixels
     * would pass it changes nothing.
     */
    @Override
    public boolean anyNearer(int y, int from, int to, double q0, double dq, double z0, double dz) {
        if (y < rowFrom || y >= rowTo) {
            return false;
        }
        int end = Math.min(to, width);
        int row = y * width;
        double[] d = depth;
        for (int x = Math.max(from, 0); x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            if ((z0 + k * dz) * inv > d[row + x]) {
                return true;
            }
        }
        return false;
    }

    /**
     * True when every depth of the box, within this stage's rows, is at
     * least z: a fragment passes only where its z is above the depth there
     * ({@link #nearer}), so no fragment of z at most z passes in the box.
     * A NaN depth or z is never at least another: not hidden.
     */
    @Override
    public boolean hides(int firstRow, int lastRow, int firstColumn, int lastColumn, double z) {
        int fromRow = Math.max(firstRow, rowFrom);
        int toRow = Math.min(lastRow, rowTo - 1);
        int fromColumn = Math.max(firstColumn, 0);
        int toColumn = Math.min(lastColumn, width - 1);
        double[] d = depth;
        for (int y = fromRow; y <= toRow; y++) {
            int row = y * width;
            for (int x = fromColumn; x <= toColumn; x++) {
                if (!(d[row + x] >= z)) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * A phong span: kept for the end, or a batch at a time, or pixel by pixel when short; true if one was written.
     * A primitive lit by the ambient term alone with one kd is one colour, that kd lit as any point of it is
     * (P and N are not read), and is drawn as a primitive of one colour ({@link #oneColourSpan}): the same bits,
     * without lighting each pixel. On one thread (session 46, {@code Interleaved}) A3 pageC, pageF, pageG and
     * pageH took 0.73-0.75 of their time, pageE 0.83, pageD 0.89, tomsPageJ 0.88 and pageI 0.92.
     */
    private boolean phongSpan(int y, int from, int end, double q0, double dq, double[] v0, double[] dv) {
        int start = Math.max(from, 0);
        if (ambientOneKd) {
            // No pixel is pending: only phongPixels makes them, never used in this look.
            shader.shade(0, 0, 0, 0, 0, 0, v0[R], v0[G], v0[B], lit);
            return oneColourSpan(y, from, start, end, q0, dq, v0, dv, lit[0], lit[1], lit[2]);
        }
        boolean isShort = end - start < SHORT_SPAN;
        if (waiting != null && shader.lightCount() >= LIGHTS_TO_WAIT) {
            // No pixel is pending here: in a look whose spans wait, phongPixels
            // is never used, and a change of look writes what was pending.
            if (!isShort) {
                return waitingSpan(y, from, start, end, q0, dq, v0, dv);
            }
            if (keepShortSpans || shader.lightCount() >= LIGHTS_TO_KEEP_SHORT_SPANS) {
                return keptShortSpan(y, from, start, end, q0, dq, v0, dv);
            }
            return waitingShortSpan(y, from, start, end, q0, dq, v0, dv);
        }
        if (isShort) {
            return phongPixels(y, from, start, end, q0, dq, v0, dv);
        }
        writePending(); // the batches below use the same arrays
        return batches(y, from, start, end, q0, dq, v0, dv, false, 0, 0, 0);
    }

    /**
     * A long span, BATCH pixels at a time: those that pass the depth test gathered ({@link #gather}), then lit
     * from v0 and dv ({@link #phong}) or, with {@code one}, of colour (r, g, b) ({@link #packOne}), and written,
     * each run of neighbours in one call. True if one was written.
     */
    private boolean batches(int y, int from, int start, int end, double q0, double dq, double[] v0, double[] dv,
            boolean one, double r, double g, double b) {
        boolean wrote = false;
        for (int first = start; first < end; first += BATCH) {
            int n = gather(y, from, first, Math.min(first + BATCH, end), q0, dq, v0[Z], dv[Z]);
            if (n > 0) {
                wrote = true;
                if (one) {
                    packOne(n, r, g, b);
                } else {
                    phong(n, v0, dv);
                }
                if (whole) {
                    panel.setRun(first, y, n, batchZ, colours, 0);
                } else {
                    writeRuns(y, n);
                }
            }
        }
        if (wrote) {
            wroteOver(y);
        }
        return wrote;
    }

    /**
     * The pixels that wait ({@link #phongPixels}) lit by the shader, fogged
     * and packed together ({@link #pack}), and written in the order they
     * passed the depth test; none wait after.
     */
    private void writePending() {
        int n = pendingCount;
        if (n == 0) {
            return;
        }
        pendingCount = 0;
        LitPoints t = points;
        if (n < FEWEST_LIT_TOGETHER) {
            PointShader s = shader;
            for (int i = 0; i < n; i++) {
                double z = batchZ[i];
                s.shade(t.px[i], t.py[i], z, t.nx[i], t.ny[i], t.nz[i], t.kdRed[i], t.kdGreen[i], t.kdBlue[i], lit);
                panel.setPixel(pendingX[i], pendingY[i], z, fogged(z, lit));
            }
            return;
        }
        lightAndPack(n, polygonGuess == GUESS_UNLIT); // the primitive at hand's, if a long span guessed it
        for (int i = 0; i < n; i++) {
            panel.setPixel(pendingX[i], pendingY[i], batchZ[i], colours[i]);
        }
    }

    /**
     * Writes the primitive's waiting pixels; the next primitive's short
     * spans wait too if this one's had enough pixels to light
     * together, else they are lit one by one (a mesh's faces are alike).
     */
    @Override
    public void primitiveDone() {
        writePending();
        polygonNumbers = null;
        polygonGuess = NOT_GUESSED;
        shortPixelsWait = shortPixels >= FEWEST_LIT_TOGETHER;
        shortPixels = 0;
    }

    /**
     * A short phong span, pixel by pixel: the depth test at each, and kd, P
     * and N resolved at each pixel that passes (P and N only where the
     * shader reads them). They wait in the points to be lit together
     * ({@link #writePending}, at once when BATCH of them wait, else when the
     * primitive is done), unless the primitive before had fewer than
     * {@link #FEWEST_LIT_TOGETHER} such pixels: then each is lit there alone.
     * A point's numbers are those pixel() would light it with, and a batch
     * lights it to the same bits. (Where pixels wait for the picture's end,
     * a lit short span's do too: {@link #LIGHTS_TO_KEEP_SHORT_SPANS}.) True
     * when a pixel passed.
     */
    private boolean phongPixels(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        double z0 = v0[Z];
        double dz = dv[Z];
        double r0 = v0[R];
        double dr = dv[R];
        double g0 = v0[G];
        double dg = dv[G];
        double b0 = v0[B];
        double db = dv[B];
        double px0 = v0[PX];
        double dpx = dv[PX];
        double py0 = v0[PY];
        double dpy = dv[PY];
        double nx0 = v0[NX];
        double dnx = dv[NX];
        double ny0 = v0[NY];
        double dny = dv[NY];
        double nz0 = v0[NZ];
        double dnz = dv[NZ];
        PointShader s = shader;
        boolean point = s.usesPoint(); // else the ambient term alone: P and N are not read
        boolean later = shortPixelsWait;
        LitPoints t = points;
        int row = y * width;
        int passed = 0;
        int n = pendingCount;
        boolean oneKd = oneColour;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!nearer(row + x, z)) {
                continue;
            }
            passed++;
            double kw = oneKd ? 1 : inv; // one kd: r0 + k * 0 times 1, r0 to the bit
            if (later) {
                pendingX[n] = x;
                pendingY[n] = y;
                batchZ[n] = z;
                t.kdRed[n] = (r0 + k * dr) * kw;
                t.kdGreen[n] = (g0 + k * dg) * kw;
                t.kdBlue[n] = (b0 + k * db) * kw;
                if (point) {
                    t.px[n] = (px0 + k * dpx) * inv;
                    t.py[n] = (py0 + k * dpy) * inv;
                    t.nx[n] = (nx0 + k * dnx) * inv;
                    t.ny[n] = (ny0 + k * dny) * inv;
                    t.nz[n] = (nz0 + k * dnz) * inv;
                }
                if (++n == BATCH) {
                    pendingCount = n;
                    writePending();
                    n = 0;
                }
                continue;
            }
            if (point) {
                s.shade((px0 + k * dpx) * inv, (py0 + k * dpy) * inv, z,
                        (nx0 + k * dnx) * inv, (ny0 + k * dny) * inv, (nz0 + k * dnz) * inv,
                        (r0 + k * dr) * kw, (g0 + k * dg) * kw, (b0 + k * db) * kw, lit);
            } else {
                s.shade(0, 0, z, 0, 0, 0, (r0 + k * dr) * kw, (g0 + k * dg) * kw, (b0 + k * db) * kw, lit);
            }
            panel.setPixel(x, y, z, fogged(z, lit));
        }
        pendingCount = n;
        shortPixels += passed;
        if (passed > 0) {
            wroteOver(y);
        }
        return passed > 0;
    }

    /**
     * A span whose colour is known (flat, gouraud, wire, lines), pixel by
     * pixel: with this little arithmetic per pixel, gathering the pixels to
     * write them as runs measured slower (about 10 against 6 ns per pixel).
     * The starts and slopes are read into locals once per span (the stores
     * to depth[] could alias v0 and dv, so the compiler would read them again
     * at every pixel). True when a pixel was written.
     */
    private boolean colourSpan(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        double z0 = v0[Z];
        double dz = dv[Z];
        double r0 = v0[R];
        double dr = dv[R];
        double g0 = v0[G];
        double dg = dv[G];
        double b0 = v0[B];
        double db = dv[B];
        if (oneColour) {
            return oneColourSpan(y, from, start, end, q0, dq, v0, dv, r0, g0, b0);
        }
        int row = y * width;
        boolean wrote = false;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!nearer(row + x, z)) {
                continue;
            }
            wrote = true;
            lit[0] = (r0 + k * dr) * inv;
            lit[1] = (g0 + k * dg) * inv;
            lit[2] = (b0 + k * db) * inv;
            panel.setPixel(x, y, z, fogged(z, lit));
        }
        if (wrote) {
            wroteOver(y);
        }
        return wrote;
    }

    /**
     * A span of a primitive of one colour: z at each pixel as {@link #colourSpan} has it, and that colour (r, g, b),
     * fogged. Under fog a long span is done BATCH pixels at a time as a phong span is ({@link #batches}), its fog
     * in loops that C2 packs, not by a division and its branches at each pixel; with no fog, pixel by pixel
     * measured faster (session 46, one thread: a flat A4 page-a1 1.057 of its time by batches, and A3 pageE
     * with its fog taken out 0.723 of the old time by batches against 0.669).
     */
    private boolean oneColourSpan(int y, int from, int start, int end, double q0, double dq, double[] v0, double[] dv,
            double r, double g, double b) {
        if (end - start >= SHORT_SPAN && !fog.isNone()) {
            return batches(y, from, start, end, q0, dq, v0, dv, true, r, g, b);
        }
        double z0 = v0[Z];
        double dz = dv[Z];
        int row = y * width;
        boolean wrote = false;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!nearer(row + x, z)) {
                continue;
            }
            wrote = true;
            lit[0] = r;
            lit[1] = g;
            lit[2] = b;
            panel.setPixel(x, y, z, fogged(z, lit));
        }
        if (wrote) {
            wroteOver(y);
        }
        return wrote;
    }

    /**
     * Pixels first &lt;= x &lt; stop of the span: z = (z q) / q at each, the
     * depth test, and for each pixel that passes (its depth now stored) x,
     * k, 1 / q and z gathered, in place. Returns how many passed; when every
     * one did, {@link #whole} is true and the x are first, first + 1, ...
     * (batchX is not written).
     */
    private int gather(int y, int from, int first, int stop, double q0, double dq, double z0, double dz) {
        return gather(y, from, first, stop, q0, dq, z0, dz, true);
    }

    /**
     * As {@link #gather}; with {@code all} false, of the pixels that pass
     * only x is gathered (each z is made, tested and stored as the depth
     * there, but k, 1 / q and z are not kept): for pixels that wait, whose
     * k, 1 / q and z are worked out again when they are shaded
     * ({@link #addPiece}).
     */
    private int gather(int y, int from, int first, int stop, double q0, double dq, double z0, double dz,
            boolean all) {
        int m = stop - first;
        double k0 = first - from;
        double[] ks = batchK;
        double[] inv = batchInverse;
        double[] zs = batchZ;
        if (all) {
            for (int j = 0; j < m; j++) {
                double k = k0 + RAMP[j];
                double w = 1 / (q0 + k * dq);
                ks[j] = k;
                inv[j] = w;
                zs[j] = (z0 + k * dz) * w;
            }
        } else {
            for (int j = 0; j < m; j++) {
                double k = k0 + RAMP[j];
                double w = 1 / (q0 + k * dq);
                zs[j] = (z0 + k * dz) * w;
            }
        }
        int at = y * width + first;
        double[] d = depth;
        // The pixels that pass from the first on need no moving: only their depths are stored.
        int j = 0;
        while (j < m) {
            double z = zs[j];
            if (!(z > d[at + j])) {
                break;
            }
            d[at + j] = z;
            j++;
        }
        whole = j == m;
        if (whole) {
            return m;
        }
        for (int i = 0; i < j; i++) {
            batchX[i] = first + i;
        }
        int n = j;
        if (!all) {
            for (j++; j < m; j++) {
                if (nearer(at + j, zs[j])) {
                    batchX[n++] = first + j;
                }
            }
            return n;
        }
        for (j++; j < m; j++) {
            double z = zs[j];
            if (nearer(at + j, z)) {
                batchX[n] = first + j;
                ks[n] = ks[j];
                inv[n] = inv[j];
                zs[n] = z;
                n++;
            }
        }
        return n;
    }

    /** The gathered pixels' kd, P and N, lit by the shader, fogged and packed ({@link #lightAndPack}). */
    private void phong(int n, double[] v0, double[] dv) {
        LitPoints t = points;
        if (shader.usesPoint()) { // else the ambient term alone: P and N are not read
            resolve(v0[PX], dv[PX], t.px, v0[PY], dv[PY], t.py, 0, n);
            resolve(v0[NX], dv[NX], t.nx, v0[NY], dv[NY], t.ny, v0[NZ], dv[NZ], t.nz, 0, n);
        }
        if (oneColour) {
            oneKd(v0[R], v0[G], v0[B], 0, n);
        } else {
            resolve(v0[R], dv[R], t.kdRed, v0[G], dv[G], t.kdGreen, v0[B], dv[B], t.kdBlue, 0, n);
        }
        lightAndPack(n, polygonUnlit());
    }

    /** The batch's kd from &lt;= i &lt; to: one kd, (r, g, b) as it is, at every pixel (no slope, no q). */
    private void oneKd(double r, double g, double b, int from, int to) {
        LitPoints t = points;
        Arrays.fill(t.kdRed, from, to, r);
        Arrays.fill(t.kdGreen, from, to, g);
        Arrays.fill(t.kdBlue, from, to, b);
    }

    /**
     * The batch's first n points lit by the shader, then fogged and packed
     * into colours ({@link #pack}); {@code unlit}: their polygons were
     * guessed unlit ({@link #polygonUnlit}).
     */
    private void lightAndPack(int n, boolean unlit) {
        LitPoints t = points;
        t.count = n;
        t.unlit = unlit;
        t.black = false;
        shader.shade(t);
        pack(n);
    }

    /** Two channels at the batch's pixels from &lt;= i &lt; to: (c0 + k dc) / q. */
    private void resolve(double a0, double da, double[] a, double b0, double db, double[] b, int from, int to) {
        double[] ks = batchK;
        double[] inv = batchInverse;
        for (int i = from; i < to; i++) {
            double k = ks[i];
            double w = inv[i];
            a[i] = (a0 + k * da) * w;
            b[i] = (b0 + k * db) * w;
        }
    }

    /** Three channels at the batch's pixels from &lt;= i &lt; to: (c0 + k dc) / q. */
    private void resolve(double a0, double da, double[] a, double b0, double db, double[] b, double c0, double dc,
            double[] c, int from, int to) {
        double[] ks = batchK;
        double[] inv = batchInverse;
        for (int i = from; i < to; i++) {
            double k = ks[i];
            double w = inv[i];
            a[i] = (a0 + k * da) * w;
            b[i] = (b0 + k * db) * w;
            c[i] = (c0 + k * dc) * w;
        }
    }

    /**
     * Each gathered pixel's colour (in [0, 1], as lit) fogged at its depth
     * and packed, as {@link #fogged} does it, in loops that C2 packs: the
     * fog's t clamped by min and max, and round(c * 255) as the clamped level
     * (c * 255 + 0.5 in [0, 255]) truncated.
     *
     * <p>Why the bits are fogged's. Where fogged keeps the colour (z at or
     * beyond near, or t &gt;= 1) t comes out 1 (z - far &gt;= near - far, as
     * rounding keeps the order), and 1 c + 0 fog is c; where it gives the fog
     * colour (z &lt;= far) or takes t as 0, t is 0, and 0 c + 1 fog is the fog
     * colour; a zero's sign may differ, which the level does not see. That
     * needs near - far positive and finite and a finite fog colour (else
     * pixel by pixel, as fogged). No z here is NaN: each passed the depth
     * test. Where a fog colour is outside [0, 1] the levels are clamped and
     * cast, and a NaN one truncates to 0, as Colors.level has it; else every
     * level is a whole number in [0, 255] (the lit colours are in [0, 1]).
     *
     * <p>A batch the shader lit black ({@link LitPoints#black}: faces turned
     * from every light, under no ambient light) is opaque black at once with
     * no fog, or with fog towards black (+0 or -0 each) on the packed path,
     * where t 0 + (1 - t) 0 is +0: level 0 either way. On A4 page-f1, 40-45 %
     * of the pixels lit at the picture's end, its time 0.95-0.97 (session 23).
     */
    private void pack(int n) {
        pack(n, false, 0, 0, 0);
    }

    /**
     * As {@link #pack}, but every pixel's colour is (r, g, b), which may be any
     * numbers (a primitive's one colour, not clamped), to the bits
     * {@link #fogged} gives: the levels are clamped where the colour is
     * outside [0, 1]; under fog, where fogged keeps or replaces the colour,
     * t c + (1 - t) fog adds or makes a zero times c, which needs c finite,
     * and a colour that is not is fogged pixel by pixel.
     */
    private void packOne(int n, double r, double g, double b) {
        pack(n, true, r, g, b);
    }

    /** {@link #pack} of the lit colours, or ({@code one}) {@link #packOne} of (r, g, b). */
    private void pack(int n, boolean one, double r, double g, double b) {
        LitPoints t = points;
        double[] red = t.red;
        double[] green = t.green;
        double[] blue = t.blue;
        Fog f = fog;
        // Whether every colour, fogged or not, is in [0, 1]: a lit one is.
        boolean inUnit = !one || unit(r) && unit(g) && unit(b);
        boolean black = !one && t.black;
        if (f.isNone()) {
            if (black) {
                Arrays.fill(colours, 0, n, 0xFF000000);
                return;
            }
            if (one) {
                Arrays.fill(colours, 0, n, Colors.pack(r, g, b));
                return;
            }
        } else {
            double near = f.near();
            double far = f.far();
            double range = near - far;
            double fr = f.r();
            double fg = f.g();
            double fb = f.b();
            if (!(range > 0 && range < Double.POSITIVE_INFINITY && finite(fr) && finite(fg) && finite(fb))
                    || one && !(finite(r) && finite(g) && finite(b))) {
                for (int i = 0; i < n; i++) {
                    lit[0] = one ? r : red[i];
                    lit[1] = one ? g : green[i];
                    lit[2] = one ? b : blue[i];
                    colours[i] = fogged(batchZ[i], lit);
                }
                return;
            }
            boolean blackFog = fr == 0 && fg == 0 && fb == 0;
            if (blackFog && black) {
                Arrays.fill(colours, 0, n, 0xFF000000);
                return;
            }
            inUnit = inUnit && unit(fr) && unit(fg) && unit(fb);
            double[] ts = fogT;
            if (far <= 0 && range >= 1) {
                // (z - far) / range is then never -inf (z never is), so
                // positive is max to the bit.
                for (int i = 0; i < n; i++) {
                    ts[i] = Math.min(BatchLighting.positive((batchZ[i] - far) / range), 1);
                }
            } else {
                for (int i = 0; i < n; i++) {
                    ts[i] = Math.min(Math.max((batchZ[i] - far) / range, 0), 1);
                }
            }
            if (one) {
                for (int i = 0; i < n; i++) {
                    double tt = ts[i];
                    double s = 1 - tt;
                    red[i] = tt * r + s * fr;
                    green[i] = tt * g + s * fg;
                    blue[i] = tt * b + s * fb;
                }
            } else if (blackFog) {
                // Fog towards black (the course's usual): (1 - t) 0 is a zero,
                // and adding it changes no level (at most a zero's sign).
                for (int i = 0; i < n; i++) {
                    double tt = ts[i];
                    red[i] = tt * red[i];
                    green[i] = tt * green[i];
                    blue[i] = tt * blue[i];
                }
            } else {
                for (int i = 0; i < n; i++) {
                    double tt = ts[i];
                    double s = 1 - tt;
                    red[i] = tt * red[i] + s * fr;
                    green[i] = tt * green[i] + s * fg;
                    blue[i] = tt * blue[i] + s * fb;
                }
            }
        }
        if (inUnit) {
            // c * 255 + 0.5 is in [0.5, 255.5] (a rounding above at most), so
            // it truncates into [0, 255] with no clamp, and truncating it is
            // flooring it. The three floors (which C2 packs, where it packs no
            // conversion to int) make one whole number below 2^24, exactly,
            // converted once (Colors.whole: the cast, faster).
            double[] levels = fogT;
            for (int i = 0; i < n; i++) {
                levels[i] = Math.floor(red[i] * 255 + 0.5) * 65536 + Math.floor(green[i] * 255 + 0.5) * 256
                        + Math.floor(blue[i] * 255 + 0.5);
            }
            for (int i = 0; i < n; i++) {
                colours[i] = 0xFF000000 | Colors.whole(levels[i]);
            }
            return;
        }
        for (int i = 0; i < n; i++) {
            red[i] = Math.min(Math.max(red[i] * 255 + 0.5, 0), 255);
            green[i] = Math.min(Math.max(green[i] * 255 + 0.5, 0), 255);
            blue[i] = Math.min(Math.max(blue[i] * 255 + 0.5, 0), 255);
        }
        for (int i = 0; i < n; i++) {
            colours[i] = 0xFF000000 | (int) red[i] << 16 | (int) green[i] << 8 | (int) blue[i];
        }
    }

    private static boolean unit(double v) {
        return v >= 0 && v <= 1;
    }

    private static boolean finite(double v) {
        return Math.abs(v) <= Double.MAX_VALUE;
    }

    /** Writes the n gathered pixels of row y, each run of neighbours in one call. */
    private void writeRuns(int y, int n) {
        int i = 0;
        while (i < n) {
            int j = i + 1;
            while (j < n && batchX[j] == batchX[j - 1] + 1) {
                j++;
            }
            panel.setRun(batchX[i], y, j - i, batchZ, colours, i);
            i = j;
        }
    }

    /**
     * All the channels, but a look lit by the ambient term alone reads z and
     * kd only ({@link FragmentLayout#COLOUR_CHANNELS}): its P and N are never
     * read, at a pixel lit alone or in a batch.
     */
    @Override
    public int channelsRead(int channels) {
        return shader != null && !shader.usesPoint() ? Math.min(channels, FragmentLayout.COLOUR_CHANNELS) : channels;
    }

    @Override
    public void pixel(int x, int y, double q, double[] v) {
        writePending();
        if (x < 0 || x >= width || y < rowFrom || y >= rowTo) {
            return;
        }
        int i = y * width + x;
        double inv = 1 / q;
        double z = v[Z] * inv;
        if (!nearer(i, z)) {
            return;
        }
        zbuffer.written(y, x, x + 1);
        wroteOver(y);
        double colourTimes = oneColour ? 1 : inv; // one colour (or one kd) is as it is
        double r = v[R] * colourTimes;
        double g = v[G] * colourTimes;
        double b = v[B] * colourTimes;
        if (shader != null) {
            shader.shade(v[PX] * inv, v[PY] * inv, z, v[NX] * inv, v[NY] * inv, v[NZ] * inv, r, g, b, lit);
        } else {
            lit[0] = r;
            lit[1] = g;
            lit[2] = b;
        }
        panel.setPixel(x, y, z, fogged(z, lit));
    }

    /**
     * The depth test, the only one of lit scenes: true when z is strictly
     * nearer than the depth at index i (a NaN z never is), which then keeps z.
     */
    private boolean nearer(int i, double z) {
        if (z > depth[i]) {
            depth[i] = z;
            return true;
        }
        return false;
    }

    /** The colour in colour[0..3), fogged in place at depth z and packed: round(c * 255), once. */
    private int fogged(double z, double[] colour) {
        fog.apply(z, colour, 0);
        return Colors.pack(colour[0], colour[1], colour[2]);
    }
}
