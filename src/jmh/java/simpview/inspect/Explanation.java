package simpview.inspect;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.shading.Fog;
import simpview.shading.LitState;
import simpview.surface.ZBuffer;

/**
 * The explanation of one phong fragment, as the inspector makes it for each
 * write at its pixel: the lighting's terms for three lights, the scene's own
 * lighting of the point, the fog and the bytes, into a fresh set of terms;
 * and the explanation printed as JSON. In the inspector's package (the
 * explainer is its own), run with the others. Average time, in µs.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class Explanation {

    private final LitState state = new LitState();
    private final LitExplainer explainer;
    private final PixelWatch watch;
    private final double[] fragment = {-40, 0.8, 0.5, 0.3, 1.5, -2.5, 0.1, 0.2, 0.97};

    public Explanation() {
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -1, -200), Matrix4.identity());
        state.setAmbient(0.1, 0.2, 0.15);
        state.setSurface(0.8, 0.5, 0.3, 0.6, 12);
        state.addLight(20, 30, -10, 1, 0.9, 0.8, 1, 0.01);
        state.addLight(-5, -40, -90, 0.5, 0.5, 1, 0.5, 0.02);
        state.addLight(0, 0, 0, 0.3, 0.3, 0.3, 1, 0);
        state.setFog(new Fog(-20, -60, 0.1, 0.1, 0.3));
        explainer = new LitExplainer(state);
        watch = new PixelWatch(325, 325, new ZBuffer(650, 650));
        watch.begin(List::of, state, null);
    }

    @Benchmark
    public Terms explain() {
        Terms terms = new Terms();
        explainer.colour(watch, fragment[0], fragment, 0, false, terms);
        return terms;
    }

    @Benchmark
    public String explainAsJson() {
        StringBuilder sb = new StringBuilder();
        explain().appendJson(sb);
        return sb.toString();
    }
}
