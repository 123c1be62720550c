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
 * Small triangles: a 100,000-triangle mesh tiling the panel (cells of 2 to 4
 * px). Ours goes through scissor, z-buffer and depth cue with per-vertex
 * colour and depth; Java2D fills the same integer triangles with a flat
 * colour each. Ours takes the triangles as plain numbers, as scenes give
 * them; Java2D as int arrays. One op is one triangle: the score is triangles/s. The
 * z-buffer is reset before each invocation, outside the timing.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class SmallTriangles extends AgainstJava2D {

    private Drawable target;
    private final FilledPolygonRenderer renderer = new FilledPolygonRenderer();
    private Workload.Triangles mesh;

    @Override
    protected void prepare() {
        target = canvas.depthCued(Rgb.WHITE, Rgb.BLACK);
        mesh = Workload.mesh();
    }

    @Benchmark
    @OperationsPerInvocation(Workload.MESH_TRIANGLES)
    public PageCanvas simpview() {
        // The triangles as plain numbers, as a scene hands them over.
        double[] p = mesh.numbers;
        int stride = 3 * Vertex.NUMBERS;
        for (int at = 0; at < p.length; at += stride) {
            renderer.drawPolygon(p, at, target);
        }
        return canvas;
    }

    @Benchmark
    @OperationsPerInvocation(Workload.MESH_TRIANGLES)
    public BufferedImage java2d() {
        int n = mesh.count();
        for (int t = 0; t < n; t++) {
            java2d.g.setColor(mesh.colors[t]);
            java2d.g.fillPolygon(mesh.imageXs[t], mesh.imageYs[t], 3);
        }
        return java2d.image;
    }
}
