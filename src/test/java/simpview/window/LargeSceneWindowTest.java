package simpview.window;

import org.junit.jupiter.api.parallel.Isolated;

import simpview.scene.simp.SceneDrawer;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * A scene of a million polygons opened in the real window: the window keeps
 * answering while it is drawn, shows progress, and Cancel leaves the page
 * that was showing.
 */
@Tag("timed")
@Isolated
public class LargeSceneWindowTest {

    static final int POLYGONS = 1_000_000;
    static final long MAX_STALL_MS = 100;
    private static final long SEED = 361;

    @TempDir
    static Path dir;
    private static Path bigScene;

    private WindowDriver driver;

    @BeforeAll
    static void writeBigScene() throws Exception {
        Displays.assumeUsable();
        bigScene = TestScenes.writeManyPolygons(dir.resolve("million.simp"), POLYGONS);
    }

    @BeforeEach
    void needsADisplay() {
        Displays.assumeUsable();
    }

    @AfterEach
    void closeWindow() throws Exception {
        if (driver != null) {
            driver.close();
        }
    }

    @Test
    void simpInterpreterKeepsTheWindowAnsweringAndCancels() throws Exception {
        cancelBigSceneAndCheckThePageStays(SceneDrawer.SIMP);
    }

    /** The same with a stand-in reader, so the window's part is tested whatever the interpreter does. */
    @Test
    void windowMachineryKeepsAnsweringAndCancelsWithAStandInReader() throws Exception {
        cancelBigSceneAndCheckThePageStays(StandInDrawers.SLOW_READER);
    }

    private void cancelBigSceneAndCheckThePageStays(SceneDrawer drawer) throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), drawer);
        SimpviewWindow window = driver.window();
        BufferedImage page1 = new PageRenderer().renderImage(1, PageContext.defaults().withSeed(SEED));
        String title = driver.onEdt(() -> window.frame().getTitle());

        long stall;
        long machine;
        String when;
        try (EdtProbe probe = EdtProbe.start()) {
            long probeStart = System.nanoTime();
            long opened = System.nanoTime();
            driver.onEdt(() -> window.openScene(bigScene));
            driver.awaitEdt(() -> !window.busy() || window.status().showingProgress() && window.linesReadSoFar() > 0,
                    "progress or the end of the scene");
            if (!driver.onEdt(window::busy)) {
                failBecauseNothingWasLeftToCancel(driver.onEdt(window::shown), (System.nanoTime() - opened) / 1_000_000);
            }
            long progressAt = (System.nanoTime() - opened) / 1_000_000;
            Thread.sleep(800); // let it draw for a while, under the probe's watch
            assertTrue(driver.onEdt(window::busy), "still drawing when Cancel is pressed");
            // Measured before the click: waiting for the click to be handled runs work on the EDT too.
            stall = probe.maxStallMillis();
            machine = probe.maxSchedulingLateMillis();
            when = "starting " + probe.maxStallStartMillis() + " ms after the probe started; scene opened at "
                    + (opened - probeStart) / 1_000_000 + " ms, progress seen " + progressAt + " ms later";
            assertTrue(probe.samples() > 50, "the probe ran: " + probe.samples() + " samples");
        }
        driver.click(window.status().cancelButton());
        driver.awaitEdt(() -> !window.busy(), "the cancel to take");
        // A machine that keeps every thread waiting excuses that much of the stall, no more.
        assertTrue(stall < MAX_STALL_MS + machine, "the EDT stalled for " + stall + " ms while a plain thread was"
                + " at most " + machine + " ms late, " + when);
        // A bar left animating would wake the EDT every few milliseconds for as long as the window is open.
        assertFalse(driver.onEdt(() -> window.status().animating()), "the progress bar still animating after cancel");

        RenderedView shown = driver.onEdt(window::shown);
        assertEquals(new View.OfPage(1), shown.view(), "cancel leaves the page that was showing");
        assertNull(shown.error());
        assertEquals(title, driver.onEdt(() -> window.frame().getTitle()));
        assertEquals(0, driver.screenDiffersFrom(page1), "pixels differing from page 1 after cancel");

        // The render thread let go of the scene: the next page comes promptly.
        driver.clickPage();
        driver.awaitShown(new View.OfPage(2));
    }

    private static void failBecauseNothingWasLeftToCancel(RenderedView shown, long millis) {
        String error = shown.error();
        fail("the scene was drawn in " + millis + " ms, before any progress showed: nothing left to cancel"
                + (error == null ? "" : "; it ended with: " + error));
    }
}
