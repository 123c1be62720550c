package simpview.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.AuxCounters;
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
import org.openjdk.jmh.infra.Blackhole;
import simpview.scene.SceneException;

/**
 * Each overlay's cost as a share of the page's own drawing, the two timed
 * in turn inside one invocation (their order swapped every time), so a
 * machine shared with others slows both alike: the aux counters
 * {@code pageNanos} and {@code overlayNanos} are the two sums over an
 * iteration, and their ratio is the overlay's cost in pages. The drawing
 * and the overlays are {@link Overlays}'s.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class OverlayShare {

    @Param({"a4/page-d", "a3/pageI", "a2/page7"})
    public String scene;

    @Param({"overdraw", "failures", "backFaces", "depth"})
    public String overlay;

    private final Overlays overlays = new Overlays();
    private boolean pageFirst;

    /** The two sums of one iteration, in ns. */
    @State(Scope.Thread)
    @AuxCounters(AuxCounters.Type.EVENTS)
    public static class Split {
        public long pageNanos;
        public long overlayNanos;

        @Setup(Level.Iteration)
        public void clear() {
            pageNanos = 0;
            overlayNanos = 0;
        }
    }

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        overlays.scene = scene;
        overlays.setUp();
    }

    @Benchmark
    public void pageAndOverlay(Split split, Blackhole sink) throws SceneException {
        pageFirst = !pageFirst;
        if (pageFirst) {
            long t0 = System.nanoTime();
            sink.consume(overlays.draw());
            long t1 = System.nanoTime();
            sink.consume(overlay());
            long t2 = System.nanoTime();
            split.pageNanos += t1 - t0;
            split.overlayNanos += t2 - t1;
        } else {
            long t0 = System.nanoTime();
            sink.consume(overlay());
            long t1 = System.nanoTime();
            sink.consume(overlays.draw());
            long t2 = System.nanoTime();
            split.overlayNanos += t1 - t0;
            split.pageNanos += t2 - t1;
        }
    }

    private Object overlay() throws SceneException {
        return switch (overlay) {
            case "overdraw" -> overlays.overdraw();
            case "failures" -> overlays.failures();
            case "backFaces" -> overlays.backFaces();
            case "depth" -> overlays.depth();
            default -> throw new IllegalArgumentException(overlay);
        };
    }
}
