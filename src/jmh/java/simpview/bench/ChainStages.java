package simpview.bench;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import simpview.geometry.Camera;
import simpview.geometry.Vertex;
import simpview.pages.PageContext;
import simpview.pages.Assignment2;
import simpview.raster.FilledPolygonRenderer;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DepthCueDrawable;
import simpview.surface.Drawable;
import simpview.surface.ImageDrawable;
import simpview.surface.PageCanvas;
import simpview.surface.PanelDrawable;
import simpview.surface.Rgb;
import simpview.surface.ScissorDrawable;
import simpview.surface.Span;
import simpview.surface.ZBuffer;
import simpview.surface.ZBufferDrawable;

/**
 * Where the time goes: the small-triangle mesh, or page 5's or page 7's
 * scene, drawn through the SIMP pages' chain (scissor, z-buffer, depth cue,
 * panel, image) cut after one stage, the rest replaced by a sink that takes
 * each span (and each line pixel) and does nothing with it. One stage's time
 * minus the one before is what that stage costs. The sink says it needs no
 * colour, as the depth cue does, so the renderer does the same work at every
 * cut. One op is one drawing of the whole mesh or scene; the z-buffer is
 * reset before each, outside the timing.
 *
 * <p>Not part of the default {@code gradle jmh}, which it would make 2.5
 * minutes longer: run it with {@code gradle jmh -PjmhArgs=ChainStages}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@Fork(1)
public class ChainStages {

    /** The mesh of SmallTriangles, page 5 (the project's, amber depth cue) or page 7 (the course's, white). */
    @Param({"mesh", "page5", "page7"})
    public String scene;

    @Param({"renderer", "scissor", "zbuffer", "depthcue", "panel", "image"})
    public String stage;

    private final ZBuffer zbuffer = new ZBuffer(PageCanvas.PANEL, PageCanvas.PANEL);
    private final BufferedImage surface = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);
    private final FilledPolygonRenderer renderer = new FilledPolygonRenderer();
    private Drawable chain;
    private double[] mesh;
    private Path file;

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        switch (scene) {
            case "mesh" -> mesh = Workload.mesh().numbers;
            case "page5" -> file = PageContext.PROJECT_SCENES.resolve("page5.simp");
            case "page7" -> file = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"), "page7.simp");
            default -> throw new IllegalArgumentException("no scene " + scene);
        }
        chain = cutAfter(stage, scene.equals("page5") ? Assignment2.PAGE5_NEAR : Rgb.WHITE);
        draw(); // fails the trial at once if the scene cannot be drawn
    }

    private Drawable cutAfter(String last, Rgb near) {
        Drawable image = last.equals("image") ? new ImageDrawable(surface) : new Sink(PageCanvas.SIZE);
        Drawable panel = last.equals("panel") || last.equals("image")
                ? new PanelDrawable(image, PageCanvas.MARGIN, PageCanvas.MARGIN, PageCanvas.PANEL)
                : new Sink(PageCanvas.PANEL);
        Drawable cue = switch (last) {
            case "renderer", "scissor", "zbuffer" -> new Sink(PageCanvas.PANEL);
            default -> new DepthCueDrawable(near, Rgb.BLACK, Camera.PARALLEL, panel);
        };
        Drawable depth = last.equals("renderer") || last.equals("scissor") ? cue : new ZBufferDrawable(zbuffer, cue);
        return last.equals("renderer") ? depth : new ScissorDrawable(Camera.PARALLEL, depth);
    }

    @Setup(Level.Invocation)
    public void resetDepth() {
        zbuffer.reset(-200);
    }

    @Benchmark
    public Drawable draw() throws SceneException {
        if (mesh != null) {
            double[] p = mesh;
            for (int at = 0; at < p.length; at += 3 * Vertex.NUMBERS) {
                renderer.drawPolygon(p, at, chain);
            }
        } else {
            ScenePipeline.drawDepthCued(file, chain, SceneMonitor.NONE);
        }
        return chain;
    }

    /** Takes spans and pixels and drops them; needs no colour. */
    private static final class Sink implements Drawable {

        private final int size;

        Sink(int size) {
            this.size = size;
        }

        @Override
        public int width() {
            return size;
        }

        @Override
        public int height() {
            return size;
        }

        @Override
        public boolean usesColour() {
            return false;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            // dropped
        }

        @Override
        public int getPixel(int x, int y) {
            return 0;
        }

        @Override
        public void fillSpan(Span span) {
            // dropped
        }
    }
}
