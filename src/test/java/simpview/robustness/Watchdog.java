package simpview.robustness;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Runs one piece of work on its own thread with a time limit, so that a
 * renderer or interpreter that loops forever fails the property instead of
 * hanging the build. A run over the limit is first asked to stop (the flag
 * given to it, then an interrupt); if it still runs a second later its thread
 * is stopped by force, the only way to get a spinning CPU back on Java 17.
 */
final class Watchdog {

    /** Work that may throw anything; {@code stop} turns true when the time is up. */
    interface Job<T> {
        T run(AtomicBoolean stop) throws Exception;
    }

    private Watchdog() {
    }

    static <T> T withinMillis(long limitMillis, String what, Job<T> job) throws Exception {
        AtomicBoolean stop = new AtomicBoolean();
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        Thread worker = new Thread(() -> {
            try {
                result.set(job.run(stop));
            } catch (Throwable t) {
                thrown.set(t);
            }
        }, "watchdog-worker");
        worker.setDaemon(true);
        long start = System.nanoTime();
        worker.start();
        worker.join(limitMillis);
        if (worker.isAlive()) {
            stop.set(true);
            worker.interrupt();
            worker.join(1000);
            if (worker.isAlive()) {
                forceStop(worker);
            }
            fail(what + " ran over " + limitMillis + " ms (still running after "
                    + (System.nanoTime() - start) / 1_000_000 + " ms)");
        }
        Throwable t = thrown.get();
        if (t instanceof Exception) {
            throw (Exception) t;
        }
        if (t instanceof Error) {
            throw (Error) t;
        }
        return result.get();
    }

    static void withinMillis(long limitMillis, String what, Callable<?> job) throws Exception {
        withinMillis(limitMillis, what, stop -> job.call());
    }

    @SuppressWarnings({"deprecation", "removal"})
    private static void forceStop(Thread worker) {
        try {
            worker.stop();
        } catch (UnsupportedOperationException e) {
            // Newer JDKs cannot stop a thread; it is a daemon, so it dies with the JVM.
        }
    }
}
