package simpview.window;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneDrawer;

/**
 * The first picture dropped for comparison in a fresh window does not hold the event thread: reading it,
 * comparing it and searching it for a mistake of the whole panel (some 300 ms the first time, the code not yet
 * compiled) happen on the render thread, and the outcome is shown when it is done. A class of its own, so that
 * no comparison before it in the same JVM has warmed that code up.
 */
@Tag("timed")
public class FirstComparisonWindowTest extends WindowTestCase {

    /** The longest the EDT may stall for the drop, beyond what a busy machine excuses. */
    private static final long MAX_STALL_MS = 100;

    @Test
    void theFirstPictureDroppedIsComparedOffTheEventThread() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        BufferedImage ours = new PageRenderer().renderImage(1, PageContext.defaults().withSeed(361));
        BufferedImage theirs = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                boolean square = x >= 300 && x < 400 && y >= 300 && y < 400;
                theirs.setRGB(x, y, square ? 0x00FFFF : ours.getRGB(x, y));
            }
        }
        Path mine = dir.resolve("mine.png");
        ImageIO.write(theirs, "png", mine.toFile());
        long stall;
        long machine;
        try (EdtProbe probe = EdtProbe.start()) {
            assertTrue(DroppedFiles.dropOn(driver, mine), "the window took the dropped picture");
            driver.awaitEdt(() -> driver.window().comparison().comparison() != null
                    && driver.window().status().text().startsWith("vs mine.png: "), "the comparison shown");
            stall = probe.maxStallMillis();
            machine = probe.maxSchedulingLateMillis();
            assertTrue(probe.samples() > 0, "the probe ran");
        }
        // A machine that keeps every thread waiting excuses that much of the stall, no more.
        assertTrue(stall < MAX_STALL_MS + machine, "the EDT stalled for " + stall + " ms while a plain thread was at "
                + "most " + machine + " ms late");
    }
}
