package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * The renderers' entries for primitives given as plain numbers, which scenes
 * use: they draw what the vertex entries draw (RasterFingerprintTest checks
 * that pixel for pixel) and allocate nothing per primitive, so a scene of a
 * million polygons makes no garbage in the drawing.
 */
class DrawingFromNumbersTest {

    private static final int PRIMITIVES = 3_000;

    private final FilledPolygonRenderer filled = new FilledPolygonRenderer();
    private final DdaLineRenderer lines = new DdaLineRenderer();
    private final WireframePolygonRenderer wire = new WireframePolygonRenderer(new DdaLineRenderer());
    private final double[] numbers = numbers(new Random(5));

    @Test
    void filledLinesAndWireframeAllocateNothingPerPrimitive() {
        com.sun.management.ThreadMXBean threads = allocationCounter();
        PageCanvas canvas = new PageCanvas();
        Drawable depthCued = canvas.depthCued(new Rgb(1, 0.75, 0.3), Rgb.BLACK);
        Drawable shaded = canvas.depthTested();
        drawAll(depthCued, shaded); // loads and initialises every class on the way first

        long before = threads.getCurrentThreadAllocatedBytes();
        drawAll(depthCued, shaded);
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;

        int drawn = 2 * 3 * PRIMITIVES;
        assertTrue(allocated < drawn / 10, allocated + " bytes allocated while drawing " + drawn + " primitives");
    }

    @Test
    void aWireframeFromNumbersDrawsItsThreeEdgesAsLines() {
        PageCanvas fromNumbers = new PageCanvas();
        PageCanvas fromLines = new PageCanvas();
        int stride = 3 * Vertex.NUMBERS;
        for (int at = 0; at + stride <= numbers.length; at += stride) {
            wire.drawPolygon(numbers, at, fromNumbers.depthTested());
            Vertex a = Vertex.readFrom(numbers, at);
            Vertex b = Vertex.readFrom(numbers, at + Vertex.NUMBERS);
            Vertex c = Vertex.readFrom(numbers, at + 2 * Vertex.NUMBERS);
            Drawable target = fromLines.depthTested();
            lines.drawLine(a, b, target);
            lines.drawLine(b, c, target);
            lines.drawLine(c, a, target);
        }
        int[] expected = fromLines.image().getRGB(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, null, 0, PageCanvas.SIZE);
        int[] got = fromNumbers.image().getRGB(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, null, 0, PageCanvas.SIZE);
        int differing = 0;
        for (int i = 0; i < expected.length; i++) {
            differing += expected[i] == got[i] ? 0 : 1;
        }
        assertEquals(0, differing, "pixels differing");
    }

    private void drawAll(Drawable depthCued, Drawable shaded) {
        int stride = 3 * Vertex.NUMBERS;
        for (Drawable target : new Drawable[] {depthCued, shaded}) {
            for (int at = 0; at + stride <= numbers.length; at += stride) {
                filled.drawPolygon(numbers, at, target);
                lines.drawLine(numbers, at, at + Vertex.NUMBERS, target);
                wire.drawPolygon(numbers, at, target);
            }
        }
    }

    /** Triangles of 2 to 200 px across the panel, some reaching off it, in and out of the depth range. */
    private static double[] numbers(Random random) {
        double[] p = new double[PRIMITIVES * 3 * Vertex.NUMBERS];
        for (int t = 0; t < PRIMITIVES; t++) {
            double size = t % 2 == 0 ? 200 : 2;
            double cx = random.nextDouble() * 700 - 25;
            double cy = random.nextDouble() * 700 - 25;
            for (int v = 0; v < 3; v++) {
                new Vertex(cx + (random.nextDouble() - 0.5) * size, cy + (random.nextDouble() - 0.5) * size,
                        random.nextDouble() * 220 - 210, random.nextDouble(), random.nextDouble(),
                        random.nextDouble()).writeTo(p, (3 * t + v) * Vertex.NUMBERS);
            }
        }
        return p;
    }

    private static com.sun.management.ThreadMXBean allocationCounter() {
        ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        assumeTrue(bean instanceof com.sun.management.ThreadMXBean counter
                && counter.isThreadAllocatedMemorySupported() && counter.isThreadAllocatedMemoryEnabled(),
                "this JVM does not count the bytes a thread allocates");
        return (com.sun.management.ThreadMXBean) bean;
    }
}
