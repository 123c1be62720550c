package simpview.bench;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
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
import simpview.inspect.InspectedScene;
import simpview.inspect.Overdraw;
import simpview.inspect.SkippedPrimitives;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.window.LineKeepingDownscale;

/**
 * What the window's overlays cost against the page's own drawing (issue 20:
 * each at most twice): the scene drawn ("draw"), the overdraw counts (V,
 * a replay with counting decorators), the culled and clipped-away outlines
 * (U, a replay that writes no pixel), and the picture made smaller than 1:1
 * with its lines kept (the view below 1:1, at 650/750 of its size and at
 * 400/750).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class Overlays {

    /** A course scene: its assignment and name ("a4/page-d"), beside -Dsimpview.courseSimp. */
    @Param({"a4/page-d"})
    public String scene;

    private final ObjLibrary models = new ObjLibrary();
    private final PageCanvas canvas = new PageCanvas();
    private InspectedScene inspected;
    private Path file;
    private BufferedImage page;

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        Path courseSimp = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        String[] parts = scene.split("/");
        file = courseSimp.resolveSibling("course-simp-" + parts[0]).resolve(parts[1] + ".simp");
        if (!Files.isRegularFile(file)) {
            throw new IllegalStateException("no " + file + ": the course's files belong beside the project");
        }
        inspected = InspectedScene.of(file);
        draw();
        page = canvas.snapshot();
    }

    @Benchmark
    public PageCanvas draw() throws SceneException {
        canvas.clear();
        ScenePipeline.draw(file, canvas, ScenePipeline.Options.byCommands(models), SceneMonitor.NONE);
        return canvas;
    }

    @Benchmark
    public Overdraw.Counts overdraw() throws SceneException {
        return Overdraw.counts(inspected, models);
    }

    @Benchmark
    public SkippedPrimitives.Found culledAndClipped() throws SceneException {
        return SkippedPrimitives.of(inspected, models);
    }

    @Benchmark
    public BufferedImage downscaleTo650() {
        return LineKeepingDownscale.of(page, 650.0 / 750);
    }

    @Benchmark
    public BufferedImage downscaleTo400() {
        return LineKeepingDownscale.of(page, 400.0 / 750);
    }
}
