package simpview.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.Locale;
import simpview.scene.simp.SceneLibrary;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * The serial share of a lit page drawn by two threads, measured rather than
 * inferred: the same page redrawn on one thread (as read, nothing recorded)
 * and on two, alternating, in one process, once both are warm
 * ({@link #WARM_NANOS}); the best of many redraws of each, to see past a
 * shared host. Of a two-thread redraw, the time outside
 * the bands ({@link DrawingThreads#nanosInBands}) is what one thread does
 * alone: reading, the geometry stage, recording. Its share of the
 * one-thread time is Amdahl's s, and 1 / (s + (1 - s) / n) its prediction
 * for n cores (an upper bound: it assumes bands of equal work). The CPU
 * time of both ways (this thread's and the band helpers', over the second
 * half of the redraws) shows what drawing in bands costs beside the one-thread
 * path, apart from the host's load.
 *
 * <p>Run: {@code java -cp <jmh runtime classpath> simpview.bench.SerialShare DIR scene...},
 * DIR the folder holding course-simp-a3 and course-simp-a4, a scene as
 * "a3/pageF". Not a JMH benchmark: a measurement of where the time goes.
 */
public final class SerialShare {

    /**
     * How long each page is redrawn both ways, alternating, before the
     * redraws that count: 80 redraws of a 2 ms page are 0.3 s, before C2 has
     * compiled the two-thread path, and A4 page-g's best came out at 1.01x
     * where warm redraws give 1.76x (session 16). 8 s, as {@link LitPages}
     * warms (its pages settle after 5-9 s on two threads); in session 45,
     * on a noisy host, 3 s and 8 s gave figures within its noise of each
     * other.
     */
    private static final long WARM_NANOS = 8_000_000_000L;

    private SerialShare() {
    }

    public static void main(String[] args) throws Exception {
        Path folder = Path.of(args[0]);
        int rounds = 80;
        System.out.println("| page | 1 thread, best | 2 threads, best | speed-up | serial part | s | 8 cores | 16 cores "
                + "| CPU per redraw, 1 thread | CPU per redraw, 2 threads (sum) |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        for (int i = 1; i < args.length; i++) {
            Path file = LitPages.sceneFile(folder, args[i]);
            SceneLibrary library = new SceneLibrary();
            try (DrawingThreads one = DrawingThreads.one(); DrawingThreads two = DrawingThreads.of(2)) {
                PageCanvas canvas = new PageCanvas();
                for (long warmUntil = System.nanoTime() + WARM_NANOS; System.nanoTime() - warmUntil < 0;) {
                    redraw(canvas, one, file, library);
                    redraw(canvas, two, file, library);
                }
                long bestOne = Long.MAX_VALUE;
                long bestTwo = Long.MAX_VALUE;
                long serialOfBest = 0;
                long cpuOne = 0;
                long cpuTwo = 0;
                for (int r = 0; r < rounds; r++) {
                    long cpu = cpu();
                    bestOne = Math.min(bestOne, redraw(canvas, one, file, library));
                    long between = cpu();
                    long before = two.nanosInBands();
                    long t = redraw(canvas, two, file, library);
                    long bands = two.nanosInBands() - before;
                    if (r >= rounds / 2) { // the second half
                        long after = cpu();
                        cpuOne += between - cpu;
                        cpuTwo += after - between;
                    }
                    if (t < bestTwo) {
                        bestTwo = t;
                        serialOfBest = t - bands;
                    }
                }
                double s = (double) serialOfBest / bestOne;
                System.out.println(String.format(Locale.ROOT,
                        "| %s | %.2f ms | %.2f ms | %.2fx | %.2f ms | %.2f | %.1fx | %.1fx | %.2f ms | %.2f ms |",
                        args[i], bestOne / 1e6, bestTwo / 1e6, (double) bestOne / bestTwo, serialOfBest / 1e6, s,
                        amdahl(s, 8), amdahl(s, 16), cpuOne / 1e6 / (rounds - rounds / 2),
                        cpuTwo / 1e6 / (rounds - rounds / 2)));
            }
        }
    }

    /** CPU time so far of this thread and of every band helper. */
    private static long cpu() {
        ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        long sum = bean.getCurrentThreadCpuTime();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().startsWith("simpview-band-")) {
                sum += Math.max(0, bean.getThreadCpuTime(t.getId()));
            }
        }
        return sum;
    }

    private static double amdahl(double s, int n) {
        return 1 / (s + (1 - s) / n);
    }

    private static long redraw(PageCanvas canvas, DrawingThreads threads, Path file, SceneLibrary library)
            throws Exception {
        canvas.drawWith(threads);
        long start = System.nanoTime();
        LitPages.redraw(canvas, file, library);
        return System.nanoTime() - start;
    }
}
