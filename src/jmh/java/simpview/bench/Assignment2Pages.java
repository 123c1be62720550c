package simpview.bench;

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
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.PageCanvas;
import simpview.surface.DrawingThreads;

/**
 * One whole page, as the window shows it: clear (image and z-buffer) and
 * draw. Pages 1 to 3 with the default seed; 4 and 5 from the project's
 * simp/ folder; 6 to 8 from the course folder, -Dsimpview.courseSimp. The
 * scene pages' files are read in the set-up and kept by the context's
 * {@code SceneLibrary} (as the window keeps them while they are unchanged),
 * so one op is the warm redraw. Sampled, so the summary can report the
 * median time.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class Assignment2Pages {

    @Param({"1", "2", "3", "4", "5", "6", "7", "8"})
    public int page;

    /** Threads drawing each page's bands (1: drawn as read, on the benchmark's thread; more: each batch drawn while the next is read). */
    @Param({"1"})
    public int threads;

    private PageRenderer renderer;
    private DrawingThreads drawing;
    private PageContext context;

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        drawing = DrawingThreads.of(threads);
        renderer = new PageRenderer(drawing);
        Path own = PageContext.PROJECT_SCENES;
        Path course = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        context = new PageContext(PageContext.DEFAULT_SEED, course, own, SceneMonitor.NONE);
        renderer.render(page, context); // fails the trial at once if the page cannot be drawn
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        drawing.close();
    }

    @Benchmark
    public PageCanvas clearAndDraw() throws SceneException {
        return renderer.render(page, context);
    }
}
