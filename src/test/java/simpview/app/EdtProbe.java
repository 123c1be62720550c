package simpview.app;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;

/**
 * Measures how long the EDT keeps the window from answering: every 10 ms it
 * posts a task and records how late the EDT ran it. The largest delay is the
 * longest stall a user would have felt.
 */
final class EdtProbe implements AutoCloseable {

    private final ScheduledExecutorService ticker = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread t = new Thread(task, "edt-probe");
        t.setDaemon(true);
        return t;
    });
    private final long startNanos = System.nanoTime();
    private volatile long maxDelayNanos;
    private volatile long maxDelayAtNanos;
    private volatile long samples;

    private EdtProbe() {
    }

    static EdtProbe start() {
        EdtProbe probe = new EdtProbe();
        probe.ticker.scheduleAtFixedRate(probe::post, 0, 10, TimeUnit.MILLISECONDS);
        return probe;
    }

    private void post() {
        long posted = System.nanoTime();
        SwingUtilities.invokeLater(() -> record(System.nanoTime() - posted));
    }

    private void record(long delay) {
        // Only the EDT writes these, so read-modify-write is safe.
        samples++;
        if (delay > maxDelayNanos) {
            maxDelayNanos = delay;
            maxDelayAtNanos = System.nanoTime() - delay - startNanos;
        }
    }

    long maxStallMillis() {
        return maxDelayNanos / 1_000_000;
    }

    /** When the longest stall began, in ms after the probe started. */
    long maxStallStartMillis() {
        return maxDelayAtNanos / 1_000_000;
    }

    long samples() {
        return samples;
    }

    @Override
    public void close() {
        ticker.shutdownNow();
    }
}
