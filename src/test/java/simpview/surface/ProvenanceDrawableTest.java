package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;
import simpview.geometry.Vertex;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.testing.RecordingDrawable;

/**
 * The provenance record, checked against a recording of every write that
 * passes the z-buffer: after a random scene, each pixel's recorded primitive
 * is the one whose write the z-buffer kept (the last write that got through
 * to it), and a pixel nobody wrote is background.
 */
class ProvenanceDrawableTest {

    private static final int SIZE = 96;

    @Property(tries = 60, seed = "1202011")
    void everyPixelNamesThePrimitiveWhoseWriteTheZBufferKept(@ForAll long seed) {
        Random random = new Random(seed);
        Provenance provenance = new Provenance(SIZE, SIZE);
        BufferedSink sink = new BufferedSink();
        Drawable recorded = new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(new ZBuffer(SIZE, SIZE),
                new ProvenanceDrawable(provenance, sink)));
        RecordingDrawable writes = new RecordingDrawable(SIZE, SIZE);
        Drawable reference = new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(new ZBuffer(SIZE, SIZE), writes));
        int[] expected = new int[SIZE * SIZE];
        Arrays.fill(expected, Provenance.BACKGROUND);
        int primitives = 1 + random.nextInt(40);
        for (int k = 0; k < primitives; k++) {
            Vertex[] v = {vertex(random), vertex(random), vertex(random)};
            int kind = random.nextInt(3);
            provenance.begin(k);
            draw(kind, v, recorded);
            int before = writes.writes().size();
            draw(kind, v, reference);
            List<RecordingDrawable.Write> made = writes.writes();
            for (int w = before; w < made.size(); w++) {
                expected[made.get(w).y() * SIZE + made.get(w).x()] = k;
            }
        }
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                assertEquals(expected[y * SIZE + x], provenance.ownerAt(x, y), "pixel (" + x + ", " + y + ")");
            }
        }
    }

    /** Depths from a few levels, so equal depths (the first write stays) happen often. */
    private static Vertex vertex(Random random) {
        double z = random.nextBoolean() ? -50 - 25 * random.nextInt(4) : -1 - 198 * random.nextDouble();
        return new Vertex(-10 + (SIZE + 20) * random.nextDouble(), -10 + (SIZE + 20) * random.nextDouble(), z,
                random.nextDouble(), random.nextDouble(), random.nextDouble());
    }

    private static void draw(int kind, Vertex[] v, Drawable target) {
        switch (kind) {
            case 0 -> new FilledPolygonRenderer().drawPolygon(v[0], v[1], v[2], target);
            case 1 -> new DdaLineRenderer().drawLine(v[0], v[1], target);
            default -> new WireframePolygonRenderer(new DdaLineRenderer()).drawPolygon(v[0], v[1], v[2], target);
        }
    }

    @Test
    void withoutTheRecordTheChainDrawsTheSamePicture() {
        PageCanvas plain = new PageCanvas();
        PageCanvas recording = new PageCanvas();
        recording.recordProvenance(new Provenance(PageCanvas.PANEL, PageCanvas.PANEL));
        Random random = new Random(7);
        Drawable a = plain.depthCued(Rgb.WHITE, Rgb.BLACK);
        Drawable b = recording.depthCued(Rgb.WHITE, Rgb.BLACK);
        FilledPolygonRenderer renderer = new FilledPolygonRenderer();
        for (int k = 0; k < 50; k++) {
            Vertex[] v = new Vertex[3];
            for (int i = 0; i < 3; i++) {
                v[i] = new Vertex(650 * random.nextDouble(), 650 * random.nextDouble(), -200 * random.nextDouble(), 1, 1, 1);
            }
            recording.provenance().begin(k);
            renderer.drawPolygon(v[0], v[1], v[2], a);
            renderer.drawPolygon(v[0], v[1], v[2], b);
        }
        int[] left = plain.image().getRGB(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, null, 0, PageCanvas.SIZE);
        int[] right = recording.image().getRGB(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, null, 0, PageCanvas.SIZE);
        assertTrue(Arrays.equals(left, right), "the record never changes a pixel");
        recording.clear();
        assertEquals(Provenance.BACKGROUND, recording.provenance().ownerAt(325, 325), "cleared with the canvas");
    }

    /** Keeps nothing; stands for the rest of the chain. */
    @Test
    void fromRecordsTheReadingAndTheDrawingAreApart() {
        Provenance provenance = new Provenance(SIZE, SIZE);
        Drawable panel = new ProvenanceDrawable(provenance, new BufferedSink());
        provenance.begin(3);
        panel.setPixel(1, 1, 0, Colors.BLACK);
        assertEquals(3, provenance.ownerAt(1, 1), "drawn as read: what is read is what is drawn");
        provenance.drawnFromRecords();
        provenance.useBands(new RowBands(SIZE, 2));
        provenance.begin(0, 7); // a drawer of the lower band draws primitive 7 ...
        provenance.begin(40); // ... while the reading thread reads primitive 40
        assertEquals(40, provenance.current());
        panel.setPixel(2, 2, 0, Colors.BLACK);
        panel.setPixel(2, SIZE - 1, 0, Colors.BLACK);
        assertEquals(7, provenance.ownerAt(2, 2), "the drawer's primitive, not the one being read");
        assertEquals(Provenance.BACKGROUND, provenance.ownerAt(2, SIZE - 1), "the upper band's drawer said nothing yet");
        provenance.reset();
        provenance.begin(5);
        panel.setPixel(3, 3, 0, Colors.BLACK);
        assertEquals(5, provenance.ownerAt(3, 3), "reset: drawn as read again");
    }

    private static final class BufferedSink implements Drawable {
        @Override
        public int width() {
            return SIZE;
        }

        @Override
        public int height() {
            return SIZE;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
        }

        @Override
        public int getPixel(int x, int y) {
            return 0;
        }

        @Override
        public void fillSpan(Span span) {
        }
    }
}
