package simpview.bench;

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
import simpview.inspect.PixelInspector;
import simpview.inspect.PixelReport;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;

/**
 * One pixel's history (@Param scene, "a4/page-d" or "a3/pageI", from the
 * course's folders beside -Dsimpview.courseSimp), replay included: the whole
 * scene drawn again with the one-pixel filter, every write at the pixel
 * recorded and explained ({@code history}); the same without the
 * explanations ({@code historyOnly}: what explaining costs is the
 * difference); and the page's own warm redraw ({@code draw}, as LitPages
 * draws it) in the same run, for the ratio. The pixel is the drawn pixel
 * nearest the panel's centre, the one most writes reach. Models parsed in
 * the set-up, as the program keeps them. Sampled, in ms.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class PixelHistory {

    @Param({"a4/page-d", "a3/pageI"})
    public String scene;

    private final SceneLibrary library = new SceneLibrary();
    private final PageCanvas canvas = new PageCanvas();
    private PixelInspector inspector;
    private PixelInspector historyOnly;
    private InspectedScene inspected;
    private Path file;
    private int x;
    private int y;

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        Path courseSimp = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        file = LitPages.sceneFile(courseSimp.toAbsolutePath().getParent(), scene);
        if (!Files.isRegularFile(file)) {
            throw new IllegalStateException("no " + file + ": the course's files belong beside the project");
        }
        inspector = new PixelInspector(library, SceneMonitor.NONE);
        historyOnly = new PixelInspector(library, SceneMonitor.NONE).explaining(false);
        inspected = InspectedScene.of(file);
        draw();
        // The drawn pixel with the most writes near the centre: rings outwards from it.
        int best = -1;
        for (int r = 0; r < 325 && best < 0; r += 5) {
            for (int dy = -r; dy <= r && best < 0; dy += 5) {
                for (int dx = -r; dx <= r; dx += 5) {
                    int px = 325 + dx;
                    int py = 325 + dy;
                    if ((canvas.panel().getPixel(px, py) & 0xFFFFFF) != 0) {
                        x = px;
                        y = py;
                        best = 1;
                        break;
                    }
                }
            }
        }
        if (best < 0) {
            throw new IllegalStateException(scene + " drew nothing");
        }
        PixelReport report = history();
        if (report.lastWritten() == null) {
            throw new IllegalStateException("the history of (" + x + ", " + y + ") has no written entry");
        }
        System.out.println(scene + ": pixel (" + x + ", " + y + "), " + report.history().size() + " writes");
    }

    @Benchmark
    public PixelReport history() throws SceneException {
        return inspector.inspect(inspected, x, y);
    }

    @Benchmark
    public PixelReport historyOnly() throws SceneException {
        return historyOnly.inspect(inspected, x, y);
    }

    @Benchmark
    public PageCanvas draw() throws SceneException {
        canvas.clear();
        ScenePipeline.draw(file, canvas, ScenePipeline.Options.byCommands(library), SceneMonitor.NONE);
        return canvas;
    }
}
