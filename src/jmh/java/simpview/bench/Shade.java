package simpview.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import simpview.shading.Fog;
import simpview.shading.Lighting;
import simpview.shading.Lights;
import simpview.shading.LitPoints;

/**
 * One phong pixel's lighting: {@link Lighting#shade} with two lights (one in
 * front, one off to the side), perspective view, at the points of a 64 x 64
 * patch in raster order, as phong shading meets them: P across a tilted
 * square 100 to 150 units in front of the eye, N and kd varying smoothly. Each shaded
 * colour is fogged and summed, so none of the work can be dropped. One op is
 * one point lit; the score is ns per point. {@code exponent} is the surface's
 * p: 8 and 128 take the repeated-squaring path, 7.5 Math.pow.
 * {@link #shade} lights one point per call, as gouraud vertices are lit;
 * {@link #shadeBatch} the same points 64 at a time, as phong spans are
 * ({@link Lighting#shade(LitPoints)}), filled in the set-up.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class Shade {

    private static final int SIDE = 64;
    private static final int POINTS = SIDE * SIDE;

    @Param({"8", "128", "7.5"})
    public double exponent;

    private final double[] points = new double[9 * POINTS];
    private final double[] colour = new double[3];
    private static final int BATCH = 64;

    private Lighting lighting;
    private final LitPoints[] batches = new LitPoints[POINTS / BATCH];
    private final Fog fog = new Fog(-100, -200, 0, 0, 0);

    @Setup
    public void build() {
        Lights lights = new Lights();
        lights.add(0, 0, 0, 1, 1, 1, 1, 0);
        lights.add(-80, 60, -60, 0.8, 0.6, 0.5, 1, 0.01);
        lighting = new Lighting(lights);
        lighting.prepare(0.1, 0.1, 0.1, 0.8, exponent, 2, true);
        // A 64 x 64 patch in raster order, as a span walks it: P on a tilted square, N and kd
        // varying smoothly across it (N not unit length, as interpolated normals are).
        for (int i = 0; i < POINTS; i++) {
            int at = 9 * i;
            double u = (i % SIDE) / (SIDE / 2.0) - 1;
            double v = (i / SIDE) / (SIDE / 2.0) - 1;
            points[at] = 50 * u;
            points[at + 1] = 50 * v;
            points[at + 2] = -125 + 25 * v;
            points[at + 3] = 0.3 * u;
            points[at + 4] = 0.5 + 0.2 * v;
            points[at + 5] = 1.5 + 0.1 * u * v;
            points[at + 6] = 0.5 + 0.5 * u;
            points[at + 7] = 0.5 + 0.5 * v;
            points[at + 8] = 0.5;
        }
        for (int k = 0; k < batches.length; k++) {
            batches[k] = new LitPoints(BATCH);
            for (int i = k * BATCH; i < (k + 1) * BATCH; i++) {
                int at = 9 * i;
                batches[k].add(points[at], points[at + 1], points[at + 2], points[at + 3], points[at + 4],
                        points[at + 5], points[at + 6], points[at + 7], points[at + 8]);
            }
        }
    }

    @Benchmark
    @OperationsPerInvocation(POINTS)
    public double shade() {
        double sum = 0;
        double[] p = points;
        double[] c = colour;
        for (int at = 0; at < p.length; at += 9) {
            lighting.shade(p[at], p[at + 1], p[at + 2], p[at + 3], p[at + 4], p[at + 5],
                    p[at + 6], p[at + 7], p[at + 8], c, 0);
            fog.apply(p[at + 2], c, 0);
            sum += c[0] + c[1] + c[2];
        }
        return sum;
    }

    @Benchmark
    @OperationsPerInvocation(POINTS)
    public double shadeBatch() {
        double sum = 0;
        double[] p = points;
        double[] c = colour;
        for (int k = 0; k < batches.length; k++) {
            LitPoints batch = batches[k];
            lighting.shade(batch);
            for (int i = 0; i < BATCH; i++) {
                c[0] = batch.red(i);
                c[1] = batch.green(i);
                c[2] = batch.blue(i);
                fog.apply(p[9 * (k * BATCH + i) + 2], c, 0);
                sum += c[0] + c[1] + c[2];
            }
        }
        return sum;
    }
}
