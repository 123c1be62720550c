package simpview.bench;

import java.awt.image.BufferedImage;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import simpview.compare.Comparison;
import simpview.compare.Flip;
import simpview.compare.Picture;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * One comparison of a page's 650x650 panel with a picture of it, by each
 * metric: simpview's page 3 (seed 361) against the same page drawn with
 * another seed, so most pixels differ (the worst case for every metric;
 * FLIP skips the colour work of pixels whose filtered colours are the same).
 * {@code flipPage} is FLIP alone on the two whole 750x750 pages (it does not
 * depend on the metric parameter: run it with {@code -p metric=FLIP}).
 * Single-threaded, as each of a batch's comparisons is.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Benchmark)
public class Metrics {

    @Param({"EXACT", "BLUR", "FLIP"})
    public String metric;

    private int[] ours;
    private int[] theirs;
    private int[] ourPage;
    private int[] theirPage;

    @Setup
    public void draw() throws Exception {
        BufferedImage pa = new PageRenderer().renderImage(3, PageContext.defaults().withSeed(361));
        BufferedImage pb = new PageRenderer().renderImage(3, PageContext.defaults().withSeed(7));
        ours = Picture.ofPage(pa, "ours").panel();
        theirs = Picture.ofPage(pb, "theirs").panel();
        ourPage = pa.getRGB(0, 0, 750, 750, null, 0, 750);
        theirPage = pb.getRGB(0, 0, 750, 750, null, 0, 750);
        for (int i = 0; i < ourPage.length; i++) {
            ourPage[i] &= 0xFFFFFF;
            theirPage[i] &= 0xFFFFFF;
        }
    }

    @Benchmark
    public Comparison compare() {
        return Comparison.of(ours, theirs, 1, Comparison.Metric.valueOf(metric));
    }

    @Benchmark
    public float[] flipPage() {
        return Flip.of(ourPage, theirPage, 750, 750);
    }
}
