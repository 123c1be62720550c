package simpview.bench;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import simpview.scene.simp.SceneLibrary;
import simpview.surface.BandWatch;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * Where a lit page's time goes on two threads, picture by picture: the page
 * is redrawn until warm ({@link #WARM_NANOS}, then {@link #WATCHED_WARM_NANOS}
 * watched), then {@link #PICTURES} redraws are watched ({@link BandWatch}),
 * and the table gives the median over them of each picture's time, its
 * batches, and of each thread the time it spent drawing bands and parked:
 * medians, because now and then a picture is drawn by one thread alone
 * while the other does not get a core (on this 2-core host, a few in 20).
 * The reading thread's "other" is the rest of its time: reading the scene,
 * the geometry stage, recording, and spinning before it parks. A worker's
 * time neither drawing nor parked is spent spinning. The "end wait" is the
 * time between the two threads' last bands' ends: how long one waited for
 * the other at the picture's end. The watch's own calls
 * (a lock and a clock read each) make a picture a little slower than the
 * benchmarks do.
 *
 * <p>Run: {@code java -cp <jmh runtime classpath> simpview.bench.BandTimeline DIR scene...},
 * DIR the folder holding course-simp-a3 and course-simp-a4, a scene as
 * "a4/page-g". Not a JMH benchmark: a measurement of where the time goes.
 */
public final class BandTimeline {

    /** How long each page is redrawn before the redraws watched, for C2 to compile the two-thread path. */
    private static final long WARM_NANOS = 3_000_000_000L;

    /** How long each page is then redrawn watched, before the redraws that count. */
    private static final long WATCHED_WARM_NANOS = 1_000_000_000L;

    /** Redraws watched per page, of which the medians are shown. */
    private static final int PICTURES = 21;

    private BandTimeline() {
    }

    public static void main(String[] args) throws Exception {
        Path folder = Path.of(args[0]);
        System.out.println("| page | picture | batches | reading thread: drawing | parked | other "
                + "| worker: drawing | parked | end wait |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
        for (int i = 1; i < args.length; i++) {
            Path file = LitPages.sceneFile(folder, args[i]);
            SceneLibrary library = new SceneLibrary();
            try (DrawingThreads two = DrawingThreads.of(2)) {
                PageCanvas canvas = new PageCanvas();
                canvas.drawWith(two);
                // The first page three times as long: C2 still compiles the whole pipeline beside it.
                long warm = i == 1 ? 3 * WARM_NANOS : WARM_NANOS;
                for (long warmUntil = System.nanoTime() + warm; System.nanoTime() - warmUntil < 0;) {
                    LitPages.redraw(canvas, file, library);
                }
                Timeline timeline = new Timeline(Thread.currentThread());
                two.watchedBy(timeline);
                for (long warmUntil = System.nanoTime() + WATCHED_WARM_NANOS; System.nanoTime() - warmUntil < 0;) {
                    LitPages.redraw(canvas, file, library); // the watch's calls compiled too
                }
                long[][] columns = new long[8][PICTURES];
                for (int p = 0; p < PICTURES; p++) {
                    timeline.clear();
                    long start = System.nanoTime();
                    LitPages.redraw(canvas, file, library);
                    long picture = System.nanoTime() - start;
                    columns[0][p] = picture;
                    columns[1][p] = timeline.batches;
                    columns[2][p] = timeline.drawing[0];
                    columns[3][p] = timeline.parked[0];
                    columns[4][p] = picture - timeline.drawing[0] - timeline.parked[0];
                    columns[5][p] = timeline.drawing[1];
                    columns[6][p] = timeline.parked[1];
                    columns[7][p] = Math.abs(timeline.lastDrawn[0] - timeline.lastDrawn[1]);
                }
                two.watchedBy(null);
                StringBuilder row = new StringBuilder("| ").append(args[i]);
                for (int c = 0; c < columns.length; c++) {
                    Arrays.sort(columns[c]);
                    long median = columns[c][PICTURES / 2];
                    row.append(" | ").append(c == 1 ? Long.toString(median) // batches; the rest in ns, shown in us
                            : String.format(Locale.ROOT, "%.0f", median / 1e3));
                }
                System.out.println(row.append(" |"));
            }
        }
    }

    /**
     * The watch: each thread's time drawing and parked in the picture, summed
     * as the calls come (thread 0 the reading thread, 1 every worker).
     */
    private static final class Timeline implements BandWatch {
        private final Thread reader;
        private final long[] drawing = new long[2];
        private final long[] parked = new long[2];
        private final long[] drawingSince = new long[2];
        private final long[] parkedSince = new long[2];
        /** When each thread last ended a band. */
        private final long[] lastDrawn = new long[2];
        private int batches;

        Timeline(Thread reader) {
            this.reader = reader;
        }

        synchronized void clear() {
            Arrays.fill(drawing, 0);
            Arrays.fill(parked, 0);
            Arrays.fill(lastDrawn, System.nanoTime());
            batches = 0;
        }

        private int thread() {
            return Thread.currentThread() == reader ? 0 : 1;
        }

        @Override
        public synchronized void handedIn(int batch) {
            batches++;
        }

        @Override
        public synchronized void drawing(int batch, int band) {
            drawingSince[thread()] = System.nanoTime();
        }

        @Override
        public synchronized void drawn(int batch, int band) {
            int t = thread();
            long now = System.nanoTime();
            drawing[t] += now - drawingSince[t];
            lastDrawn[t] = now;
        }

        @Override
        public synchronized void parked() {
            parkedSince[thread()] = System.nanoTime();
        }

        @Override
        public synchronized void woken() {
            int t = thread();
            parked[t] += System.nanoTime() - parkedSince[t];
        }
    }
}
