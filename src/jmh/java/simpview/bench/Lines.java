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
import simpview.raster.DdaLineRenderer;

/**
 * 100,000 random lines between pixel centres of the panel (seed 7, about 340
 * px long on average). Ours with the DDA, lerping colour (and z): straight
 * onto the panel as page 1 draws, and through the SIMP pages' chain (scissor,
 * z-buffer, depth cue; z-buffer reset before each invocation, outside the
 * timing). Java2D: drawLine between the same end pixels, flat colour per
 * line. One op is one line: the score is lines/s.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class Lines extends AgainstJava2D {

    private Drawable panel;
    private Drawable depthCued;
    private final DdaLineRenderer renderer = new DdaLineRenderer();
    private Workload.Lines lines;

    @Override
    protected void prepare() {
        panel = canvas.panel();
        depthCued = canvas.depthCued(Rgb.WHITE, Rgb.BLACK);
        lines = Workload.randomLines();
    }

    @Benchmark
    @OperationsPerInvocation(Workload.LINES)
    public PageCanvas simpviewPanel() {
        draw(panel);
        return canvas;
    }

    @Benchmark
    @OperationsPerInvocation(Workload.LINES)
    public PageCanvas simpviewDepthCued() {
        draw(depthCued);
        return canvas;
    }

    private void draw(Drawable target) {
        Vertex[] v = lines.vertices;
        for (int i = 0; i < v.length; i += 2) {
            renderer.drawLine(v[i], v[i + 1], target);
        }
    }

    @Benchmark
    @OperationsPerInvocation(Workload.LINES)
    public BufferedImage java2d() {
        int[] c = lines.imageCoords;
        int n = lines.count();
        for (int l = 0; l < n; l++) {
            java2d.g.setColor(lines.colors[l]);
            java2d.g.drawLine(c[4 * l], c[4 * l + 1], c[4 * l + 2], c[4 * l + 3]);
        }
        return java2d.image;
    }
}
