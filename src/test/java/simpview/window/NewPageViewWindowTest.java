package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * Another page or scene opens at the default view, as in an image viewer,
 * whichever way it is opened (Ctrl+O's open, a drop, a page key, A for the
 * first assignment); the same one drawn again (F5, a save of its file) keeps
 * the zoom and the pan, to compare before and after.
 */
public class NewPageViewWindowTest extends WindowTestCase {

    @Test
    void anotherPageOpensFittedAndTheSameOneDrawnAgainKeepsZoomAndPan() throws Exception {
        Path first = Files.writeString(dir.resolve("first.simp"), triangle(-150));
        Path second = Files.writeString(dir.resolve("second.simp"), triangle(-50));
        SimpviewWindow window = openWindowOn(first);
        assertFitted("the first scene");

        // the same scene drawn again: F5, then a save of its file
        Point zoomed = zoomInAndPan();
        driver.press(KeyEvent.VK_F5);
        driver.awaitShown(new View.OfScene(first));
        assertZoomedAt(zoomed, "after F5");
        RenderedView before = driver.onEdt(window::shown);
        Files.writeString(first, triangle(-100));
        driver.awaitEdt(() -> window.shown() != before && !window.busy(), "the scene drawn again after its save");
        assertZoomedAt(zoomed, "after a save");

        // another scene, opened as Ctrl+O opens it
        driver.onEdt(() -> window.openScene(second));
        RenderedView opened = driver.awaitShown(new View.OfScene(second));
        assertFitted("a scene opened");
        assertEquals(0, driver.screenDiffersFrom(opened.image()), "the whole page on screen");

        // another scene dropped on the window
        zoomInAndPan();
        assertTrue(DroppedFiles.dropOn(driver, first), "the window took the dropped scene");
        driver.awaitShown(new View.OfScene(first));
        assertFitted("a scene dropped");

        // the next page (→), then the first assignment's (A)
        zoomInAndPan();
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitEdt(() -> !window.busy() && window.shown().view() instanceof View.OfPage, "the next page");
        assertFitted("the next page");
        zoomInAndPan();
        driver.press(KeyEvent.VK_A);
        driver.awaitEdt(() -> !window.busy() && window.shown().view() instanceof View.OfAssignment1Page,
                "the first assignment's page");
        assertFitted("the first assignment's page");

        // Crop chosen: a new page opens cropped, the fit last chosen
        driver.press(KeyEvent.VK_X);
        zoomInAndPan();
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfAssignment1Page(2));
        assertTrue(driver.onEdt(() -> window.pageView().zoomPan().fitting() && window.pageView().zoomPan().cropped()),
                "the next page opens cropped, as Crop was the fit chosen");
    }

    /**
     * The scene on screen opened again keeps zoom and pan however its path is written: the window opened on a
     * relative path ({@code simpview first.simp}), Ctrl+O and a drop give the absolute one. A scene of the same
     * name in another folder is another scene, and opens fitted.
     */
    @Test
    void theSceneOnScreenOpenedAgainByAnotherPathKeepsZoomAndAnotherOfItsNameOpensFitted() throws Exception {
        Path first = Files.writeString(dir.resolve("first.simp"), triangle(-150));
        Path relative = Path.of("").toAbsolutePath().relativize(first);
        assertFalse(relative.isAbsolute());
        SimpviewWindow window = openWindowOn(relative);
        Point zoomed = zoomInAndPan();
        driver.onEdt(() -> window.openScene(first));
        driver.awaitShown(new View.OfScene(first));
        assertZoomedAt(zoomed, "after the scene on screen was opened again by its absolute path");
        driver.onEdt(() -> window.openScene(dir.resolve("sub").resolve("..").resolve("first.simp")));
        driver.awaitShown(new View.OfScene(dir.resolve("sub").resolve("..").resolve("first.simp")));
        assertZoomedAt(zoomed, "after the scene on screen was opened again through a folder and ..");

        Path namesake = Files.writeString(Files.createDirectories(dir.resolve("other")).resolve("first.simp"),
                triangle(-50));
        driver.onEdt(() -> window.openScene(namesake));
        driver.awaitShown(new View.OfScene(namesake));
        assertFitted("a scene of the same name in another folder");
    }

    /** Zooms in to 4x about a point off the middle and pans; returns the image's corner on screen then. */
    private Point zoomInAndPan() throws Exception {
        return driver.onEdt(() -> {
            ZoomPan zoomPan = driver.window().pageView().zoomPan();
            zoomPan.zoomAbout(200, 260, 4);
            zoomPan.pan(-37, 23);
            driver.window().pageView().repaint();
            assertFalse(zoomPan.fitting());
            return new Point((int) zoomPan.originX(), (int) zoomPan.originY());
        });
    }

    private void assertZoomedAt(Point corner, String when) throws Exception {
        ZoomPan zoomPan = driver.onEdt(() -> driver.window().pageView().zoomPan());
        assertEquals(4.0, driver.onEdt(zoomPan::zoom), "zoom kept " + when);
        assertEquals(corner, driver.onEdt(() -> new Point((int) zoomPan.originX(), (int) zoomPan.originY())),
                "pan kept " + when);
    }

    private void assertFitted(String what) throws Exception {
        ZoomPan zoomPan = driver.onEdt(() -> driver.window().pageView().zoomPan());
        assertTrue(driver.onEdt(zoomPan::fitting), what + " opens at the fit, not at " + driver.onEdt(zoomPan::describe));
        assertEquals(driver.onEdt(zoomPan::fitZoom), driver.onEdt(zoomPan::zoom), what);
    }

    private static String triangle(int z) {
        return "polygon (-60, -60, " + z + ") (60, -60, " + z + ") (0, 60, " + z + ")\n";
    }
}
