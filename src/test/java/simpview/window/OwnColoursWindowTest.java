package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import simpview.scene.simp.SceneDrawer;
import simpview.window.render.View;

/**
 * C (own colours) changes depth-cued scenes only: on pages 1 to 3, the first assignment's pages and lit scenes,
 * which have no depth cue, the status line says it looks the same, nothing is drawn again, and the inspector's
 * line says "own colours" only over a picture it changed.
 */
public class OwnColoursWindowTest extends WindowTestCase {

    private static final String NOTE = " · own colours";

    @Test
    void ownColoursAreNotedOnlyWhereTheyChangeThePicture() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        SimpviewWindow window = driver.window();

        driver.onEdt(() -> window.perform(WindowAction.OWN_COLOURS));
        assertEquals("Own colours: on for depth-cued scenes. Page 1 has no depth cue (its triangles are drawn in "
                + "their vertices' own colours), so it looks the same either way.",
                driver.onEdt(() -> window.status().messageText()));
        assertFalse(driver.onEdt(window::busy), "page 1 not drawn again");
        assertFalse(driver.onEdt(() -> window.status().inspectorText()).contains(NOTE), "no note on page 1");

        driver.onEdt(() -> window.perform(WindowAction.PAGE_3));
        driver.awaitShown(new View.OfPage(3));
        assertFalse(driver.onEdt(() -> window.status().inspectorText()).contains(NOTE), "no note on page 3");

        driver.onEdt(() -> window.perform(WindowAction.ASSIGNMENT_1));
        driver.awaitShown(new View.OfAssignment1Page(1));
        assertFalse(driver.onEdt(() -> window.status().inspectorText()).contains(NOTE),
                "no note on the first assignment's page 1");

        Path lit = litSquare();
        driver.onEdt(() -> window.openScene(lit));
        driver.awaitShown(new View.OfScene(lit));
        assertFalse(driver.onEdt(() -> window.status().inspectorText()).contains(NOTE), "no note on a lit scene");

        driver.onEdt(() -> window.perform(WindowAction.PAGE_4));
        driver.awaitShown(new View.OfPage(4));
        assertTrue(driver.onEdt(() -> window.status().inspectorText()).endsWith(NOTE),
                "the note on page 4, a depth-cued scene: " + driver.onEdt(() -> window.status().inspectorText()));
    }
}
