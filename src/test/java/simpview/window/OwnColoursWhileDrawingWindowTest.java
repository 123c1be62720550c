package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * C (own colours) on a lit scene still being drawn does what it does on a finished one: SPEC Part 2 colours a lit
 * scene by its lights and fog, own colours or not, so its drawing goes on, not started over, and the status line
 * says the scene is lit instead of claiming it now shows its vertices' colours.
 */
public class OwnColoursWhileDrawingWindowTest extends WindowTestCase {

    @Test
    void ownColoursOnALitSceneBeingDrawnKeepDrawingItAndSayItIsLit() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), StandInDrawers.LIT_UNTIL_CANCELLED);
        SimpviewWindow window = driver.window();
        Path scene = StandInDrawers.sceneFile(dir, "lit.simp");
        driver.onEdt(() -> window.openScene(scene));
        driver.awaitEdt(() -> window.linesReadSoFar() > 0, "the lit scene being drawn, its lines read");

        long[] lines = driver.onEdt(() -> {
            long before = window.linesReadSoFar();
            window.perform(WindowAction.OWN_COLOURS);
            return new long[] {before, window.linesReadSoFar()};
        });
        assertTrue(lines[1] >= lines[0], "the drawing started over: " + lines[0] + " lines read before C, "
                + lines[1] + " after");
        assertEquals("Own colours: on for depth-cued scenes. This scene is lit (its camera, lights and fog make its "
                + "colours, SPEC Part 2), so it looks the same either way.",
                driver.onEdt(() -> window.status().messageText()));
        assertTrue(driver.onEdt(window::busy), "the lit scene still being drawn");

        driver.onEdt(() -> {
            window.perform(WindowAction.OWN_COLOURS);
            return null;
        });
        assertEquals("Depth cue: on again for depth-cued scenes. This scene is lit (its camera, lights and fog make "
                + "its colours, SPEC Part 2), so it looks the same either way.",
                driver.onEdt(() -> window.status().messageText()));
    }
}
