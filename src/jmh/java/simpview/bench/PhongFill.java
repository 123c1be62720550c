package simpview.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.raster.FragmentLayout;
import simpview.raster.LitPolygonRasterizer;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.surface.BandQueue;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.RowBands;

/**
 * Lit fill rate: one quad (a fan of two triangles) covering the whole
 * 650x650 panel, phong-shaded by two point lights, through the lit pipeline's
 * rasterizer and fragment stage onto the page's panel and z-buffer. The quad
 * is a plane tilted away from the eye (camera-space depth 10 at the bottom,
 * 14 at the top) with normals that vary across it, surface (0.8, 0.6, 0.4),
 * ks 0.5, p 16, ambient 0.2. One op is one panel pixel, so ops/us is
 * Mpixels/s.
 *
 * <p>{@code depthTest=passes}: the z-buffer is reset to -infinity before each
 * invocation (outside the timing), so every pixel passes the z-test and is
 * lit. {@code rejects}: it is reset to +infinity, so the z-test rejects every
 * pixel and nothing is lit or written.
 *
 * <p>{@code threads}: the panel's bands are filled by that many threads at
 * once, each band with a rasterizer, fragment stage and shader of its own,
 * as a scene drawn by several threads fills them.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class PhongFill {

    private static final int CHANNELS = FragmentLayout.PHONG_CHANNELS;
    private static final int STRIDE = 3 + CHANNELS;

    private final PageCanvas canvas = new PageCanvas();
    private final double[] quad = new double[4 * STRIDE];
    /** Per band: its rasterizer and fragment stage. */
    private LitPolygonRasterizer[] rasterizers;
    private FragmentStage[] fragments;
    private DrawingThreads drawing;
    /** The quad as one batch in one slot (of two), drawn band by band. */
    private BandQueue queue;

    /** Threads filling the bands (1: the whole panel on the benchmark's thread). */
    @Param({"1"})
    public int threads;

    /** "passes": every pixel is nearer than the z-buffer and is lit; "rejects": none is. */
    @Param({"passes", "rejects"})
    public String depthTest;

    @Setup(Level.Trial)
    public void build() {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.setAmbient(0.2, 0.2, 0.2);
        state.setSurface(0.8, 0.6, 0.4, 0.5, 16);
        state.addLight(0, 0, 0, 1, 1, 1, 1, 0);
        state.addLight(-8, 6, -4, 0.8, 0.6, 0.5, 1, 0.01);
        drawing = DrawingThreads.of(threads);
        RowBands bands = drawing.bands(PageCanvas.PANEL);
        queue = drawing.queue(bands.count(), 2,
                (slot, b) -> rasterizers[b].fill(quad, 4, CHANNELS, PageCanvas.PANEL, PageCanvas.PANEL, fragments[b]));
        rasterizers = new LitPolygonRasterizer[bands.count()];
        fragments = new FragmentStage[bands.count()];
        for (int b = 0; b < bands.count(); b++) {
            rasterizers[b] = new LitPolygonRasterizer();
            fragments[b] = new FragmentStage(canvas.zbuffer(), canvas.panel());
            if (bands.count() > 1) {
                rasterizers[b].rows(bands.start(b), bands.end(b));
                fragments[b].rows(bands.start(b), bands.end(b));
            }
            fragments[b].phong(bands.count() > 1 ? state.frozenShader().get() : state, Fog.NONE);
        }
        // Corners a pixel outside the panel, unprojected to their depths.
        corner(0, -1, -1, 10, -0.2, -0.1);
        corner(1, 1, -1, 10, 0.2, -0.1);
        corner(2, 1, 1, 14, 0.2, 0.3);
        corner(3, -1, 1, 14, -0.2, 0.3);
    }

    /** Vertex i at window position (u, v) in [-1, 1] (a little beyond), depth d, normal (nx, ny, 1). */
    private void corner(int i, double u, double v, double d, double nx, double ny) {
        double reach = 1 + 2.0 / PageCanvas.PANEL;
        u *= reach;
        v *= reach;
        double q = 1 / d;
        double[] attributes = {-d, 0.8, 0.6, 0.4, u * d, v * d, nx, ny, 1};
        int at = i * STRIDE;
        quad[at] = (u + 1) / 2 * PageCanvas.PANEL;
        quad[at + 1] = (v + 1) / 2 * PageCanvas.PANEL;
        quad[at + 2] = q;
        for (int c = 0; c < CHANNELS; c++) {
            quad[at + 3 + c] = attributes[c] * q;
        }
    }

    /** Before each invocation, outside the timing: every pixel passes the z-test, or none does. */
    @Setup(Level.Invocation)
    public void resetDepth() {
        canvas.zbuffer().reset(depthTest.equals("passes") ? Double.NEGATIVE_INFINITY : Double.POSITIVE_INFINITY);
    }

    @Benchmark
    @OperationsPerInvocation(PageCanvas.PANEL * PageCanvas.PANEL)
    public PageCanvas fill() {
        queue.slot();
        queue.publish();
        queue.finish();
        return canvas;
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        drawing.close();
    }
}
