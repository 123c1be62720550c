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
import org.openjdk.jmh.annotations.Warmup;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;

/**
 * What the window's inspector costs: a page drawn as {@link Assignment2Pages} draws it
 * ("off": no record, no trace, the command line's drawing), and drawn with
 * the provenance decorator after the z-buffer and a {@link PrimitiveLog} of
 * every primitive's file, line and outline ("record"), as the window draws.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class Inspector {

    @Param({"7"})
    public int page;

    @Param({"off", "record"})
    public String inspector;

    private final PageRenderer renderer = new PageRenderer();
    private final Provenance provenance = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
    private PageContext context;
    private boolean record;

    /** The window's trace: a fresh log for every picture. */
    private final class Tracing implements SceneMonitor {
        private PrimitiveLog log;

        @Override
        public PrimitiveTrace trace() {
            return log;
        }
    }

    private final Tracing tracing = new Tracing();

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        Path own = PageContext.PROJECT_SCENES;
        Path course = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        record = inspector.equals("record");
        context = new PageContext(PageContext.DEFAULT_SEED, course, own, record ? tracing : SceneMonitor.NONE);
        renderer.canvas().recordProvenance(record ? provenance : null);
        clearAndDraw(); // fails the trial at once if the page cannot be drawn
    }

    @Benchmark
    public PageCanvas clearAndDraw() throws SceneException {
        if (record) {
            tracing.log = new PrimitiveLog(provenance, -1);
        }
        return renderer.render(page, context);
    }
}
