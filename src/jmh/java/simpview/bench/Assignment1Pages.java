package simpview.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;

/**
 * One of the first assignment's five pages, whole: its layout painted and its
 * four panels drawn, on a reused canvas, as the window redraws it. The
 * target is at most 1 ms a page (issue 23). Sampled, for the median.
 * {@link #drawBefore} draws the same page the way it was drawn before it was
 * made fast ({@link A1Before}), so that one run gives the ratio.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class Assignment1Pages {

    @Param({"1", "2", "3", "4", "5"})
    public int page;

    private final PageCanvas canvas = new PageCanvas();
    private final PageContext context = PageContext.defaults();

    @Benchmark
    public PageCanvas draw() throws SceneException {
        Assignment1.page(page).draw(canvas, context);
        return canvas;
    }

    @Benchmark
    public PageCanvas drawBefore() {
        A1Before.draw(page, canvas, context);
        return canvas;
    }
}
