package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.raster.FragmentLayout;
import simpview.raster.FragmentSink;
import simpview.raster.LitPolygonRasterizer;
import simpview.surface.Drawable;
import simpview.surface.ImageDrawable;
import simpview.surface.Provenance;
import simpview.surface.ProvenanceDrawable;
import simpview.surface.WaitingPixels;
import simpview.surface.ZBuffer;

/**
 * A span through the fragment stage draws, to the bit, what its pixels drawn
 * one by one ({@link FragmentStage#pixel}) draw: colours, depths kept and
 * the provenance of each pixel, for phong-lit and coloured primitives, with
 * and without fog, spans longer than a batch, spans over the edges, and
 * spans hidden in part by earlier ones.
 */
class FragmentStageTest {

    private static final int SIZE = 150;
    private static final int CHANNELS = FragmentLayout.PHONG_CHANNELS;

    /** One stage, its surface, and what it keeps. */
    private record StageSetup(FragmentStage fragments, BufferedImage image, ZBuffer zbuffer, Provenance provenance) {
        static StageSetup make(LitState state, boolean phong) {
            BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
            ZBuffer zbuffer = new ZBuffer(SIZE, SIZE);
            zbuffer.reset(-200);
            Provenance provenance = new Provenance(SIZE, SIZE);
            Drawable panel = new ProvenanceDrawable(provenance, new ImageDrawable(image));
            FragmentStage fragments = new FragmentStage(zbuffer, panel);
            if (phong) {
                fragments.phong(state, state.fog());
            } else {
                fragments.colours(state.fog());
            }
            return new StageSetup(fragments, image, zbuffer, provenance);
        }

        /** A phong stage whose pixels wait to be shaded at the end ({@link FragmentStage#shadeLater}). */
        static StageSetup deferring(LitState state) {
            StageSetup stage = make(state, true);
            stage.fragments().shadeLater(new WaitingPixels(SIZE, SIZE), stage.provenance());
            stage.fragments().clearWaits();
            return stage;
        }
    }

    private static LitState scene(Random random) {
        return scene(random, random.nextInt(4));
    }

    private static LitState scene(Random random, int lights) {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.setAmbient(0.2, 0.1, 0.3);
        state.setSurface(0.8, 0.6, 0.4, random.nextDouble(), random.nextBoolean() ? 16 : 7.5);
        for (int i = 0; i < lights; i++) {
            state.addLight(random.nextDouble() * 20 - 10, random.nextDouble() * 20 - 10, random.nextDouble() * 10 - 12,
                    random.nextDouble(), random.nextDouble(), random.nextDouble(), 1, random.nextBoolean() ? 0 : 0.02);
        }
        if (random.nextBoolean()) {
            state.setFog(FOGS[random.nextInt(FOGS.length)]);
        }
        return state;
    }

    /**
     * As {@link #scene}, with two lights more, or a third of the time with
     * one light in all: its phong pixels wait where a stage shades later (a
     * short span's as points with one light, kept as a span with more).
     */
    private static LitState sceneThatWaits(Random random) {
        boolean oneLight = random.nextInt(3) == 0;
        LitState state = scene(random, oneLight ? 0 : random.nextInt(4));
        state.addLight(3, 4, -2, 0.9, 0.8, 0.7, 1, 0);
        if (!oneLight) {
            state.addLight(-5, 2, -1, 0.3, 0.6, 0.2, 1, 0.01);
        }
        return state;
    }

    /** One light, attenuated, and fog: a short span's pixels wait as points. */
    private static LitState oneLightScene() {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.setAmbient(0.2, 0.1, 0.3);
        state.setSurface(0.8, 0.6, 0.4, 0.5, 16);
        state.addLight(-5, 2, -1, 0.3, 0.6, 0.2, 1, 0.01);
        state.setFog(FOGS[0]);
        return state;
    }

    /** As {@link #scene}, with no light: the ambient term alone. */
    private static LitState ambientScene(Random random) {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.setAmbient(0.2 + random.nextDouble(), 0.1, 0.3);
        state.setSurface(0.8, 0.6, 0.4, random.nextDouble(), 16);
        if (random.nextBoolean()) {
            state.setFog(FOGS[random.nextInt(FOGS.length)]);
        }
        return state;
    }

    /**
     * Fogs that the phong batches take each way: colours in [0, 1] (no clamp
     * of the levels), outside it (clamped), near and far the wrong way round
     * or equal, a huge range, and colours that are not finite (pixel by pixel).
     */
    private static final Fog[] FOGS = {
        new Fog(-8, -16, 0.1, 0.2, 0.3),
        new Fog(-6, -14, 0, 1, 0.5),
        new Fog(-8, -16, 1.5, -0.25, 3),
        new Fog(-16, -8, 0.1, 0.2, 0.3),
        new Fog(-10, -10, 0.4, 0.2, 0.9),
        new Fog(1e308, -1e308, 0.1, 0.2, 0.3),
        new Fog(-8, -16, 1e300, Double.NaN, Double.POSITIVE_INFINITY),
    };

    /** The two stages drew the same picture, depths and owners, to the bit. */
    private static void assertSameDrawing(StageSetup expected, StageSetup actual) {
        assertArrayEquals(pixels(expected.image()), pixels(actual.image()), "the picture");
        assertArrayEquals(expected.zbuffer().copyDepths(), actual.zbuffer().copyDepths(), "the depths");
        assertArrayEquals(expected.provenance().copyOwners(), actual.provenance().copyOwners(), "the provenance");
    }

    /** A random span's channels into v0 and dv (as times q), and its q0 and dq. */
    private static double[] randomSpan(Random random, double[] v0, double[] dv) {
        double q0 = 1 / (4 + random.nextDouble() * 12);
        double dq = (random.nextDouble() - 0.5) * 1e-4;
        for (int c = 0; c < CHANNELS; c++) {
            double value = c == FragmentLayout.Z ? -(4 + random.nextDouble() * 12) : random.nextDouble() * 2 - 1;
            v0[c] = value * q0;
            dv[c] = (random.nextDouble() - 0.5) * 1e-3;
        }
        return new double[] {q0, dq};
    }

    /**
     * The span's pixels from {@code from} to {@code to} drawn one by one through {@link FragmentStage#pixel}, each
     * pixel's channels v0 + k dv (into v) and q q0 + k dq, k = x - from: what a span's pixels are.
     */
    private static void drawByPixels(FragmentStage stage, int y, int from, int to, double q0, double dq, double[] v0,
            double[] dv, double[] v) {
        for (int x = from; x < to; x++) {
            int k = x - from;
            for (int c = 0; c < CHANNELS; c++) {
                v[c] = v0[c] + k * dv[c];
            }
            stage.pixel(x, y, q0 + k * dq, v);
        }
    }

    @Property(tries = 150, seed = "1202002")
    void aSpanDrawsWhatItsPixelsDrawOneByOne(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = scene(random);
        boolean phong = random.nextInt(3) > 0;
        StageSetup bySpan = StageSetup.make(state, phong);
        StageSetup byPixel = StageSetup.make(state, phong);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        double[] v = new double[CHANNELS];
        int spans = 1 + random.nextInt(40);
        for (int s = 0; s < spans; s++) {
            int y = random.nextInt(SIZE + 4) - 2;
            int from = random.nextInt(SIZE + 40) - 30;
            int to = from + random.nextInt(SIZE + 10);
            double[] q = randomSpan(random, v0, dv);
            double q0 = q[0];
            double dq = q[1];
            bySpan.provenance().begin(s);
            byPixel.provenance().begin(s);
            bySpan.fragments().span(y, from, to, q0, dq, v0, dv);
            bySpan.fragments().primitiveDone(); // each span a primitive of its own: they overlap
            drawByPixels(byPixel.fragments(), y, from, to, q0, dq, v0, dv, v);
            byPixel.fragments().primitiveDone();
        }
        assertSameDrawing(byPixel, bySpan);
    }

    /**
     * Phong pixels that wait to be shaded at the end ({@link FragmentStage#shadeLater})
     * draw what pixels shaded as they pass the depth test draw: colours, depths
     * and owners, with phong spans long and short, coloured spans and lone
     * pixels over and under them, on a few rows so that they overdraw.
     */
    @Property(tries = 150, seed = "1203009")
    void pixelsShadedAtTheEndDrawWhatPixelsShadedAtOnceDraw(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = sceneThatWaits(random);
        PointShader frozen = state.frozenShader().get();
        StageSetup atOnce = StageSetup.make(state, true);
        StageSetup atEnd = StageSetup.deferring(state);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        double[] v = new double[CHANNELS];
        int spans = 1 + random.nextInt(60);
        for (int s = 0; s < spans; s++) {
            boolean phong = random.nextInt(3) > 0;
            for (StageSetup stage : new StageSetup[] {atOnce, atEnd}) {
                if (phong) {
                    stage.fragments().phong(frozen, state.fog());
                } else {
                    stage.fragments().colours(state.fog());
                }
                stage.provenance().begin(s);
            }
            int y = 10 + random.nextInt(4);
            int from = random.nextInt(SIZE + 40) - 30;
            int to = from + (random.nextBoolean() ? random.nextInt(12) : random.nextInt(SIZE + 10));
            double[] q = randomSpan(random, v0, dv);
            double q0 = q[0];
            double dq = q[1];
            if (random.nextInt(5) == 0) {
                int x = from + random.nextInt(Math.max(1, to - from));
                for (int c = 0; c < CHANNELS; c++) {
                    v[c] = v0[c];
                }
                atOnce.fragments().pixel(x, y, q0, v);
                atEnd.fragments().pixel(x, y, q0, v);
            } else {
                atOnce.fragments().span(y, from, to, q0, dq, v0, dv);
                atEnd.fragments().span(y, from, to, q0, dq, v0, dv);
            }
            atOnce.fragments().primitiveDone();
            atEnd.fragments().primitiveDone();
        }
        atEnd.fragments().shadeWaiting();
        assertSameDrawing(atOnce, atEnd);
    }

    /**
     * Waiting pixels of several looks, lit at the end a look at a time in
     * batches of runs from many rows, draw what they draw shaded at once:
     * looks that come back after others (more of them than the stage
     * searches for a kept span's look), runs cut at a batch's end, spans
     * that hide others' waiting pixels, and spans shaded at once (the
     * ambient term, known colours) over and under them.
     */
    @Property(tries = 60, seed = "1204015")
    void waitingPixelsOfSeveralLooksDrawWhatTheyDrawShadedAtOnce(@ForAll long seed) {
        Random random = new Random(seed);
        int lookCount = 1 + random.nextInt(12);
        PointShader[] shaders = new PointShader[lookCount];
        Fog[] fogs = new Fog[lookCount];
        for (int i = 0; i < lookCount; i++) {
            LitState state = sceneThatWaits(random);
            shaders[i] = state.frozenShader().get();
            fogs[i] = state.fog();
        }
        LitState first = scene(random);
        StageSetup atOnce = StageSetup.make(first, true);
        StageSetup atEnd = StageSetup.deferring(first);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        PointShader ambient = ambientScene(random).frozenShader().get();
        int spans = 1 + random.nextInt(400);
        for (int s = 0; s < spans; s++) {
            int look = random.nextInt(lookCount + 2); // the last two shaded at once: the ambient term, colours
            for (StageSetup stage : new StageSetup[] {atOnce, atEnd}) {
                if (look < lookCount) {
                    stage.fragments().phong(shaders[look], fogs[look]);
                } else if (look == lookCount) {
                    stage.fragments().phong(ambient, first.fog());
                } else {
                    stage.fragments().colours(first.fog());
                }
                stage.provenance().begin(s);
            }
            int y = random.nextInt(SIZE);
            int from = random.nextInt(SIZE + 40) - 30;
            int to = from + (random.nextBoolean() ? random.nextInt(20) : random.nextInt(SIZE + 10));
            double[] q = randomSpan(random, v0, dv);
            atOnce.fragments().span(y, from, to, q[0], q[1], v0, dv);
            atEnd.fragments().span(y, from, to, q[0], q[1], v0, dv);
            atOnce.fragments().primitiveDone();
            atEnd.fragments().primitiveDone();
        }
        atEnd.fragments().shadeWaiting();
        assertSameDrawing(atOnce, atEnd);
    }

    /**
     * A primitive's short phong spans (one per row, as a rasterizer gives
     * them) draw what the same pixels draw one by one: with and without
     * lights, more pixels than a batch holds, and a second primitive over the
     * first. They wait until the primitive is done (or a BATCH of them
     * waits) and are written then, lit or not.
     */
    @Property(tries = 60, seed = "1204014")
    void aPrimitivesShortSpansWaitUntilItIsDoneAndDrawWhatItsPixelsDraw(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = random.nextBoolean() ? scene(random) : ambientScene(random);
        StageSetup bySpan = StageSetup.make(state, true);
        StageSetup byPixel = StageSetup.make(state, true);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        double[] v = new double[CHANNELS];
        for (int primitive = 0; primitive < 2; primitive++) {
            bySpan.provenance().begin(primitive);
            byPixel.provenance().begin(primitive);
            double[] q = randomSpan(random, v0, dv);
            int rows = 1 + random.nextInt(SIZE);
            int written = 0;
            for (int y = 0; y < rows; y++) {
                int from = random.nextInt(SIZE) - 2;
                int to = from + random.nextInt(6);
                // The same plane at every row: k counts from each span's own from, as a rasterizer's spans do.
                bySpan.fragments().span(y, from, to, q[0], q[1], v0, dv);
                drawByPixels(byPixel.fragments(), y, from, to, q[0], q[1], v0, dv, v);
                written += Math.max(0, Math.min(to, SIZE) - Math.max(from, 0));
            }
            if (primitive == 0 && written < FragmentStage.BATCH) {
                assertArrayEquals(pixels(StageSetup.make(state, true).image()), pixels(bySpan.image()),
                        "nothing written before the primitive is done");
            }
            bySpan.fragments().primitiveDone();
        }
        assertSameDrawing(byPixel, bySpan);
    }

    @Test
    void aLongLitPhongSpanWaitsUntilTheEndAndIsThenWhatItWouldHaveBeen() {
        LitState state = sceneThatWaits(new Random(5));
        PointShader frozen = state.frozenShader().get();
        StageSetup atOnce = StageSetup.make(state, true);
        StageSetup atEnd = StageSetup.make(state, true);
        WaitingPixels waiting = new WaitingPixels(SIZE, SIZE);
        atEnd.fragments().shadeLater(waiting, null);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        v0[FragmentLayout.Z] = -5;
        v0[FragmentLayout.NZ] = 1;
        v0[FragmentLayout.R] = 1;
        atOnce.fragments().phong(frozen, state.fog());
        atEnd.fragments().phong(frozen, state.fog());
        atOnce.fragments().span(10, 0, 100, 1, 0, v0, dv);
        atEnd.fragments().span(10, 0, 100, 1, 0, v0, dv);
        assertEquals(0, atEnd.image().getRGB(50, 10) & 0xFFFFFF, "not written yet");
        assertEquals(0, waiting.at(50, 10), "it waits for the first span kept");
        atEnd.fragments().shadeWaiting();
        assertEquals(WaitingPixels.NONE, waiting.at(50, 10));
        assertArrayEquals(pixels(atOnce.image()), pixels(atEnd.image()));
        assertTrue((atEnd.image().getRGB(50, 10) & 0xFFFFFF) != 0, "lit");
    }

    /**
     * With one light, a short span's pixels wait as points: nothing is
     * written until the end, a nearer long span (kept, its run written first
     * at the end) and a nearer short span take pixels from the first, a
     * farther one takes none, and the end draws what shading at once draws,
     * owners too.
     */
    @Test
    void aShortSpanLitByOneLightWaitsAsPointsUntilTheEnd() {
        LitState state = oneLightScene();
        PointShader frozen = state.frozenShader().get();
        assertEquals(1, frozen.lightCount());
        StageSetup atOnce = StageSetup.make(state, true);
        StageSetup atEnd = StageSetup.deferring(state);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        v0[FragmentLayout.NZ] = 1;
        v0[FragmentLayout.R] = 1;
        v0[FragmentLayout.G] = 0.5;
        dv[FragmentLayout.NX] = 0.05;
        double[] depths = {-5, -4.5, -4, -6}; // the first's pixels taken by the next two, not by the last
        int[] froms = {10, 12, 13, 8};
        int[] tos = {15, 12 + FragmentStage.SHORT_SPAN, 18, 13}; // the second a long span
        for (int s = 0; s < depths.length; s++) {
            v0[FragmentLayout.Z] = depths[s];
            for (StageSetup stage : new StageSetup[] {atOnce, atEnd}) {
                stage.fragments().phong(frozen, state.fog());
                stage.provenance().begin(s);
                stage.fragments().span(20, froms[s], tos[s], 1, 0, v0, dv);
                stage.fragments().primitiveDone();
            }
        }
        assertArrayEquals(pixels(StageSetup.make(state, true).image()), pixels(atEnd.image()), "nothing written yet");
        atEnd.fragments().shadeWaiting();
        assertSameDrawing(atOnce, atEnd);
        assertTrue((atEnd.image().getRGB(14, 20) & 0xFFFFFF) != 0, "lit");
    }

    /**
     * A stage whose last picture's one-light short spans passed many pixels
     * each keeps this picture's as spans (marked as waiting, not points),
     * and draws what a new stage, whose short spans wait as points, draws:
     * short and long spans over and under one another, with and without fog.
     */
    @Property(tries = 60, seed = "1205021")
    void oneLightShortSpansKeptAfterAPictureOfLongOnesDrawWhatPointsDraw(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = scene(random, 1);
        PointShader frozen = state.frozenShader().get();
        assertEquals(1, frozen.lightCount());
        StageSetup points = StageSetup.deferring(state);
        WaitingPixels waits = new WaitingPixels(SIZE, SIZE);
        StageSetup kept = keepingShortSpans(state, frozen, waits);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        double[] q = randomSpan(random, v0, dv);
        for (StageSetup stage : new StageSetup[] {points, kept}) {
            stage.fragments().phong(frozen, state.fog());
            stage.fragments().span(100, 40, 45, q[0], q[1], v0, dv);
            stage.fragments().primitiveDone();
        }
        assertTrue(waits.at(44, 100) != WaitingPixels.NONE, "the short span waits as a span, not as points");
        int spans = 1 + random.nextInt(50);
        for (int s = 0; s < spans; s++) {
            int y = 10 + random.nextInt(4);
            int from = random.nextInt(SIZE + 20) - 10;
            int length = random.nextBoolean() ? 1 + random.nextInt(FragmentStage.SHORT_SPAN - 1) : random.nextInt(SIZE);
            q = randomSpan(random, v0, dv);
            for (StageSetup stage : new StageSetup[] {points, kept}) {
                stage.fragments().phong(frozen, state.fog());
                stage.provenance().begin(s);
                stage.fragments().span(y, from, from + length, q[0], q[1], v0, dv);
                stage.fragments().primitiveDone();
            }
        }
        points.fragments().shadeWaiting();
        kept.fragments().shadeWaiting();
        assertSameDrawing(points, kept);
    }

    /**
     * Phong spans of one kd ({@link FragmentStage#phong(PointShader, Fog, boolean)}: the kd as it is in the
     * colour channels, with no slope) among spans whose kd is resolved, long and short, lit at once (short spans'
     * pixels waiting for their primitive, or lit alone after a primitive of a few) and at the picture's end
     * (kept spans, points, short pieces), draw what their pixels drawn one by one draw ({@link FragmentStage#pixel}
     * takes the colour channels as they are then): colours, depths and owners, to the bit.
     */
    @Property(tries = 120, seed = "1233033")
    void phongSpansOfOneKdDrawWhatTheirPixelsDrawEveryWay(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = random.nextInt(3) == 0 ? ambientScene(random) : sceneThatWaits(random);
        PointShader frozen = state.frozenShader().get();
        StageSetup byPixel = StageSetup.make(state, true);
        StageSetup atOnce = StageSetup.make(state, true);
        StageSetup atEnd = StageSetup.deferring(state);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        double[] v = new double[CHANNELS];
        int spans = 1 + random.nextInt(80);
        for (int s = 0; s < spans; s++) {
            boolean oneKd = random.nextInt(3) > 0;
            double[] q = randomSpan(random, v0, dv);
            if (oneKd) {
                for (int c = FragmentLayout.R; c <= FragmentLayout.B; c++) {
                    v0[c] = random.nextBoolean() ? 0.5 : random.nextDouble();
                    dv[c] = 0;
                }
            }
            int y = 10 + random.nextInt(4);
            int from = random.nextInt(SIZE + 40) - 30;
            int to = from + (random.nextBoolean() ? random.nextInt(12) : random.nextInt(SIZE + 10));
            for (StageSetup stage : new StageSetup[] {byPixel, atOnce, atEnd}) {
                stage.fragments().phong(frozen, state.fog(), oneKd);
                stage.provenance().begin(s);
            }
            atOnce.fragments().span(y, from, to, q[0], q[1], v0, dv);
            atEnd.fragments().span(y, from, to, q[0], q[1], v0, dv);
            drawByPixels(byPixel.fragments(), y, from, to, q[0], q[1], v0, dv, v);
            for (StageSetup stage : new StageSetup[] {byPixel, atOnce, atEnd}) {
                stage.fragments().primitiveDone();
            }
        }
        atEnd.fragments().shadeWaiting();
        assertSameDrawing(byPixel, atOnce);
        assertSameDrawing(byPixel, atEnd);
    }

    /** Colours of one-colour primitives: in [0, 1], a half byte, outside it, huge, and not finite. */
    private static final double[] ONE_COLOURS = {0.5, 0, 1, -0.3, 1.7, 1e300, -1e300, Double.NaN,
        Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};

    /**
     * Spans of one colour ({@link FragmentStage#oneColour}) and phong spans of one kd lit by the ambient term
     * alone, which are one colour too, long (a batch at a time under fog) and short (pixel by pixel), under no
     * fog and each of {@link #FOGS}, draw what their pixels drawn one by one draw: colours, depths and owners,
     * to the bit, whatever the colour or kd, in [0, 1] or not, finite or not.
     */
    @Property(tries = 120, seed = "1246001")
    void spansOfOneColourDrawWhatTheirPixelsDraw(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = ambientScene(random);
        PointShader frozen = state.frozenShader().get();
        StageSetup bySpan = StageSetup.make(state, true);
        StageSetup byPixel = StageSetup.make(state, true);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        double[] v = new double[CHANNELS];
        int spans = 1 + random.nextInt(60);
        for (int s = 0; s < spans; s++) {
            double[] q = randomSpan(random, v0, dv);
            for (int c = FragmentLayout.R; c <= FragmentLayout.B; c++) {
                v0[c] = random.nextBoolean() ? random.nextDouble() : ONE_COLOURS[random.nextInt(ONE_COLOURS.length)];
                dv[c] = 0;
            }
            Fog fog = random.nextInt(4) == 0 ? Fog.NONE : FOGS[random.nextInt(FOGS.length)];
            boolean lit = random.nextBoolean();
            int y = 10 + random.nextInt(4);
            int from = random.nextInt(SIZE + 40) - 30;
            int to = from + (random.nextBoolean() ? random.nextInt(FragmentStage.SHORT_SPAN) : random.nextInt(SIZE + 10));
            for (StageSetup stage : new StageSetup[] {bySpan, byPixel}) {
                if (lit) {
                    stage.fragments().phong(frozen, fog, true);
                } else {
                    stage.fragments().oneColour(fog);
                }
                stage.provenance().begin(s);
            }
            bySpan.fragments().span(y, from, to, q[0], q[1], v0, dv);
            drawByPixels(byPixel.fragments(), y, from, to, q[0], q[1], v0, dv, v);
            bySpan.fragments().primitiveDone();
            byPixel.fragments().primitiveDone();
        }
        assertSameDrawing(byPixel, bySpan);
    }

    /**
     * A phong span of one kd, 0.5, under an ambient light of 1 and lights behind it (which add nothing) is 0.5
     * at every pixel, whose byte is round(127.5) = 128, however its q runs: lit at once or at the end, long or
     * short, on a stage whose short spans are kept or wait as points. Resolved as (kd q) / q it was 127 at some.
     */
    @Property(tries = 60, seed = "1233034")
    void aPhongSpanOfOneKdIsThatKdAtEveryPixel(@ForAll long seed) {
        Random random = new Random(seed);
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.setAmbient(1, 1, 1);
        int lights = random.nextInt(3);
        for (int i = 0; i < lights; i++) {
            state.addLight(i, 0, -1000, 1, 1, 1, 1, 0); // far behind a face turned to +z
        }
        PointShader frozen = state.frozenShader().get();
        WaitingPixels waits = new WaitingPixels(SIZE, SIZE);
        StageSetup[] stages = {StageSetup.make(state, true), StageSetup.deferring(state),
            keepingShortSpans(state, frozen, waits)};
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        int rows = 1 + random.nextInt(SIZE);
        for (StageSetup stage : stages) {
            stage.fragments().phong(frozen, state.fog(), true);
        }
        for (int y = 0; y < rows; y++) {
            double depth = 4 + random.nextDouble() * 12;
            double q0 = 1 / depth;
            double dq = (random.nextDouble() - 0.5) * 1e-3 * q0;
            v0[FragmentLayout.Z] = -depth * q0;
            dv[FragmentLayout.Z] = -depth * dq;
            v0[FragmentLayout.NZ] = q0;
            dv[FragmentLayout.NZ] = dq;
            v0[FragmentLayout.R] = 0.5;
            v0[FragmentLayout.G] = 0.5;
            v0[FragmentLayout.B] = 0.5;
            int from = random.nextInt(SIZE) - 5;
            int to = from + (random.nextBoolean() ? random.nextInt(FragmentStage.SHORT_SPAN) : random.nextInt(SIZE));
            for (StageSetup stage : stages) {
                stage.fragments().span(y, from, to, q0, dq, v0, dv);
                if (random.nextInt(4) == 0) {
                    stage.fragments().primitiveDone();
                }
            }
        }
        for (StageSetup stage : stages) {
            stage.fragments().primitiveDone();
            stage.fragments().shadeWaiting();
            int written = 0;
            for (int p : pixels(stage.image())) {
                if ((p & 0xFFFFFF) != 0) {
                    assertEquals(0x808080, p & 0xFFFFFF, lights + " light(s)");
                    written++;
                }
            }
            assertTrue(written > 0 || rows < 4, "nothing written");
        }
    }

    /**
     * A deferring stage that has drawn a picture of one-light short spans of
     * ten pixels, all passing, and now starts a new picture on a surface of
     * its own, its pixels waiting in {@code waits}: its short spans are kept.
     */
    private static StageSetup keepingShortSpans(LitState state, PointShader frozen, WaitingPixels waits) {
        StageSetup first = StageSetup.deferring(state);
        FragmentStage fragments = first.fragments();
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        v0[FragmentLayout.Z] = -5;
        v0[FragmentLayout.NZ] = 1;
        v0[FragmentLayout.R] = 1;
        fragments.phong(frozen, state.fog());
        for (int y = 0; y < 8; y++) {
            fragments.span(y, 20, 30, 1, 0, v0, dv);
            fragments.primitiveDone();
        }
        fragments.shadeWaiting();
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        ZBuffer zbuffer = new ZBuffer(SIZE, SIZE);
        zbuffer.reset(-200);
        Provenance provenance = new Provenance(SIZE, SIZE);
        fragments.startPicture(zbuffer, new ProvenanceDrawable(provenance, new ImageDrawable(image)));
        fragments.shadeLater(waits, provenance);
        fragments.clearWaits();
        return new StageSetup(fragments, image, zbuffer, provenance);
    }

    /** Forwards the spans, but not the questions: every triangle is walked and every span given. */
    private static class Unasked implements FragmentSink {
        final FragmentSink sink;

        Unasked(FragmentSink sink) {
            this.sink = sink;
        }

        @Override
        public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
            sink.span(y, from, to, q0, dq, v0, dv);
        }

        @Override
        public void pixel(int x, int y, double q, double[] v) {
            sink.pixel(x, y, q, v);
        }

        @Override
        public void primitiveDone() {
            sink.primitiveDone();
        }

        @Override
        public int channelsRead(int channels) {
            return sink.channelsRead(channels);
        }
    }

    /** Forwards the questions too, and counts the answers that let a rasterizer skip work. */
    private static final class Asked extends Unasked {
        int hidden;
        int noneNearer;

        Asked(FragmentSink sink) {
            super(sink);
        }

        @Override
        public boolean anyNearer(int y, int from, int to, double q0, double dq, double z0, double dz) {
            boolean nearer = sink.anyNearer(y, from, to, q0, dq, z0, dz);
            noneNearer += nearer ? 0 : 1;
            return nearer;
        }

        @Override
        public boolean hides(int firstRow, int lastRow, int firstColumn, int lastColumn, double z) {
            boolean hides = sink.hides(firstRow, lastRow, firstColumn, lastColumn, z);
            hidden += hides ? 1 : 0;
            return hides;
        }
    }

    /**
     * A triangle or quad of the given size in pixels about (cx, cy), its
     * corners' z on a tilted plane about z, laid out for the rasterizer.
     */
    private static double[] polygon(Random random, int n, double cx, double cy, double size, double z) {
        int stride = FragmentLayout.stride(CHANNELS);
        double[] v = new double[n * stride];
        double tiltX = (random.nextDouble() - 0.5) * 0.2;
        double tiltY = (random.nextDouble() - 0.5) * 0.2;
        double q = 1 / (4 + random.nextDouble() * 12);
        boolean oneQ = random.nextBoolean();
        for (int k = 0; k < n; k++) {
            double angle = 2 * Math.PI * k / n + random.nextDouble() * 0.5;
            double x = cx + size * Math.cos(angle);
            double y = cy + size * Math.sin(angle);
            double qk = oneQ ? q : q * (1 + (random.nextDouble() - 0.5) * 0.1);
            double[] channels = new double[CHANNELS];
            channels[FragmentLayout.Z] = z + tiltX * (x - cx) + tiltY * (y - cy);
            channels[FragmentLayout.R] = random.nextDouble();
            channels[FragmentLayout.G] = random.nextDouble();
            channels[FragmentLayout.B] = random.nextDouble();
            channels[FragmentLayout.PX] = (x - SIZE / 2.0) / SIZE;
            channels[FragmentLayout.PY] = (y - SIZE / 2.0) / SIZE;
            channels[FragmentLayout.NX] = random.nextDouble() - 0.5;
            channels[FragmentLayout.NY] = random.nextDouble() - 0.5;
            channels[FragmentLayout.NZ] = 1;
            v[k * stride + FragmentLayout.X] = x;
            v[k * stride + FragmentLayout.Y] = y;
            v[k * stride + FragmentLayout.Q] = qk;
            for (int c = 0; c < CHANNELS; c++) {
                v[k * stride + FragmentLayout.CHANNEL + c] = channels[c] * qk;
            }
        }
        return v;
    }

    /**
     * Triangles the rasterizer skips, as hidden behind what is drawn or as
     * rows none of whose pixels is nearer, draw what they draw walked and
     * given in full: mesh-like runs of small polygons drawn over one another
     * at depths apart by nothing, by a few units in the last place, by a
     * billionth and by units, some slivers, some over the panel's edges;
     * phong and coloured, shaded at once and at the end.
     */
    @Test
    void trianglesSkippedAsHiddenDrawWhatTheyDrawGivenInFull() {
        Random random = new Random(1205021);
        int hidden = 0;
        int noneNearer = 0;
        for (int trial = 0; trial < 40; trial++) {
            LitState state = random.nextBoolean() ? sceneThatWaits(random) : scene(random);
            boolean atEnd = random.nextBoolean();
            StageSetup asked = atEnd ? StageSetup.deferring(state) : StageSetup.make(state, true);
            StageSetup unasked = atEnd ? StageSetup.deferring(state) : StageSetup.make(state, true);
            Asked askedSink = new Asked(asked.fragments());
            FragmentSink unaskedSink = new Unasked(unasked.fragments());
            LitPolygonRasterizer rasterizer = new LitPolygonRasterizer();
            LitPolygonRasterizer unaskedRasterizer = new LitPolygonRasterizer();
            double[] offsets = {0, Math.ulp(8.0), -Math.ulp(8.0), 3 * Math.ulp(8.0), -3 * Math.ulp(8.0), 1e-9, -1e-9, 1, -1};
            int polygons = 20 + random.nextInt(200);
            for (int p = 0; p < polygons; p++) {
                boolean phong = random.nextInt(4) > 0;
                for (StageSetup stage : new StageSetup[] {asked, unasked}) {
                    if (phong) {
                        stage.fragments().phong(state.frozenShader().get(), state.fog());
                    } else {
                        stage.fragments().colours(state.fog());
                    }
                    stage.provenance().begin(p);
                }
                // About the same places again and again, as a mesh's layers are.
                double cx = 20 + random.nextInt(6) * 20 + random.nextDouble();
                double cy = 20 + random.nextInt(6) * 20 + random.nextDouble();
                double size = random.nextInt(8) == 0 ? 80 : 1 + random.nextDouble() * 6;
                double z = -8 + offsets[random.nextInt(offsets.length)];
                int n = 3 + random.nextInt(2);
                double[] v = polygon(random, n, cx, cy, size, z);
                if (random.nextInt(10) == 0) {
                    int stride = FragmentLayout.stride(CHANNELS);
                    v[2 * stride + FragmentLayout.X] = (v[FragmentLayout.X] + v[stride + FragmentLayout.X]) / 2 + 1e-7;
                    v[2 * stride + FragmentLayout.Y] = (v[FragmentLayout.Y] + v[stride + FragmentLayout.Y]) / 2;
                }
                int channels = phong ? CHANNELS : FragmentLayout.COLOUR_CHANNELS;
                if (!phong) {
                    v = colourLayout(v, n);
                }
                rasterizer.fill(v, n, channels, SIZE, SIZE, askedSink);
                unaskedRasterizer.fill(v, n, channels, SIZE, SIZE, unaskedSink);
            }
            if (atEnd) {
                asked.fragments().shadeWaiting();
                unasked.fragments().shadeWaiting();
            }
            assertSameDrawing(unasked, asked);
            hidden += askedSink.hidden;
            noneNearer += askedSink.noneNearer;
        }
        assertTrue(hidden > 200, hidden + " triangles skipped as hidden");
        assertTrue(noneNearer > 200, noneNearer + " rows with no pixel nearer");
    }

    /**
     * Polygons a stage guesses unlit (told of each, {@link FragmentStage#polygon})
     * draw what they draw untold: faces turned from every light, to them,
     * edge on, and curved ones whose corners disagree (N tilted across them),
     * shaded at the end and at once, among coloured ones; every other time
     * under no ambient light, where batches no light reaches come out black
     * ({@link LitPoints#black}), with no fog, fog towards black, and fog the
     * stage takes pixel by pixel or towards another colour. Fails unless some
     * batches were lit as guessed unlit, and some came out black.
     */
    @Test
    void polygonsGuessedUnlitDrawWhatTheyDrawUntold() {
        Random random = new Random(1205023);
        Fog[] withNoAmbient = {Fog.NONE, new Fog(-8, -16, 0, 0, -0.0), new Fog(-10, -10, 0, 0, 0), FOGS[0]};
        int unlitBatches = 0;
        int blackBatches = 0;
        for (int trial = 0; trial < 40; trial++) {
            LitState state = scene(random, 0);
            if (trial % 2 == 1) {
                state.setAmbient(0, -0.0, 0);
                state.setFog(withNoAmbient[random.nextInt(withNoAmbient.length)]);
            }
            int lights = 1 + random.nextInt(2);
            for (int i = 0; i < lights; i++) {
                state.addLight(random.nextDouble() * 4 - 2, random.nextDouble() * 4 - 2, -30 + random.nextInt(2) * 28,
                        0.9, 0.7, 0.5, 1, random.nextBoolean() ? 0 : 0.02);
            }
            boolean atEnd = random.nextBoolean();
            StageSetup told = atEnd ? StageSetup.deferring(state) : StageSetup.make(state, true);
            StageSetup untold = atEnd ? StageSetup.deferring(state) : StageSetup.make(state, true);
            BatchCount shader = new BatchCount(state.frozenShader().get());
            LitPolygonRasterizer rasterizer = new LitPolygonRasterizer();
            LitPolygonRasterizer untoldRasterizer = new LitPolygonRasterizer();
            FragmentSink untoldSink = new Unasked(untold.fragments()); // not told of polygons
            int polygons = 10 + random.nextInt(60);
            for (int p = 0; p < polygons; p++) {
                boolean phong = random.nextInt(5) > 0;
                for (StageSetup stage : new StageSetup[] {told, untold}) {
                    if (phong) {
                        stage.fragments().phong(shader, state.fog());
                    } else {
                        stage.fragments().colours(state.fog());
                    }
                    stage.provenance().begin(p);
                }
                int n = 3 + random.nextInt(2);
                double size = random.nextInt(4) == 0 ? 60 : 3 + random.nextDouble() * 20;
                double[] v = polygon(random, n, 20 + random.nextDouble() * 110, 20 + random.nextDouble() * 110, size,
                        -8 + random.nextDouble());
                turn(v, n, random);
                int channels = phong ? CHANNELS : FragmentLayout.COLOUR_CHANNELS;
                if (!phong) {
                    v = colourLayout(v, n);
                }
                rasterizer.fill(v, n, channels, SIZE, SIZE, told.fragments());
                untoldRasterizer.fill(v, n, channels, SIZE, SIZE, untoldSink);
            }
            if (atEnd) {
                told.fragments().shadeWaiting();
                untold.fragments().shadeWaiting();
            }
            assertSameDrawing(untold, told);
            unlitBatches += shader.unlit;
            blackBatches += shader.black;
        }
        assertTrue(unlitBatches > 20, unlitBatches + " batches lit as guessed unlit");
        assertTrue(blackBatches > 10, blackBatches + " batches lit black");
    }

    /**
     * The polygon's normals (of +z, as {@link #polygon} makes them) turned:
     * to -z, or edge on, or each corner its own way, or left.
     */
    private static void turn(double[] v, int n, Random random) {
        int stride = FragmentLayout.stride(CHANNELS);
        int how = random.nextInt(4);
        for (int k = 0; k < n; k++) {
            int c = k * stride + FragmentLayout.CHANNEL;
            double q = v[k * stride + FragmentLayout.Q];
            if (how == 0) {
                v[c + FragmentLayout.NZ] = -v[c + FragmentLayout.NZ];
            } else if (how == 1) {
                v[c + FragmentLayout.NX] = (random.nextBoolean() ? 1e-3 : -1e-3) * q;
                v[c + FragmentLayout.NY] = q;
                v[c + FragmentLayout.NZ] = 0;
            } else if (how == 2) {
                v[c + FragmentLayout.NZ] = (random.nextDouble() * 2 - 1) * q;
            }
        }
    }

    /** A shader that counts the batches it lights as guessed unlit. */
    private static final class BatchCount implements PointShader {
        private final PointShader shader;
        int unlit;
        int black;

        BatchCount(PointShader shader) {
            this.shader = shader;
        }

        @Override
        public void shade(double px, double py, double pz, double nx, double ny, double nz, double kr, double kg,
                double kb, double[] out) {
            shader.shade(px, py, pz, nx, ny, nz, kr, kg, kb, out);
        }

        @Override
        public void shade(LitPoints points) {
            unlit += points.unlit ? 1 : 0;
            shader.shade(points);
            black += points.black ? 1 : 0;
        }

        @Override
        public boolean usesPoint() {
            return shader.usesPoint();
        }

        @Override
        public int lightCount() {
            return shader.lightCount();
        }

        @Override
        public boolean unlitAt(double px, double py, double pz, double nx, double ny, double nz) {
            return shader.unlitAt(px, py, pz, nx, ny, nz);
        }
    }

    /** The same polygon with only the colour channels (z, kd). */
    private static double[] colourLayout(double[] phong, int n) {
        int from = FragmentLayout.stride(CHANNELS);
        int to = FragmentLayout.stride(FragmentLayout.COLOUR_CHANNELS);
        double[] v = new double[n * to];
        for (int k = 0; k < n; k++) {
            System.arraycopy(phong, k * from, v, k * to, to);
        }
        return v;
    }

    @Test
    void aFullRowIsDrawnAndASecondFartherOneLeavesItAlone() {
        LitState state = scene(new Random(5));
        StageSetup stage = StageSetup.make(state, true);
        double[] v0 = new double[CHANNELS];
        double[] dv = new double[CHANNELS];
        v0[FragmentLayout.Z] = -5;
        v0[FragmentLayout.NZ] = 1;
        v0[FragmentLayout.R] = 1;
        stage.provenance().begin(1);
        stage.fragments().span(10, -5, SIZE + 5, 1, 0, v0, dv);
        v0[FragmentLayout.Z] = -6;
        stage.provenance().begin(2);
        stage.fragments().span(10, 0, SIZE, 1, 0, v0, dv);
        for (int x = 0; x < SIZE; x++) {
            assertEquals(-5, stage.zbuffer().depthAt(x, 10));
            assertEquals(1, stage.provenance().ownerAt(x, 10));
            assertTrue((stage.image().getRGB(x, 10) & 0xFFFFFF) != 0, "pixel " + x + " is lit");
        }
    }

    private static int[] pixels(BufferedImage image) {
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }
}
