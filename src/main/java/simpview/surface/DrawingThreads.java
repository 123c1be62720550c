package simpview.surface;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;

/**
 * The threads that draw one picture's bands of rows together: the thread
 * that calls {@link #start} and {@code threads - 1} workers named
 * {@code simpview-band-1}, {@code simpview-band-2}, ... Made and closed by
 * whoever draws (a page renderer, a command, a benchmark) and handed to the
 * scene it draws; never shared through a global. One thread has no worker at
 * all: then everything is drawn on the caller's thread, as it always was.
 *
 * <p>Which thread draws which band does not matter to the picture: a band's
 * pixels are written by that band's drawer only, in drawing order.
 *
 * <p>Made by {@link #of}, every picture is drawn in bands by all the threads
 * (the count the user gave with {@code --threads}). Made by {@link #upTo}
 * (no count given), each recorded batch of a picture is drawn in bands or as
 * one band by one thread, as {@link BandChoice} finds it pays; the picture is
 * the same either way. A batch is started ({@link #start}) while the caller
 * goes on reading the next one, and finished by the caller, which takes the
 * bands no worker has begun.
 */
public final class DrawingThreads implements AutoCloseable {

    /**
     * Bands per thread: more bands than threads even out pages whose content
     * is not spread evenly, and shorten the wait at the end of a batch for
     * the last band; each band costs the row test of every primitive and the
     * set-up of each triangle that crosses into it. 8 measured faster than 3
     * on the course's lit pages on two threads (0.84 to 0.99 of the time)
     * and the same on A2's (docs/performance.md, session 4).
     */
    private static final int BANDS_PER_THREAD = 8;

    private final int threads;
    /** True when each batch's band count is chosen by {@link BandChoice}; false when every batch uses all threads. */
    private final boolean perPicture;
    /** The workers; null for one thread. */
    private final ExecutorService workers;
    /** Wall time from each start to the end of its finish, summed: the parallel part of drawing. */
    private long nanosInBands;
    /** Tasks given to {@link #start}, summed. */
    private long tasks;

    private DrawingThreads(int threads, boolean perPicture) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        }
        this.threads = threads;
        this.perPicture = perPicture && threads > 1;
        if (threads == 1) {
            workers = null;
            return;
        }
        AtomicInteger made = new AtomicInteger();
        workers = Executors.newFixedThreadPool(threads - 1, task -> {
            Thread t = new Thread(task, "simpview-band-" + made.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    /** Drawing every picture with {@code threads} threads (the caller's and threads - 1 workers): a count given. */
    public static DrawingThreads of(int threads) {
        return new DrawingThreads(threads, false);
    }

    /**
     * Drawing with at most {@code threads} threads: each recorded batch in
     * bands by all of them, or as one band by the caller alone, as
     * {@link BandChoice} finds it pays (no count given: the default).
     */
    public static DrawingThreads upTo(int threads) {
        return new DrawingThreads(threads, true);
    }

    /** The caller's thread alone. */
    public static DrawingThreads one() {
        return new DrawingThreads(1, false);
    }

    /** At most as many threads as the JVM sees processors, chosen per picture ({@link #upTo}). */
    public static DrawingThreads perProcessor() {
        return upTo(Runtime.getRuntime().availableProcessors());
    }

    public int threads() {
        return threads;
    }

    /** True when each batch's band count is chosen by {@link BandChoice} (made by {@link #upTo}, more than one thread). */
    public boolean choosesPerPicture() {
        return perPicture;
    }

    /** True when there is only the caller's thread: then scenes are drawn as they are read, unrecorded. */
    public boolean isOne() {
        return threads == 1;
    }

    /** The bands a picture of {@code rows} rows is split into for these threads. */
    public RowBands bands(int rows) {
        return new RowBands(rows, Math.max(1, Math.min(rows, threads * BANDS_PER_THREAD)));
    }

    /**
     * Starts {@code task} for each of 0, 1, ..., count - 1 on the workers and
     * returns at once, so that the caller can go on with other work (reading
     * the next batch of a scene) while they draw; {@link InFlight#finish} then
     * has the caller take the tasks no worker has begun, and returns when all
     * are done. With one thread every task is run here, before this returns.
     * At most one may be in flight at a time (finish it before the next start).
     */
    public InFlight start(int count, IntConsumer task) {
        tasks += count;
        InFlight run = new InFlight(count, task);
        if (workers == null) {
            run.drain();
            return run;
        }
        int helpers = Math.min(threads - 1, count);
        for (int k = 0; k < helpers; k++) {
            run.running.add(workers.submit(run::drain));
        }
        return run;
    }

    /**
     * The wall time from each {@link #start} to the end
     * of its finish, summed: how long some band was being drawn, against the
     * whole drawing's time (the rest, reading and the geometry stage while
     * nothing is drawn, runs on one thread alone). For benchmarks; read on the
     * thread that starts them.
     */
    public long nanosInBands() {
        return nanosInBands;
    }

    /** How many tasks (bands, or batches drawn whole) were run so far: for benchmarks and tests, as {@link #nanosInBands}. */
    public long tasks() {
        return tasks;
    }

    /** Tasks started by {@link #start}: the caller finishes them. */
    public final class InFlight {
        private final long started = System.nanoTime();
        private final int count;
        private final IntConsumer task;
        private final AtomicInteger next = new AtomicInteger();
        private final List<Future<?>> running = new ArrayList<>();
        private boolean finished;

        private InFlight(int count, IntConsumer task) {
            this.count = count;
            this.task = task;
        }

        private void drain() {
            for (int i = next.getAndIncrement(); i < count; i = next.getAndIncrement()) {
                task.accept(i);
            }
        }

        /**
         * Runs on this thread the tasks no worker has begun, waits for the
         * rest, and throws the first failure once all have stopped. Only the
         * thread that started them calls it; a second call does nothing.
         */
        public void finish() {
            if (finished) {
                return;
            }
            finished = true;
            try {
                awaitAll();
            } finally {
                nanosInBands += System.nanoTime() - started;
            }
        }

        private void awaitAll() {
            Throwable failure = null;
            try {
                drain();
            } catch (RuntimeException | Error e) {
                next.set(count); // the others stop after the task at hand
                failure = e;
            }
            // Every worker is waited for, even when interrupted: none may still be drawing when this returns.
            boolean interrupted = false;
            for (Future<?> f : running) {
                while (true) {
                    try {
                        f.get();
                        break;
                    } catch (ExecutionException e) {
                        failure = failure == null ? e.getCause() : failure;
                        break;
                    } catch (CancellationException e) {
                        failure = failure == null ? e : failure; // closed while drawing
                        break;
                    } catch (InterruptedException e) {
                        interrupted = true;
                    }
                }
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
            if (failure instanceof RuntimeException r) {
                throw r;
            }
            if (failure instanceof Error e) {
                throw e;
            }
            if (failure != null) {
                throw new IllegalStateException(failure);
            }
        }
    }

    /** Stops the workers (they finish nothing new); the caller's thread is untouched. */
    @Override
    public void close() {
        if (workers != null) {
            workers.shutdownNow();
        }
    }
}
