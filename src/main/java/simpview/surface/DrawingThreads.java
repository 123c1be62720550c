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
 * that calls {@link #forEach} and {@code threads - 1} workers named
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
 * one band on the caller's thread, as {@link BandChoice} finds it pays; the
 * picture is the same either way.
 */
public final class DrawingThreads implements AutoCloseable {

    /** Bands per thread: more bands than threads even out pages whose content is not spread evenly. */
    private static final int BANDS_PER_THREAD = 3;

    private final int threads;
    /** True when each batch's band count is chosen by {@link BandChoice}; false when every batch uses all threads. */
    private final boolean perPicture;
    /** The workers; null for one thread. */
    private final ExecutorService workers;
    /** Wall time the callers of forEach spent in it, summed: the parallel part of drawing. */
    private long nanosInBands;

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
     * Runs {@code task} once for each of 0, 1, ..., count - 1, spread over
     * the threads (the caller's included), and returns when every one is
     * done. The first failure is thrown on, once all have stopped.
     */
    public void forEach(int count, IntConsumer task) {
        long start = System.nanoTime();
        try {
            runAll(count, task);
        } finally {
            nanosInBands += System.nanoTime() - start;
        }
    }

    /**
     * The wall time spent in {@link #forEach} so far, summed over its calls:
     * how long the bands took, against the whole drawing's time (the rest,
     * reading and the geometry stage, runs on one thread). For benchmarks;
     * read on the thread that calls forEach.
     */
    public long nanosInBands() {
        return nanosInBands;
    }

    private void runAll(int count, IntConsumer task) {
        if (workers == null || count == 1) {
            for (int i = 0; i < count; i++) {
                task.accept(i);
            }
            return;
        }
        AtomicInteger next = new AtomicInteger();
        Runnable drain = () -> {
            for (int i = next.getAndIncrement(); i < count; i = next.getAndIncrement()) {
                task.accept(i);
            }
        };
        int helpers = Math.min(threads - 1, count - 1);
        List<Future<?>> running = new ArrayList<>(helpers);
        for (int k = 0; k < helpers; k++) {
            running.add(workers.submit(drain));
        }
        Throwable failure = null;
        try {
            drain.run();
        } catch (RuntimeException | Error e) {
            next.set(count); // the others stop after the band at hand
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

    /** Stops the workers (they finish nothing new); the caller's thread is untouched. */
    @Override
    public void close() {
        if (workers != null) {
            workers.shutdownNow();
        }
    }
}
