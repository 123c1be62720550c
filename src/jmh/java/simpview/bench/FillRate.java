package simpview.bench;

import java.awt.image.BufferedImage;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Warmup;
import simpview.geometry.Vertex;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.raster.FilledPolygonRenderer;

/**
 * Fill rate: two triangles covering the whole 650x650 panel. Ours blerps,
 * z-tests and depth-cues every pixel (the SIMP pages' chain); Java2D fills
 * the same two triangles with a flat colour. One op is one pixel, so the
 * score in ops/us is Mpixels/s. The z-buffer is reset before each invocation,
 * outside the timing, so every pixel passes the depth test and is written.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class FillRate extends AgainstJava2D {

    private Drawable target;
    private final FilledPolygonRenderer renderer = new FilledPolygonRenderer();
    private Workload.Triangles triangles;

    @Override
    protected void prepare() {
        target = canvas.depthCued(Rgb.WHITE, Rgb.BLACK);
        triangles = Workload.fullPanel();
    }

    @Benchmark
    @OperationsPerInvocation(Workload.PANEL_PIXELS)
    public PageCanvas simpview() {
        double[] p = triangles.numbers;
        renderer.drawPolygon(p, 0, target);
        renderer.drawPolygon(p, 3 * Vertex.NUMBERS, target);
        return canvas;
    }

    @Benchmark
    @OperationsPerInvocation(Workload.PANEL_PIXELS)
    public BufferedImage java2d() {
        for (int t = 0; t < 2; t++) {
            java2d.g.setColor(triangles.colors[t]);
            java2d.g.fillPolygon(triangles.imageXs[t], triangles.imageYs[t], 3);
        }
        return java2d.image;
    }
}
