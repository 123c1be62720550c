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
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import simpview.scene.SceneException;
import simpview.stage.ObjFace;
import simpview.scene.obj.ObjModel;
import simpview.scene.obj.ObjReader;
import simpview.scene.obj.ObjSink;

/**
 * The course's dummy.obj (2.2 MB: 14,652 vertices, 16,119 normals, 16,026
 * faces), from course-simp-a3 beside -Dsimpview.courseSimp: streamed to a
 * sink that reads every vertex of every face (target: at most 15 ms warm),
 * read into a kept model, and that model replayed. Sampled, in ms.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class ObjParse {

    private Path dummy;
    private ObjModel model;
    private final Sum sum = new Sum();

    /** Touches what a drawing sink reads: every position and normal. */
    static final class Sum implements ObjSink {
        double total;

        @Override
        public void face(ObjFace face) {
            double t = 0;
            for (int k = 0; k < face.size(); k++) {
                t += face.x(k) + face.y(k) + face.z(k);
                if (face.hasNormal(k)) {
                    t += face.nx(k);
                }
            }
            total += t;
        }
    }

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        Path courseSimp = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        dummy = courseSimp.resolveSibling("course-simp-a3").resolve("dummy.obj");
        if (!Files.isRegularFile(dummy)) {
            throw new IllegalStateException("no " + dummy + ": the course's files belong beside the project");
        }
        model = ObjModel.read(dummy);
    }

    @Benchmark
    public double streamDummy() throws SceneException {
        sum.total = 0;
        ObjReader.stream(dummy, sum);
        return sum.total;
    }

    @Benchmark
    public ObjModel readDummyModel() throws SceneException {
        return ObjModel.read(dummy);
    }

    @Benchmark
    public double replayDummy() throws SceneException {
        sum.total = 0;
        model.replay(sum);
        return sum.total;
    }
}
