package simpview.robustness;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Runs one piece of work on a worker thread with a time limit, so that a
 * renderer or interpreter that loops forever fails the property instead of
 * hanging the build. A run over the limit is first asked to stop (the flag
 * given to it, then an interrupt); if it still runs a second later its thread
 * is stopped by force, the only way to get a spinning CPU back on Java 17,
 * and a fresh worker takes its place.
 */
final class Watchdog {

    /** Work that may throw anything; {@code stop} turns true when the time is up. */
    interface Job<T> {
        T run(AtomicBoolean stop) throws Exception;
    }

    private static ExecutorService worker = newWorker();
    private static final AtomicReference<Thread> WORKER_THREAD = new AtomicReference<>();

    private Watchdog() {
    }

    private static ExecutorService newWorker() {
        return Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "watchdog-worker");
            t.setDaemon(true);
            return t;
        });
    }

    static synchronized <T> T withinMillis(long limitMillis, String what, Job<T> job) throws Exception {
        AtomicBoolean stop = new AtomicBoolean();
        long start = System.nanoTime();
        Future<T> future = worker.submit(() -> {
            WORKER_THREAD.set(Thread.currentThread());
            return job.run(stop);
        });
        try {
            return future.get(limitMillis, TimeUnit.MILLISECONDS);
        } catch (ExecutionException e) {
            Throwable t = e.getCause();
            if (t instanceof Exception) {
                throw (Exception) t;
            }
            throw (Error) t;
        } catch (TimeoutException e) {
            stop.set(true);
            future.cancel(true);
            Thread runaway = WORKER_THREAD.get();
            runaway.join(1000);
            if (runaway.isAlive()) {
                forceStop(runaway);
            }
            worker.shutdownNow();
            worker = newWorker();
            fail(what + " ran over " + limitMillis + " ms (still running after "
                    + (System.nanoTime() - start) / 1_000_000 + " ms)");
            return null;
        }
    }

    static void withinMillis(long limitMillis, String what, Callable<?> job) throws Exception {
        withinMillis(limitMillis, what, stop -> job.call());
    }

    @SuppressWarnings({"deprecation", "removal"})
    private static void forceStop(Thread runaway) {
        try {
            runaway.stop();
        } catch (UnsupportedOperationException e) {
            // Newer JDKs cannot stop a thread; it is a daemon, so it dies with the JVM.
        }
    }
}
