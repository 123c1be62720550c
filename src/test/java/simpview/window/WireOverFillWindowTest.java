package simpview.window;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Wire over fill (W) on a scene of tens of thousands of primitives, in the real window: zooming and panning
 * under it keeps the window answering, as a page of the course's size (page-d, 16,026 outlines) must, and the
 * wire is drawn at the zoom it ends at.
 */
@Tag("timed")
class WireOverFillWindowTest extends WindowTestCase {

    private static final int POLYGONS = 40_000;

    @Test
    void zoomingUnderTheWireKeepsTheWindowAnswering() throws Exception {
        Path scene = TestScenes.writeManyPolygons(dir.resolve("many.simp"), POLYGONS);
        SimpviewWindow window = openWindowOn(scene);
        driver.onEdt(() -> window.perform(WindowAction.WIRE));
        driver.awaitEdt(() -> window.pageView().wireShown(), "wire over fill");
        driver.settle();
        long stall;
        long machine;
        try (EdtProbe probe = EdtProbe.start()) {
            for (int k = 0; k < 3; k++) {
                driver.onEdt(() -> window.perform(WindowAction.ZOOM_IN));
                driver.settle();
                driver.onEdt(() -> window.perform(WindowAction.ZOOM_OUT));
                driver.settle();
            }
            stall = probe.maxStallMillis();
            machine = probe.maxSchedulingLateMillis();
        }
        assertTrue(stall < LargeSceneWindowTest.MAX_STALL_MS + machine, "the EDT stalled for " + stall
                + " ms drawing " + POLYGONS + " outlines, while a plain thread was at most " + machine + " ms late");
        driver.awaitEdt(() -> window.pageView().outlinesFinished(), "the wire drawn at the last zoom");
    }
}
