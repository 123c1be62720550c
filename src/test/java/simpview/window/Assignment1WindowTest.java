package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.event.KeyEvent;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.scene.simp.SceneDrawer;
import simpview.testing.Images;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/** A switches the window to the first assignment's five pages and back; the keys step within them. */
public class Assignment1WindowTest extends WindowTestCase {

    private static final long SEED = 361;

    @Test
    void aSwitchesAssignmentAndTheKeysStepWithinIt() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_A);
        RenderedView first = driver.awaitShown(new View.OfAssignment1Page(1));
        assertEquals("simpview — assignment 1, page 1/5: Starburst", driver.onEdt(() -> driver.window().frame().getTitle()));
        assertEquals(0, Images.differingPixels(Assignment1.render(1, PageContext.defaults().withSeed(SEED)), first.image()));
        assertEquals(0, driver.screenDiffersFrom(first.image()), "the page on screen");
        driver.press(KeyEvent.VK_LEFT);
        driver.awaitShown(new View.OfAssignment1Page(5));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfAssignment1Page(1));
        driver.press(KeyEvent.VK_3);
        RenderedView three = driver.awaitShown(new View.OfAssignment1Page(3));
        assertEquals("simpview — assignment 1, page 3/5: Random lines — seed 361",
                driver.onEdt(() -> driver.window().frame().getTitle()));
        assertEquals("a1-page3-seed361.png", three.suggestedFileName());
        driver.press(KeyEvent.VK_END);
        driver.awaitShown(new View.OfAssignment1Page(5));
        driver.clickPage();
        driver.awaitShown(new View.OfAssignment1Page(1));
        // Back to the eight pages, where the window left them.
        driver.press(KeyEvent.VK_A);
        driver.awaitShown(new View.OfPage(2));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(3));
    }
}
