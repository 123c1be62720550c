package simpview.window;

import simpview.window.instruments.InspectorPanel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.JViewport;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import simpview.surface.PageCanvas;
import simpview.window.render.RenderedView;

/** The inspector panel under Xvfb: I shows the pinned pixel's history, wrapped, never cut; J steps to its primitive. */
public class InspectorPanelWindowTest extends WindowTestCase {

    /** Points at the panel's centre, pins it (P) and opens the inspector panel (I), and waits for its report. */
    private void pinTheCentreAndOpenThePanel(SimpviewWindow window) throws Exception {
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.robot().mouseMove(centre.x, centre.y);
        driver.awaitEdt(() -> window.status().inspectorText().contains("drawn by primitive"), "the inspector on the centre");
        driver.press(KeyEvent.VK_P);
        driver.press(KeyEvent.VK_I);
        driver.awaitEdt(() -> window.inspectorPanel().isShown() && window.inspectorPanel().answered()
                && window.inspectorPanel().text().contains("history:"), "the panel's report");
    }

    @Test
    void inANarrowWindowThePanelLeavesThePageHalfTheWidth() throws Exception {
        SimpviewWindow window = openWindowOn(litSquare());
        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        driver.awaitEdt(() -> window.inspectorPanel().isShown(), "the panel shown");
        driver.onEdt(() -> window.frame().setSize(400, 400));
        driver.awaitEdt(() -> window.frame().getWidth() == 400 && window.inspectorPanel().component().isShowing()
                && window.pageView().getWidth() >= window.frame().getContentPane().getWidth() / 2,
                "the page beside the panel at half the window's width at least");
        driver.onEdt(() -> window.frame().setSize(1200, 600));
        driver.awaitEdt(() -> window.frame().getWidth() == 1200
                && window.inspectorPanel().component().getWidth() == InspectorPanel.WIDTH,
                "the panel at its whole width again in a wide window");
    }

    /**
     * Hiding the panel (I) takes away what showing it added, from the width the window has then: a window the user
     * resized between keeps the rest of its new size, and never goes below its minimum.
     */
    @Test
    void hidingThePanelTakesAwayWhatShowingAddedFromTheWidthNow() throws Exception {
        SimpviewWindow window = openWindowOn(litSquare());
        int opened = driver.onEdt(() -> window.frame().getWidth());
        int height = driver.onEdt(() -> window.frame().getHeight());
        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        driver.awaitEdt(() -> window.inspectorPanel().isShown() && window.frame().getWidth() > opened,
                "the window widened for the panel");
        int added = driver.onEdt(() -> window.frame().getWidth()) - opened;

        driver.onEdt(() -> window.frame().setSize(opened + added - 150, height)); // the user narrows it
        driver.awaitEdt(() -> window.frame().getWidth() == opened + added - 150, "the window as the user left it");
        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        driver.awaitEdt(() -> !window.inspectorPanel().isShown() && window.frame().getWidth() == opened - 150,
                "the window " + added + " px narrower than the user left it, at " + (opened - 150));

        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        driver.awaitEdt(() -> window.inspectorPanel().isShown() && window.frame().getWidth() == opened - 150 + added,
                "the window widened for the panel again");
        driver.onEdt(() -> window.frame().setSize(added + 50, height)); // narrowed to little more than the panel
        driver.awaitEdt(() -> window.frame().getWidth() == added + 50, "the narrow window as the user left it");
        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        int least = driver.onEdt(() -> window.frame().getMinimumSize().width);
        driver.awaitEdt(() -> !window.inspectorPanel().isShown() && window.frame().getWidth() == least,
                "the window at its minimum width, " + least);
    }

    @Test
    void aTurningDragLeavesThePanelsReplayToTheFrameAfterIt() throws Exception {
        SimpviewWindow window = openWindowOn(litSquare());
        RenderedView unturned = driver.onEdt(() -> window.shown());
        pinTheCentreAndOpenThePanel(window);
        int before = driver.onEdt(() -> window.inspectorPanel().requests());

        // Frames of the drag: each a new picture, none replayed for the panel (its history is the unturned view's).
        dragTurning(unturned, first -> {
            nextDragFrame(first);
            assertEquals(before, driver.onEdt(() -> window.inspectorPanel().requests()), "no replay during the drag");
        });
        // The frame after the drag, traced, replays the pinned pixel's history once more, saying which view it is of.
        driver.awaitEdt(() -> !window.busy() && window.shown().facts().owners() != null
                && window.inspectorPanel().answered() && window.inspectorPanel().text().contains("unturned view"),
                "the panel replayed after the drag");
        assertTrue(driver.onEdt(() -> window.inspectorPanel().requests()) > before);
    }

    @Test
    void thePinnedPixelsHistoryAndSteppingToItsPrimitive() throws Exception {
        Files.writeString(dir.resolve("leaf.simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path scene = dir.resolve("top.simp");
        Files.writeString(scene, "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\nfile \"leaf\"\n"
                + "polygon (-90, -90, -150) (90, -90, -150) (0, 90, -150)\n"
                + "polygon (60, 60, -50) (60, 90, -50) (90, 60, -50)\n"
                + "polygon (60, -90, -300) (90, -90, -300) (90, -60, -300)\n");
        SimpviewWindow window = openWindowOn(scene);

        pinTheCentreAndOpenThePanel(window);
        String text = driver.onEdt(() -> window.inspectorPanel().text());
        assertTrue(text.contains("drawn by primitive 2: top.simp:2 › leaf.simp:1 polygon"), text);
        assertTrue(text.contains("history: 3 writes attempted"), text);
        assertTrue(text.contains("depth-failed"), text);
        assertTrue(text.contains("final_rgb"), text);
        assertTrue(text.contains("vertices of primitive 2:"), text);
        // Wrapped in a scrolling view that is as wide as the panel: no line runs off its right edge.
        boolean wraps = driver.onEdt(() -> {
            JViewport port = (JViewport) SwingUtilities.getAncestorOfClass(JViewport.class, textArea(window));
            return textArea(window).getLineWrap() && textArea(window).getWidth() <= port.getWidth();
        });
        assertTrue(wraps, "the panel's text wraps within its width");

        // J steps the drawing to the primitive that drew the pinned pixel: the second of three.
        driver.press(KeyEvent.VK_J);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().startsWith("primitive 2 of 4, leaf.simp:1"),
                "stepping to the pixel's primitive");

        // V: the overdraw overlay; the three triangles overlap at the centre, so the most is 3 writes.
        driver.press(KeyEvent.VK_BACK_SLASH);
        driver.awaitEdt(() -> !window.busy() && window.shown().facts().primitives().size() == 4, "the whole picture");
        driver.press(KeyEvent.VK_V);
        driver.awaitEdt(() -> window.overdrawShownMax() == 3, "the overdraw overlay, up to 3 writes");
        assertTrue(driver.onEdt(() -> window.status().messageText()).contains("up to 3 writes"));
        driver.press(KeyEvent.VK_V);
        driver.awaitEdt(() -> window.overdrawShownMax() == -1, "the page again");
        // Shift+V: at the centre the farthest triangle, drawn last, lost to the two before it: at most 1 loss.
        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_V);
        driver.awaitEdt(() -> window.overdrawShownMax() == 1, "the depth-test failures, at most 1");
        assertTrue(driver.onEdt(() -> window.status().messageText()).startsWith("Depth-test failures: up to 1 lost write at"));
        // V while the failures are shown: the overdraw takes their place; V again: the page
        driver.press(KeyEvent.VK_V);
        driver.awaitEdt(() -> window.overdrawShownMax() == 3, "the overdraw instead of the failures");
        driver.press(KeyEvent.VK_V);
        driver.awaitEdt(() -> window.overdrawShownMax() == -1, "the page again");
        assertEquals(driver.onEdt(() -> window.status().hints()), driver.onEdt(() -> window.status().messageText()), "no word of the overlay left");

        // K: the back faces: only the last triangle, (60, 60) (60, 90) (90, 60), is clockwise.
        driver.press(KeyEvent.VK_K);
        driver.awaitEdt(() -> window.backFacesShownCount() == 1, "the back-face overlay, one polygon facing away");
        assertTrue(driver.onEdt(() -> window.status().messageText()).contains("1 of 4 polygons"));
        driver.press(KeyEvent.VK_K);
        driver.awaitEdt(() -> window.backFacesShownCount() == -1, "the page again");

        // U: the one polygon beyond the far plane (z = -300) is culled, and outlined with its legend.
        driver.press(KeyEvent.VK_U);
        driver.awaitEdt(() -> window.skippedShown() != null, "the culled outlines");
        assertEquals(1L, (long) driver.onEdt(() -> window.skippedShown().culled()));
        assertEquals(0L, (long) driver.onEdt(() -> window.skippedShown().clipped()));
        String legend = driver.onEdt(() -> window.legendStrip().text());
        assertTrue(legend.contains("1 culled") && legend.contains("0 clipped away"), legend);
        driver.press(KeyEvent.VK_U);
        driver.awaitEdt(() -> window.skippedShown() == null && window.legendStrip().empty(), "the outlines off");

        // W: wire over fill, the edges of the 4 primitives drawn, with its legend.
        driver.press(KeyEvent.VK_W);
        driver.awaitEdt(() -> window.pageView().wireShown(), "wire over fill");
        assertTrue(driver.onEdt(() -> window.legendStrip().text()).contains("the edges of all 4 primitives"));
        driver.press(KeyEvent.VK_W);
        driver.awaitEdt(() -> !window.pageView().wireShown() && window.legendStrip().empty(), "wire off");

        // I again hides the panel.
        driver.press(KeyEvent.VK_I);
        driver.awaitEdt(() -> !window.inspectorPanel().isShown(), "the panel hidden");
        assertFalse(driver.onEdt(() -> window.inspectorPanel().component().isShowing()));
    }

    /**
     * J while stepping goes to the primitive that draws the pixel in the whole picture: at step 1 the centre
     * shows the first triangle, which the second (nearer, drawn next) covers in the end. Stepped back to 1
     * again, a pixel that no primitive draws leaves the step where it was.
     */
    @Test
    void jWhileSteppingGoesToThePrimitiveOfTheWholePicture() throws Exception {
        Path scene = dir.resolve("steps.simp");
        Files.writeString(scene, "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\n"
                + "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n"
                + "polygon (60, 60, -50) (60, 90, -50) (90, 60, -50)\n");
        SimpviewWindow window = openWindowOn(scene);
        driver.onEdt(() -> window.goToPixel("325, 325"));
        driver.press(KeyEvent.VK_I);
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().startsWith("primitive 1 of 3"),
                "the first step");
        // The panel's history is the whole drawing's (the owner is primitive 2), its vertices the stepped one's.
        driver.awaitEdt(() -> window.inspectorPanel().answered()
                && window.inspectorPanel().text().contains("vertices of primitive 1:"), "the stepped primitive's vertices");
        String panel = driver.onEdt(() -> window.inspectorPanel().text());
        assertTrue(panel.contains("The vertices below are primitive 1's, the one stepped to."), panel);
        assertTrue(panel.contains("drawn by primitive 2: steps.simp:2"), panel);
        driver.press(KeyEvent.VK_J);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().startsWith("primitive 2 of 3, steps.simp:2"),
                "stepping to the pinned pixel's primitive in the whole picture");

        driver.press(KeyEvent.VK_OPEN_BRACKET);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().startsWith("primitive 1 of 3"),
                "back to the first step");
        driver.onEdt(() -> window.goToPixel("5, 640"));
        driver.press(KeyEvent.VK_J);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().equals("No primitive draws the pinned "
                + "pixel in the whole picture: nothing to step to. Back at primitive 1."), "no primitive to step to");
        assertEquals(1, (int) driver.onEdt(() -> window.stepLimit()), "the step is where it was");
        // Not stepping: the owner's vertices again.
        driver.press(KeyEvent.VK_BACK_SLASH);
        driver.onEdt(() -> window.goToPixel("325, 325"));
        driver.awaitEdt(() -> !window.busy() && window.inspectorPanel().answered()
                && window.inspectorPanel().text().contains("vertices of primitive 2:"), "the owner's vertices");
    }

    /**
     * J while stepping with no pixel pinned and the pointer off the picture (here over the status strip): there is
     * no pixel to look for, and the words say so and what to do, not that no primitive draws "the pixel under the
     * pointer". The step stays where it was.
     */
    @Test
    void jWithThePointerOffThePictureSaysThereIsNoPixel() throws Exception {
        Path scene = dir.resolve("off.simp");
        Files.writeString(scene, "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\n"
                + "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        SimpviewWindow window = openWindowOn(scene);
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().startsWith("primitive 1 of 2"),
                "the first step");
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.robot().mouseMove(centre.x, centre.y);
        driver.awaitEdt(() -> window.status().inspectorText().startsWith("x 325, y 324"), "the inspector on the centre");
        Point strip = driver.onEdt(() -> {
            Point corner = window.status().component().getLocationOnScreen();
            return new Point(corner.x + window.status().component().getWidth() / 2,
                    corner.y + window.status().component().getHeight() / 2);
        });
        driver.robot().mouseMove(strip.x, strip.y);
        driver.awaitEdt(() -> !window.status().inspectorText().startsWith("x "), "the pointer off the picture");
        driver.press(KeyEvent.VK_J);
        driver.awaitEdt(() -> !window.busy() && window.status().messageText().startsWith("There is no pixel under"),
                "the words for no pixel");
        assertEquals("There is no pixel under the pointer: point at the picture, or pin a pixel (P, or Shift+G for its "
                + "coordinates), then press J.", driver.onEdt(() -> window.status().messageText()));
        assertEquals(1, (int) driver.onEdt(() -> window.stepLimit()), "the step is where it was");
    }

    private static JTextArea textArea(SimpviewWindow window) {
        return (JTextArea) ((JScrollPane) window.inspectorPanel().component()).getViewport().getView();
    }

    /** G in a scene that draws nothing says so; it asked "Go to primitive (1 to 0)" in a dialog. */
    @Test
    void goToAPrimitiveInASceneWithNoneSaysThereIsNone() throws Exception {
        Path scene = dir.resolve("empty.simp");
        Files.writeString(scene, "# nothing yet\n");
        SimpviewWindow window = openWindowOn(scene);
        driver.press(KeyEvent.VK_G);
        driver.awaitEdt(() -> window.status().messageText().equals(
                "There is no primitive to go to: this picture has none."), "the words for a picture of no primitives");
    }
}
