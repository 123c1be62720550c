package simpview.surface;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;

/**
 * The threads that draw one picture's bands of rows together: the thread
 * that reads the scene and {@code threads - 1} workers named
 * {@code simpview-band-1}, {@code simpview-band-2}, ... Made and closed by
 * whoever draws (a page renderer, a command, a benchmark) and handed to the
 * scene it draws; never shared through a global. One thread has no worker at
 * all: then everything is drawn on the caller's thread, as it always was.
 *
 * <p>Which thread draws which band does not matter to the picture: a band's
 * pixels are written by that band's drawer only, in drawing order.
 *
 * <p>With more than one thread, every recorded batch of a picture is drawn
 * in bands by all of them, handed to a {@link BandQueue} and drawn while the
 * caller goes on reading the next one; the caller draws bands too whenever
 * it waits. No batch is kept whole for one thread, however little work it
 * holds: the default once kept a batch of under 50,000 pixels so, and took
 * up to 1.67 times as long for it (A4 page-c3 turned, two threads), faster
 * on no course page beyond the measurements' noise (docs/performance-log.md,
 * session 39).
 */
public final class DrawingThreads implements AutoCloseable {

    /**
     * Bands per thread unless a record asks for another number
     * ({@link #bands(int, int)}): more bands than threads even out pages
     * whose content is not spread evenly, and shorten the wait at a
     * picture's end for the last band; each band costs the row test of
     * every primitive and the set-up of each triangle that crosses into it.
     * 8 measured faster than 3 on the course's lit pages on two threads
     * (0.84 to 0.99 of the time, docs/performance-log.md, session 4), and than 4
     * (A3 pageE, pageF and A4 page-e 1.10-1.15 of 8's time with 4, session
     * 14).
     */
    public static final int BANDS_PER_THREAD = 8;

    /**
     * How long a worker with nothing to do spins, looking for the next
     * task, before it parks: a picture drawn right after another (a turning
     * view, a benchmark, a batch of pages) hands in its first batch within
     * about 0.06 ms of the last one's end, and a parked thread took 0.03-0.05
     * ms to wake on this machine's cores.
     */
    private static final long IDLE_SPIN_NANOS = 100_000;

    private final int threads;
    /**
     * True when each drawing thread had a processor of its own when these
     * threads were made ({@link #coreEach}). Asked once, not for each
     * picture: in a container the JVM keeps its processor count 20 ms and
     * then reads the cgroup's CPU limits again, and on this machine
     * {@code availableProcessors()} called every 7 ms took a mean of 60 us,
     * every 30 ms 158 us; each picture's queue asked it before handing in
     * its first batch (docs/performance-log.md, session 50).
     */
    private final boolean coreEach;
    /** The workers; empty for one thread. */
    private final List<Thread> workers = new ArrayList<>();
    /** What the workers are to run, each by one of them. */
    private final LinkedBlockingQueue<Runnable> toRun = new LinkedBlockingQueue<>();
    /** Set by {@link #close}: the workers return. */
    private volatile boolean closed;
    /** Wall time from each picture's first batch to the end of its finish, summed: the parallel part of drawing. */
    private long nanosInBands;
    /** Tasks handed to queues (a band of a batch each), summed. */
    private long tasks;
    /**
     * What a picture's drawing made and gave back for the next picture, by
     * class: each record's ring of batches, the fragment stages of the lit
     * drawers.
     */
    private final Map<Class<?>, List<?>> kept = new HashMap<>();
    /** Who is told what the queues' threads do, or null: nobody. */
    private volatile BandWatch watch;

    private DrawingThreads(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        }
        this.threads = threads;
        this.coreEach = threads <= Runtime.getRuntime().availableProcessors();
        for (int w = 1; w < threads; w++) {
            Thread t = new Thread(this::work, "simpview-band-" + w);
            t.setDaemon(true);
            workers.add(t);
            t.start();
        }
    }

    /** A worker's loop: runs the tasks handed in, spinning a while for the next before it parks, until closed. */
    private void work() {
        while (!closed) {
            Runnable task = toRun.poll();
            long until = System.nanoTime() + IDLE_SPIN_NANOS;
            while (task == null && !closed && System.nanoTime() - until < 0) {
                Thread.onSpinWait();
                task = toRun.poll();
            }
            try {
                if (task == null) {
                    task = toRun.take();
                }
            } catch (InterruptedException e) {
                return; // closed
            }
            try {
                task.run();
            } catch (RuntimeException | Error e) {
                // Not a drawer's failure (the queue keeps those for the drawing thread): a fault of the queue
                // itself. Told to the handler; the worker stays for the next picture.
                Thread self = Thread.currentThread();
                self.getUncaughtExceptionHandler().uncaughtException(self, e);
            }
        }
    }

    /** Drawing every picture with {@code threads} threads: the caller's and threads - 1 workers. */
    public static DrawingThreads of(int threads) {
        return new DrawingThreads(threads);
    }

    /** The caller's thread alone. */
    public static DrawingThreads one() {
        return new DrawingThreads(1);
    }

    /** As many threads as the JVM sees processors: what simpview draws with when no {@code --threads} is given. */
    public static DrawingThreads perProcessor() {
        return of(Runtime.getRuntime().availableProcessors());
    }

    /** How many threads draw each picture: the caller's and {@code threads() - 1} workers. */
    public int threads() {
        return threads;
    }

    /**
     * True when each of these threads had a processor of its own when they
     * were made: a thread waiting for the others may then spin a while
     * without taking a core a drawer needs.
     */
    public boolean coreEach() {
        return coreEach;
    }

    /** True when there is only the caller's thread: then scenes are drawn as they are read, unrecorded. */
    public boolean isOne() {
        return threads == 1;
    }

    /** The bands a picture of {@code rows} rows is split into for these threads: {@link #BANDS_PER_THREAD} each. */
    public RowBands bands(int rows) {
        return bands(rows, BANDS_PER_THREAD);
    }

    /** The bands a picture of {@code rows} rows is split into for these threads: {@code perThread} each, at most a row each. */
    public RowBands bands(int rows, int perThread) {
        return new RowBands(rows, Math.max(1, Math.min(rows, threads * perThread)));
    }

    /**
     * A queue of batches drawn in this picture's {@code bands} bands by these
     * threads, the batches in a ring of {@code slots} (2 or more), drawn by
     * {@code drawer} (see {@link BandQueue}).
     */
    public BandQueue queue(int bands, int slots, BandQueue.Drawer drawer) {
        return new BandQueue(this, bands, slots, drawer, watch);
    }

    /**
     * From the next queue made on, tells {@code by} what the queues' threads
     * do (null: nobody, the default): for a timeline of where a picture's
     * time goes ({@link BandWatch}).
     */
    public void watchedBy(BandWatch by) {
        watch = by;
    }

    /**
     * The objects of this class a picture drawn by these threads gave back
     * with {@link #keep} when it finished (a record's ring of batches, whose
     * arrays have grown to what the pictures need, the drawers' fragment
     * stages), so that the next picture neither allocates nor grows them
     * again. Handed to one picture at a time: null when none are kept, or
     * when a picture drawing now has them.
     */
    public synchronized <T> List<T> takeKept(Class<T> kind) {
        List<?> objects = kept.remove(kind);
        if (objects == null) {
            return null;
        }
        List<T> taken = new ArrayList<>(objects.size());
        for (Object o : objects) {
            taken.add(kind.cast(o));
        }
        return taken;
    }

    /**
     * Keeps a finished picture's objects of this class for the next picture
     * ({@link #takeKept}), in place of any kept before; none of them may be
     * in use.
     */
    public synchronized <T> void keep(Class<T> kind, List<T> objects) {
        kept.put(kind, objects);
    }

    /**
     * Runs {@code work} on a worker (there are workers: more than one
     * thread), once one is free; not once closed. What it throws is told to
     * the worker's uncaught-exception handler, and the worker goes on: a
     * drawer's failure never is, being the queue's to throw on the drawing
     * thread.
     */
    void start(Runnable work) {
        if (closed) {
            throw new IllegalStateException("the drawing threads are closed");
        }
        toRun.add(work);
    }

    /** Adds to the counters: {@code count} tasks handed in, {@code nanos} of drawing in bands. */
    void counted(long count, long nanos) {
        tasks += count;
        nanosInBands += nanos;
    }

    /**
     * The wall time from each picture's first batch handed in to the end of
     * its {@link BandQueue#finish}, summed: how long bands were being drawn,
     * against the whole drawing's time (the rest, reading and the geometry
     * stage before the first batch, runs on one thread alone). For
     * benchmarks; read on the thread that draws.
     */
    public long nanosInBands() {
        return nanosInBands;
    }

    /** How many tasks (a band of a batch each) were handed in so far: for benchmarks and tests, as {@link #nanosInBands}. */
    public long tasks() {
        return tasks;
    }

    /**
     * Stops the workers: they start nothing new, and one drawing stops
     * (interrupted), the caller drawing what is left. The caller's thread is
     * untouched.
     */
    @Override
    public void close() {
        closed = true;
        for (Thread t : workers) {
            t.interrupt();
        }
        toRun.clear();
    }
}
