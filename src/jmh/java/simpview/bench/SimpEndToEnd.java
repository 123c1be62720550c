package simpview.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * End to end: a generated SIMP file of 1,000,000 polygons read, interpreted
 * and drawn depth-cued onto a cleared page, in a JVM limited to 64 MB of heap
 * (the file is about 60 MB, so it must be streamed). One op is one line of
 * the file: the score is SIMP lines/s.
 *
 * <p>The file: 1,000 groups, each {@code {}, a translate, a rotate, 1,000
 * polygons and {@code }}, so 1,004,000 lines. Polygons are small (about 2
 * world units, 6 px) at random places and depths, numbers written with
 * three decimals, commas and spaces as the course's files write them.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 3, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx64m")
public class SimpEndToEnd {

    static final int GROUPS = 1_000;
    static final int POLYGONS_PER_GROUP = 1_000;
    static final int LINES = GROUPS * (POLYGONS_PER_GROUP + 4);

    private Path dir;
    private Path file;
    private final PageCanvas canvas = new PageCanvas();

    @Setup(Level.Trial)
    public void setUp() throws IOException {
        dir = Files.createTempDirectory("simpview-bench");
        file = dir.resolve("million.simp");
        write(file);
    }

    @TearDown(Level.Trial)
    public void tearDown() throws IOException {
        Files.deleteIfExists(file);
        Files.deleteIfExists(dir);
    }

    @Benchmark
    @OperationsPerInvocation(LINES)
    public PageCanvas readInterpretDraw() throws SceneException {
        canvas.clear();
        ScenePipeline.drawDepthCued(file, canvas.depthCued(Rgb.WHITE, Rgb.BLACK), SceneMonitor.NONE);
        return canvas;
    }

    static void write(Path file) throws IOException {
        Random random = new Random(1);
        StringBuilder line = new StringBuilder(96);
        try (BufferedWriter out = Files.newBufferedWriter(file, StandardCharsets.US_ASCII)) {
            for (int g = 0; g < GROUPS; g++) {
                out.write("{\n");
                line.setLength(0);
                line.append("translate ");
                number(line, random.nextDouble() * 20 - 10).append(", ");
                number(line, random.nextDouble() * 20 - 10).append(", 0\n");
                line.append("rotate Z ");
                number(line, random.nextDouble() * 360).append('\n');
                out.append(line);
                for (int p = 0; p < POLYGONS_PER_GROUP; p++) {
                    double cx = random.nextDouble() * 180 - 90;
                    double cy = random.nextDouble() * 180 - 90;
                    double cz = -2 - random.nextDouble() * 196;
                    line.setLength(0);
                    line.append("polygon");
                    for (int k = 0; k < 3; k++) {
                        line.append(" (");
                        number(line, cx + random.nextDouble() * 2 - 1).append(", ");
                        number(line, cy + random.nextDouble() * 2 - 1).append(", ");
                        number(line, cz + random.nextDouble() * 2 - 1).append(')');
                    }
                    out.append(line.append('\n'));
                }
                out.write("}\n");
            }
        }
    }

    /** Appends v with exactly three decimals, e.g. -12.345, without String.format's cost. */
    private static StringBuilder number(StringBuilder sb, double v) {
        long thousandths = Math.round(v * 1000);
        if (thousandths < 0) {
            sb.append('-');
            thousandths = -thousandths;
        }
        sb.append(thousandths / 1000).append('.');
        long frac = thousandths % 1000;
        if (frac < 100) {
            sb.append('0');
        }
        if (frac < 10) {
            sb.append('0');
        }
        return sb.append(frac);
    }
}
