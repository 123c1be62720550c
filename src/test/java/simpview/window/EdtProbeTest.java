package simpview.window;

import org.junit.jupiter.api.parallel.Isolated;

import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The probe the window tests judge stalls by: an EDT held up for 600 ms
 * shows as a stall that the machine's own lateness does not excuse, so
 * LargeSceneWindowTest's allowance for a busy machine cannot hide a window
 * that blocks its EDT.
 */
@Tag("timed")
@Isolated
public class EdtProbeTest {

    @Test
    void aBlockedEdtIsAStallThatABusyMachineDoesNotExcuse() throws Exception {
        try (EdtProbe probe = EdtProbe.start()) {
            Thread.sleep(100);
            SwingUtilities.invokeAndWait(() -> {
                long until = System.nanoTime() + 600_000_000L;
                while (System.nanoTime() < until) {
                    Thread.onSpinWait();
                }
            });
            Thread.sleep(100);
            long stall = probe.maxStallMillis();
            long machine = probe.maxSchedulingLateMillis();
            assertTrue(stall >= 550, "stall " + stall + " ms");
            assertTrue(stall >= LargeSceneWindowTest.MAX_STALL_MS + machine,
                    "a 600 ms block excused by a machine " + machine + " ms late");
        }
    }
}
