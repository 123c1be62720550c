package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import simpview.scene.simp.SceneDrawer;
import simpview.window.render.View;

/**
 * A lit scene whose .obj model has hundreds of thousands of lines, opened in the real window: while the model is
 * read the progress bar counts its lines, and Cancel stops the reading, so the next page comes at once.
 */
class LargeModelWindowTest extends WindowTestCase {

    @Test
    void theBarCountsTheModelsLinesAndCancelStopsItsReading() throws Exception {
        Path scene = TestScenes.writeGridModelScene(dir, "grid", 500);
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), SceneDrawer.SIMP);
        SimpviewWindow window = driver.window();
        driver.onEdt(() -> window.openScene(scene));
        // the scene's own file has six lines: a count beyond them is the model's
        driver.awaitEdt(() -> window.status().showingProgress() && window.linesReadSoFar() > 6,
                "the progress bar to count the model's lines");
        driver.click(window.status().cancelButton());
        driver.awaitEdt(() -> !window.busy(), "the cancel to take");
        assertEquals(new View.OfPage(1), driver.onEdt(() -> window.shown().view()), "cancel leaves the page showing");
        driver.clickPage();
        driver.awaitShown(new View.OfPage(2));
    }
}
