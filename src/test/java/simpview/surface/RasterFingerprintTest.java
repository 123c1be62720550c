package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Random;
import java.util.zip.CRC32;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import simpview.geometry.Vertex;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.stage.CuedPrimitives;
import simpview.stage.Painter;

/**
 * Guards the raster fast paths against any change of output while they are
 * optimised: many random triangles and lines (on and off the panel, in and
 * out of the depth range, large and tiny) through each drawable chain, and a
 * checksum of every pixel and every depth. The expected checksums were
 * recorded from the unoptimised code (commit 86fd575) and recorded again
 * when SPEC's line rule changed (rounded endpoints, drawn from the smaller
 * x or y, the minor coordinate added up per step: issue 23; the lines'
 * pixels are held by DdaLineRendererTest's exact expectations); an
 * optimisation must never change them. The same primitives given as plain numbers
 * (the renderers' array entries, as scenes use them) must match the same
 * checksums, and so must the same primitives drawn band by band by 2 and by
 * 7 threads.
 */
class RasterFingerprintTest {

    private static final Rgb NEAR = new Rgb(1, 0.8, 0.3);
    private static final Rgb FAR = new Rgb(0.1, 0, 0.2);

    @ParameterizedTest(name = "{0}")
    @MethodSource("ways")
    void panelChain(Way entry) {
        PageCanvas canvas = new PageCanvas();
        draw(canvas, canvas.panel(), 11, entry);
        assertEquals(3035845392L, checksum(canvas), "panel");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("ways")
    void depthTestedChain(Way entry) {
        PageCanvas canvas = new PageCanvas();
        draw(canvas, canvas.depthTested(), 12, entry);
        assertEquals(1872279498L, checksum(canvas), "depth tested");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("ways")
    void depthCuedChain(Way entry) {
        PageCanvas canvas = new PageCanvas();
        draw(canvas, canvas.depthCued(NEAR, FAR), 13, entry);
        assertEquals(1458905852L, checksum(canvas), "depth cued");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("ways")
    void depthCuedWhiteToBlackChain(Way entry) {
        PageCanvas canvas = new PageCanvas();
        draw(canvas, canvas.depthCued(Rgb.WHITE, Rgb.BLACK), 14, entry);
        assertEquals(2691378239L, checksum(canvas), "depth cued white to black");
    }

    /** How the primitives reach the renderers. */
    enum Entry { VERTICES, NUMBERS }

    /**
     * An entry and the threads that draw: more than one records the
     * primitives as numbers and draws them band by band ({@link CuedPrimitives}).
     */
    record Way(Entry entry, int threads) {
        @Override
        public String toString() {
            return entry + " on " + threads + (threads == 1 ? " thread" : " threads");
        }
    }

    static List<Way> ways() {
        return List.of(new Way(Entry.VERTICES, 1), new Way(Entry.NUMBERS, 1), new Way(Entry.NUMBERS, 2),
                new Way(Entry.NUMBERS, 7));
    }

    private static void draw(PageCanvas canvas, Drawable target, long seed, Way way) {
        try (DrawingThreads threads = DrawingThreads.of(way.threads())) {
            Renderers r = new Renderers(way.entry(), threads, target);
            draw(r, target, seed);
            r.finish();
        }
    }

    private static void draw(Renderers r, Drawable target, long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 3000; i++) {
            double size = i % 3 == 0 ? 900 : i % 3 == 1 ? 60 : 4;
            double cx = random.nextDouble() * 800 - 75;
            double cy = random.nextDouble() * 800 - 75;
            Vertex a = vertex(random, cx, cy, size);
            Vertex b = vertex(random, cx, cy, size);
            Vertex c = vertex(random, cx, cy, size);
            if (i % 4 == 3) {
                r.line(a, b, target);
            } else {
                r.triangle(a, b, c, target);
            }
        }
        // A shared-edge pair and an axis-aligned pair on pixel centres.
        r.triangle(Vertex.of(10.5, 10.5, -50), Vertex.of(300.5, 10.5, -60), Vertex.of(300.5, 200.5, -70), target);
        r.triangle(Vertex.of(10.5, 10.5, -50), Vertex.of(300.5, 200.5, -70), Vertex.of(10.5, 200.5, -40), target);
    }

    /** The renderers, fed vertices or the same vertices as numbers at an offset in a larger array. */
    private static final class Renderers {
        private static final int AT = 5;
        private final FilledPolygonRenderer filled = new FilledPolygonRenderer();
        private final DdaLineRenderer lines = new DdaLineRenderer();
        private final double[] numbers = new double[AT + 3 * Vertex.NUMBERS + 1];
        private final Entry entry;
        /** With more than one thread: the painter that records, and its record. */
        private final Painter painter;
        private final CuedPrimitives record;
        private final double[] primitive = new double[Painter.STRIDE];

        Renderers(Entry entry, DrawingThreads threads, Drawable target) {
            this.entry = entry;
            if (threads.isOne()) {
                painter = null;
                record = null;
            } else {
                painter = new Painter(target, lines, filled, filled);
                record = new CuedPrimitives(threads, null, () -> OwedRows.NONE, target, null);
                painter.recordTo(record);
            }
        }

        /** Draws what was recorded. */
        void finish() {
            if (record != null) {
                record.flush();
            }
        }

        void triangle(Vertex a, Vertex b, Vertex c, Drawable target) {
            if (painter != null) {
                a.writeTo(primitive, 0);
                b.writeTo(primitive, Vertex.NUMBERS);
                c.writeTo(primitive, 2 * Vertex.NUMBERS);
                painter.draw(Painter.FILLED, primitive, 0);
                return;
            }
            if (entry == Entry.VERTICES) {
                filled.drawPolygon(a, b, c, target);
                return;
            }
            a.writeTo(numbers, AT);
            b.writeTo(numbers, AT + Vertex.NUMBERS);
            c.writeTo(numbers, AT + 2 * Vertex.NUMBERS);
            filled.drawPolygon(numbers, AT, target);
        }

        void line(Vertex a, Vertex b, Drawable target) {
            if (painter != null) {
                a.writeTo(primitive, 0);
                b.writeTo(primitive, Vertex.NUMBERS);
                painter.draw(Painter.LINE, primitive, 0);
                return;
            }
            if (entry == Entry.VERTICES) {
                lines.drawLine(a, b, target);
                return;
            }
            // The second end first in the array: the entry takes any two offsets.
            b.writeTo(numbers, AT);
            a.writeTo(numbers, AT + 2 * Vertex.NUMBERS);
            lines.drawLine(numbers, AT + 2 * Vertex.NUMBERS, AT, target);
        }
    }

    private static Vertex vertex(Random random, double cx, double cy, double size) {
        return new Vertex(cx + (random.nextDouble() - 0.5) * size, cy + (random.nextDouble() - 0.5) * size,
                random.nextDouble() * 240 - 220, random.nextDouble() * 1.2 - 0.1,
                random.nextDouble(), random.nextDouble());
    }

    private static long checksum(PageCanvas canvas) {
        CRC32 crc = new CRC32();
        for (int y = 0; y < PageCanvas.SIZE; y++) {
            for (int x = 0; x < PageCanvas.SIZE; x++) {
                update(crc, canvas.image().getRGB(x, y));
            }
        }
        ZBuffer z = canvas.zbuffer();
        for (int y = 0; y < z.height(); y++) {
            for (int x = 0; x < z.width(); x++) {
                long bits = Double.doubleToLongBits(z.depthAt(x, y));
                update(crc, (int) bits);
                update(crc, (int) (bits >>> 32));
            }
        }
        return crc.getValue();
    }

    private static void update(CRC32 crc, int v) {
        crc.update(v >>> 24);
        crc.update(v >>> 16);
        crc.update(v >>> 8);
        crc.update(v);
    }
}
