package simpview.surface;

import java.util.Arrays;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.IntUnaryOperator;

/**
 * Batches of primitives drawn band by band by all the threads, each band's
 * batches in the order they were handed in, while the thread that hands
 * them in (the one reading the scene) fills the next: band b of a batch is
 * drawn as soon as band b of the batch before it is, whatever the other
 * bands are doing, so no thread waits at a batch's end for the slowest band.
 * Each pixel belongs to one band and sees its writes in drawing order, so
 * the picture is the same to the bit as one thread drawing the scene as it
 * reads it.
 *
 * <p>The batches live in a ring of {@code slots} the caller owns: batch k in
 * slot k mod slots. The caller fills the slot {@link #slot} gives, hands it
 * in with {@link #publish}, and asks for the next slot, which is free once
 * every band has drawn the batch that was in it; waiting for it, the caller
 * draws bands itself.
 *
 * <p>Which thread draws which band does not change the picture; for speed,
 * each thread first draws its own bands (band b is thread b mod threads's,
 * the caller being thread 0), so that a band's rows stay in one core's
 * cache from batch to batch, and takes another's only when its own are
 * drawn, the least drawn first; among bands equally far along, the lowest,
 * or the heaviest by what the caller says of them ({@link #heavierFirst}).
 *
 * <p>Used by one thread, the one that fills the batches; the workers are
 * {@link DrawingThreads}'s, started at a picture's first batch and let go
 * by {@link #finish}. Everything the threads share is guarded by one lock,
 * taken twice per band of a batch; the drawing itself runs outside it.
 */
public final class BandQueue {

    /** Draws the batches: what the queue hands each thread. */
    @FunctionalInterface
    public interface Drawer {
        /** Draws band {@code band}'s rows of the batch in {@code slot}. */
        void band(int slot, int band);
    }

    /** How long a thread waiting for a change spins before it parks ({@link #awaitChange}). */
    private static final long SPIN_NANOS = 50_000;

    /**
     * How long the thread that hands in the batches spins in {@link #finish},
     * waiting for a picture's last bands, before it parks, when each drawing
     * thread has a processor of its own (else {@link #SPIN_NANOS}: a
     * spinning thread would take a core a drawer needs). The last bands take
     * tenths of a millisecond, and a thread parked after SPIN_NANOS took
     * 30-50 us to wake, added to every picture: on A4 page-f1 on two
     * threads, finish returned 29-50 us after the last band was drawn, and
     * 9 us spinning on (session 22).
     */
    private static final long FINISH_SPIN_NANOS = 2_000_000;

    /** What {@link #claim} returns when nothing can be drawn now. */
    private static final int NOTHING = -1;

    private final DrawingThreads threads;
    private final int bands;
    private final int slots;
    private final Drawer drawer;
    /** Who is told what the threads do, or null. */
    private final BandWatch watch;
    private final ReentrantLock lock = new ReentrantLock();
    /** Signalled when a batch is handed in, a band is drawn, or the picture is done. */
    private final Condition changed = lock.newCondition();

    // Guarded by lock.
    /** How many batches each band has drawn. */
    private final int[] drawn;
    /** True while a thread draws the band. */
    private final boolean[] claimed;
    /** Batches handed in so far. */
    private int published;
    /** Threads waiting for a change, parked. */
    private int waiting;
    /**
     * Changes so far (a batch handed in, a band or batch drawn, the picture
     * done): written with the lock held, read by a thread spinning without
     * it ({@link #awaitChange}).
     */
    private volatile int changes;
    /** True when no picture is being drawn: the workers return. */
    private boolean stopping = true;
    /** What a drawer threw first, or null. */
    private Throwable failure;
    /** When the picture's first batch was handed in. */
    private long since;
    /** How long {@link #finish} spins before it parks: {@link #FINISH_SPIN_NANOS} or {@link #SPIN_NANOS}. */
    private final long finishSpin;
    /** Each band's work still to come, as {@link #heavierFirst} was given it; 0 for every band by default. */
    private IntUnaryOperator weight = band -> 0;

    /**
     * For a panel drawn in {@code bands} bands (1 or more) by
     * {@code threads}, batches in a ring of {@code slots} (2 or more),
     * drawn by {@code drawer}, watched by {@code watch} (or null).
     */
    BandQueue(DrawingThreads threads, int bands, int slots, Drawer drawer, BandWatch watch) {
        if (bands < 1 || slots < 2) {
            throw new IllegalArgumentException(bands + " bands, " + slots + " slots");
        }
        this.threads = threads;
        this.bands = bands;
        this.slots = slots;
        this.drawer = drawer;
        this.watch = watch;
        this.drawn = new int[bands];
        this.claimed = new boolean[bands];
        this.finishSpin = threads.coreEach() ? FINISH_SPIN_NANOS : SPIN_NANOS;
    }

    /**
     * Among the bands a thread may take that are equally far along, the one
     * {@code weight} gives the most is taken first, the lowest of those that
     * tie (without a weight: the lowest). A picture's last bands then start
     * with the longest, so that no thread is left at the end with a long
     * band to draw while the others wait. {@code weight} is asked with the
     * lock held, on whichever thread claims, of bands no thread is drawing;
     * set it before the first batch is handed in.
     */
    public void heavierFirst(IntUnaryOperator weight) {
        this.weight = weight;
    }

    /**
     * The slot to fill next, once it is free: every band has drawn the batch
     * that was in it (this thread drawing bands meanwhile). Throws what a
     * drawer failed with, once every thread has stopped.
     */
    public int slot() {
        lock.lock();
        try {
            int next = published;
            while (failure == null && lowest() < next - slots + 1) {
                helpOrWait(SPIN_NANOS);
            }
            if (failure == null) {
                return next % slots;
            }
        } finally {
            lock.unlock();
        }
        finish(); // throws the failure
        throw new IllegalStateException("a drawer failed, and finish did not say so");
    }

    /**
     * Hands in the batch filled in the slot {@link #slot} gave, to be drawn
     * band by band; returns at once (with no worker, after drawing it).
     */
    public void publish() {
        lock.lock();
        try {
            if (watch != null) {
                watch.handedIn(published);
            }
            published++;
            if (stopping) {
                stopping = false;
                since = System.nanoTime();
                for (int w = 1; w < threads.threads(); w++) {
                    int home = w;
                    threads.start(() -> work(home));
                }
            }
            signalChange();
        } finally {
            lock.unlock();
        }
        threads.counted(bands, 0);
        if (threads.isOne()) {
            finish();
        }
    }

    /**
     * Returns when every batch handed in is drawn (this thread drawing
     * bands meanwhile), so that no thread draws any more; throws the first
     * failure of a drawer once every thread has stopped drawing. The workers
     * are let go and return on their own: waiting for them to be seen
     * returning took two wake-ups one after the other, 0.1-0.15 ms of A2's
     * page 5 (docs/performance-log.md, session 11). The queue can be used again
     * after a failure; the failed picture's undrawn rest is left undrawn.
     */
    public void finish() {
        Throwable failed;
        long start;
        lock.lock();
        try {
            while (failure == null ? lowest() < published : !nothingClaimed()) {
                helpOrWait(finishSpin);
            }
            if (stopping) {
                return;
            }
            stopping = true;
            signalChange();
            failed = failure;
            failure = null;
            Arrays.fill(drawn, published);
            start = since;
        } finally {
            lock.unlock();
        }
        threads.counted(0, System.nanoTime() - start);
        if (failed instanceof RuntimeException r) {
            throw r;
        }
        if (failed instanceof Error e) {
            throw e;
        }
        if (failed != null) {
            throw new IllegalStateException(failed);
        }
    }

    /** A worker's loop: draws what it can, its own bands first, and waits for more until the picture is drawn. */
    private void work(int home) {
        lock.lock();
        try {
            while (!stopping) {
                int item = claim(home);
                if (item != NOTHING) {
                    draw(item);
                    continue;
                }
                if (!awaitChange(true, SPIN_NANOS)) {
                    return; // closed: the caller draws whatever is left
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * With the lock held, on the caller's thread: draws something if it can,
     * or else waits for a change, spinning {@code spin} ns before it parks.
     * An interrupt does not stop it (the picture must not be left half drawn
     * by others); the thread stays interrupted.
     */
    private void helpOrWait(long spin) {
        int item = claim(0);
        if (item != NOTHING) {
            draw(item);
            return;
        }
        awaitChange(false, spin);
    }

    /**
     * With the lock held: tells whoever waits that something changed, the
     * spinning ({@link #changes}) and the parked.
     */
    private void signalChange() {
        changes++;
        if (waiting > 0) {
            changed.signalAll();
        }
    }

    /**
     * With the lock held: waits for a change. First it spins {@code spin} ns
     * without the lock: a parked thread took 30-50 us to wake on this
     * machine's cores, as long as drawing a band of a small batch, and the
     * reading thread hands in the next batch, or a band drawer ends its band,
     * within {@link #SPIN_NANOS} as often as not. Then it parks, counted among
     * the waiters so that changes signal only when someone waits. An
     * interruptible wait returns false when interrupted; the other waits
     * through interrupts and leaves the thread interrupted.
     */
    private boolean awaitChange(boolean interruptible, long spin) {
        int seen = changes;
        lock.unlock();
        try {
            long until = System.nanoTime() + spin;
            while (changes == seen && System.nanoTime() - until < 0) {
                Thread.onSpinWait();
            }
        } finally {
            lock.lock();
        }
        if (changes != seen) {
            return true;
        }
        waiting++;
        if (watch != null) {
            watch.parked();
        }
        try {
            if (interruptible) {
                changed.await();
            } else {
                changed.awaitUninterruptibly();
            }
            return true;
        } catch (InterruptedException e) {
            return false;
        } finally {
            if (watch != null) {
                watch.woken();
            }
            waiting--;
        }
    }

    /**
     * With the lock held: takes a band to draw, for thread {@code home}: one
     * of its own whose next batch is handed in, else another thread's, the
     * least drawn first, then the heaviest ({@link #heavierFirst}). Returns
     * the batch times bands plus the band; NOTHING when there is nothing to
     * draw now, or a drawer has failed.
     */
    private int claim(int home) {
        if (failure != null) {
            return NOTHING;
        }
        int best = NOTHING;
        boolean bestMine = false;
        int bestWeight = 0; // of best
        int count = threads.threads();
        for (int b = 0; b < bands; b++) {
            int k = drawn[b];
            if (claimed[b] || k >= published) {
                continue;
            }
            boolean mine = b % count == home;
            if (best == NOTHING || (mine && !bestMine) || (mine == bestMine && k < drawn[best])) {
                best = b;
                bestMine = mine;
                bestWeight = weight.applyAsInt(b);
            } else if (mine == bestMine && k == drawn[best]) {
                int its = weight.applyAsInt(b);
                if (its > bestWeight) {
                    best = b;
                    bestWeight = its;
                }
            }
        }
        if (best == NOTHING) {
            return NOTHING;
        }
        claimed[best] = true;
        return drawn[best] * bands + best;
    }

    /**
     * With the lock held: draws what {@link #claim} gave, the lock let go
     * meanwhile, then marks it drawn and wakes whoever waits.
     */
    private void draw(int item) {
        int batch = item / bands;
        int band = item % bands;
        Throwable failed = null;
        lock.unlock();
        if (watch != null) {
            watch.drawing(batch, band);
        }
        try {
            drawer.band(batch % slots, band);
        } catch (RuntimeException | Error e) {
            failed = e;
        } finally {
            if (watch != null) {
                watch.drawn(batch, band);
            }
            lock.lock();
        }
        drawn[band] = batch + 1;
        claimed[band] = false;
        if (failed != null && failure == null) {
            failure = failed;
        }
        signalChange();
    }

    private int lowest() {
        int low = Integer.MAX_VALUE;
        for (int k : drawn) {
            low = Math.min(low, k);
        }
        return low;
    }

    private boolean nothingClaimed() {
        for (boolean c : claimed) {
            if (c) {
                return false;
            }
        }
        return true;
    }
}
