package simpview.window;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;

/**
 * Measures how long the EDT keeps the window from answering: every 10 ms it
 * posts a task and records how late the EDT ran it. The largest delay is the
 * longest stall a user would have felt. Beside it a control thread measures
 * how late the machine itself runs a waiting thread, so that a test can tell
 * a window that stalls from a machine that other builds keep busy.
 */
public final class EdtProbe implements AutoCloseable {

    private final ScheduledExecutorService ticker = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread t = new Thread(task, "edt-probe");
        t.setDaemon(true);
        return t;
    });
    /** A plain thread that sleeps 5 ms at a time: how late it wakes is how busy the machine is. */
    private final Thread control = new Thread(this::measureScheduling, "edt-probe-control");
    private final long startNanos = System.nanoTime();
    private volatile long maxLateNanos;
    private volatile long maxDelayNanos;
    private volatile long maxDelayAtNanos;
    private volatile long samples;

    private EdtProbe() {
    }

    static EdtProbe start() {
        EdtProbe probe = new EdtProbe();
        probe.ticker.scheduleAtFixedRate(probe::post, 0, 10, TimeUnit.MILLISECONDS);
        probe.control.setDaemon(true);
        probe.control.start();
        return probe;
    }

    private void measureScheduling() {
        while (true) {
            long before = System.nanoTime();
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                return;
            }
            long late = System.nanoTime() - before - 5_000_000;
            if (late > maxLateNanos) {
                maxLateNanos = late; // only this thread writes it
            }
        }
    }

    /**
     * The longest a plain thread of this process overslept while the probe ran:
     * the part of an EDT stall that a busy machine, not the window, accounts for.
     */
    long maxSchedulingLateMillis() {
        return maxLateNanos / 1_000_000;
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
        control.interrupt();
    }
}
