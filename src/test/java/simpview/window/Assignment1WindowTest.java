package simpview.window;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import simpview.pages.A1Lines;
import simpview.pages.A1Marks;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.scene.simp.SceneDrawer;
import simpview.surface.PageCanvas;
import simpview.testing.Images;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * A switches the window to the first assignment's five pages and back; the
 * keys step within them; stepping draws them line by line (triangle by
 * triangle), every panel together; the magnifier shows the line under the
 * pointer as given and between its rounded ends.
 */
public class Assignment1WindowTest extends WindowTestCase {

    private static final long SEED = 361;

    /**
     * A picture of the first assignment's page dropped on the window is not taken for one 650x650 panel with a
     * pixel of slack (what the window compares on the eight pages): the status says so and gives the command that
     * compares it panel by panel as the window would draw it: the page its name names (else the page on screen,
     * else N), with the window's seed and rule as compare takes them, wherever the window is.
     */
    @Test
    void aFirstAssignmentPictureDroppedIsSentToCompareAssignment1() throws Exception {
        long seed = 7;
        driver = WindowDriver.open(new WindowOptions(seed, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_1);
        driver.awaitShown(new View.OfPage(1));
        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_R);
        driver.awaitEdt(() -> driver.window().status().text().contains(A1Rule.COURSE.label()), "the course's rule");
        BufferedImage page3 = Assignment1.render(3, PageContext.defaults().withSeed(seed).withA1Rule(A1Rule.COURSE));
        Path named = dir.resolve("a1-page3.png");
        ImageIO.write(page3, "png", named.toFile());
        Path unnamed = dir.resolve("mine.png");
        ImageIO.write(page3, "png", unnamed.toFile());
        String sent = " is a page of the first assignment (four 300x300 panels), not a page of one 650x650 panel: its "
                + "panels are compared one by one, without slack, by simpview compare ";
        // on the eight pages: the page its name names, else N (the seed, as N may be a page drawn from it)
        assertSays(named, named.getFileName() + sent + named + " --assignment 1 --page 3 --seed 7 --a1-rule course");
        assertSays(unnamed, unnamed.getFileName() + sent + unnamed + " --assignment 1 --page N --seed 7 --a1-rule course");
        // on another page of the first assignment: the page its name names, else the page on screen
        driver.press(KeyEvent.VK_A);
        driver.awaitShown(new View.OfAssignment1Page(1));
        assertSays(named, named.getFileName() + sent + named + " --assignment 1 --page 3 --seed 7 --a1-rule course");
        assertSays(unnamed, unnamed.getFileName() + sent + unnamed + " --assignment 1 --page 1 --a1-rule course");
        assertTrue(driver.onEdt(() -> driver.window().comparison().comparison()) == null, "nothing is compared");
    }

    /** Drops {@code picture} on the window and waits for the status to say {@code said}. */
    private void assertSays(Path picture, String said) throws Exception {
        driver.onEdt(() -> driver.window().status().say("")); // the same words said again are waited for
        assertTrue(DroppedFiles.dropOn(driver, picture), "the window took the dropped picture");
        driver.awaitEdt(() -> driver.window().status().text().equals(said), "the status says: " + said);
    }

    @Test
    void aSwitchesAssignmentAndTheKeysStepWithinIt() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_A);
        RenderedView first = driver.awaitShown(new View.OfAssignment1Page(1));
        assertEquals("simpview — assignment 1, page 1/5: Starburst", driver.onEdt(() -> driver.window().frame().getTitle()));
        assertEquals(0, Images.differingPixels(Assignment1.render(1, PageContext.defaults().withSeed(SEED)), first.image()));
        assertEquals(0, driver.screenDiffersFrom(first.image()), "the page on screen");
        // Shift+R: the course's pictures' rule, and back to SPEC's.
        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_R);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().shown().a1Rule() == A1Rule.COURSE,
                "page 1 drawn by the course's rule");
        driver.settle();
        RenderedView course = driver.onEdt(driver.window()::shown);
        assertEquals("simpview — assignment 1, page 1/5: Starburst — the course's pictures' rule",
                driver.onEdt(() -> driver.window().frame().getTitle()));
        assertEquals(0, Images.differingPixels(
                Assignment1.render(1, PageContext.defaults().withSeed(SEED).withA1Rule(A1Rule.COURSE)), course.image()));
        assertTrue(Images.differingPixels(first.image(), course.image()) > 100, "the Bresenham panels differ");
        assertEquals(0, driver.screenDiffersFrom(course.image()), "the page on screen");
        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_R);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().shown().a1Rule() == A1Rule.SPEC,
                "page 1 drawn by SPEC's rule again");
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
        driver.press(KeyEvent.VK_4);
        driver.awaitShown(new View.OfAssignment1Page(4));
        // D and K are a scene's: here they say so, and the page stays as drawn
        driver.press(KeyEvent.VK_D);
        driver.awaitEdt(() -> driver.window().status().messageText().startsWith(
                "The first assignment's pages have no depths to show"), "D refused on a first-assignment page");
        driver.press(KeyEvent.VK_K);
        driver.awaitEdt(() -> driver.window().status().messageText().startsWith("Back faces are a scene's"),
                "K refused on a first-assignment page");
        assertEquals(0, driver.screenDiffersFrom(driver.onEdt(driver.window()::shown).image()), "the page on screen");
        // Back to the eight pages, where the window left them, and to the first assignment's where it left those.
        driver.press(KeyEvent.VK_A);
        driver.awaitShown(new View.OfPage(2));
        driver.press(KeyEvent.VK_A);
        driver.awaitShown(new View.OfAssignment1Page(4));
        driver.press(KeyEvent.VK_A);
        driver.awaitShown(new View.OfPage(2));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(3));
    }

    /** Page 1 drawn with every panel's first n lines, as the window should show it while stepping. */
    private static BufferedImage firstLines(int page, int n) {
        PageCanvas canvas = new PageCanvas();
        Assignment1.page(page).drawSteps(canvas, PageContext.defaults().withSeed(SEED), n);
        return canvas.image();
    }

    @Test
    void steppingGoesLineByLineInEveryPanelAndTheMagnifierShowsTheLineAsGiven() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_A);
        RenderedView whole = driver.awaitShown(new View.OfAssignment1Page(1));

        // ]: the first spoke in all four panels, named with its ends as given and rounded, marked over the page.
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !driver.window().busy()
                && driver.window().status().messageText().startsWith("line 1 of 90, (150, 150) to (285, 150), rounded"),
                "stepping at line 1: " + driver.onEdt(() -> driver.window().status().messageText()));
        assertEquals(0, Images.differingPixels(firstLines(1, 1), driver.onEdt(() -> driver.window().shown().image())));
        A1Marks marks = driver.onEdt(() -> driver.window().pageView().marks());
        assertEquals(16, marks.given().length, "one segment in each of the four panels");
        // Panel 2's: pixel centres at integer panel coordinates, rows down in the image.
        assertArrayEquals(new double[] {400 + 150.5, 50 + 299.5 - 150, 400 + 285.5, 50 + 299.5 - 150},
                Arrays.copyOfRange(marks.given(), 4, 8), 1e-9);
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().status().messageText().startsWith("line 2 of 90"),
                "stepping at line 2");
        assertEquals(0, Images.differingPixels(firstLines(1, 2), driver.onEdt(() -> driver.window().shown().image())));
        assertTrue(driver.onEdt(() -> driver.window().status().messageText()).contains("panel 3 by the Bresenham"));
        driver.press(KeyEvent.VK_BACK_SLASH);
        driver.awaitEdt(() -> !driver.window().busy()
                && Images.differingPixels(whole.image(), driver.window().shown().image()) == 0
                && driver.window().pageView().marks().isEmpty(), "the whole page again, unmarked");

        // The magnifier (8x): the 92-degree spoke's pixel at column 145, row 279 of the Bresenham panel.
        int ix = 400 + 145;
        int iy = 50 + 299 - 279;
        Point at = driver.onScreen(ix, iy);
        Point corner = driver.onEdt(() -> driver.window().pageView().getLocationOnScreen());
        driver.onEdt(() -> driver.window().pageView().zoomPan().zoomAbout(at.x - corner.x, at.y - corner.y, 8));
        Point pixel = driver.onScreen(ix, iy);
        driver.robot().mouseMove(pixel.x, pixel.y);
        driver.awaitEdt(() -> driver.window().pageView().marks().given().length == 4, "the magnifier's line");
        A1Marks spoke = driver.onEdt(() -> driver.window().pageView().marks());
        double ex = 150 + 135 * Math.cos(23 * A1Lines.STEP);
        double ey = 150 + 135 * Math.sin(23 * A1Lines.STEP);
        assertArrayEquals(new double[] {400 + 150.5, 50 + 299.5 - 150, 400 + ex + 0.5, 50 + 299.5 - ey},
                spoke.given(), 1e-9, "as given");
        assertArrayEquals(new double[] {400 + 150.5, 50 + 299.5 - 150, 400 + 145.5, 50 + 299.5 - 285},
                spoke.rounded(), 1e-9, "between the rounded ends");
        assertTrue(driver.onEdt(() -> driver.window().status().inspectorText()).contains("line 24 of 90"));
        assertEquals(0, Images.differingPixels(whole.image(), driver.onEdt(() -> driver.window().pageView().image())),
                "the marks are an overlay: the page's pixels are unchanged");
        // J: step to the line under the pointer.
        driver.press(KeyEvent.VK_J);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().status().messageText().startsWith("line 24 of 90"),
                "stepped to line 24");
        assertEquals(0, Images.differingPixels(firstLines(1, 24), driver.onEdt(() -> driver.window().shown().image())));
    }

    @Test
    void thePolygonPagesStepTriangleByTriangle() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_A);
        driver.awaitShown(new View.OfAssignment1Page(1));
        driver.press(KeyEvent.VK_5);
        driver.awaitShown(new View.OfAssignment1Page(5));
        for (int i = 0; i < 3; i++) {
            driver.press(KeyEvent.VK_CLOSE_BRACKET);
        }
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().status().messageText().startsWith(
                "triangle 3: panel 1, 3 of 90; panel 2, 3 of 162; panel 3, 3 of 162; panel 4, 3 of 20"),
                "stepping at triangle 3: " + driver.onEdt(() -> driver.window().status().messageText()));
        assertEquals(0, Images.differingPixels(firstLines(5, 3), driver.onEdt(() -> driver.window().shown().image())));
        assertEquals(4, driver.onEdt(() -> driver.window().pageView().marks().outlines().size()), "each panel's third triangle");
        // A hundred on: panels 1 and 4 are whole (90 and 20 triangles), 2 and 3 at their 103rd.
        driver.pressWithControl(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().status().messageText().startsWith("triangle 103:"),
                "stepping at triangle 103");
        assertTrue(driver.onEdt(() -> driver.window().status().messageText())
                .startsWith("triangle 103: panel 1 whole (90); panel 2, 103 of 162; panel 3, 103 of 162; panel 4 whole (20)"));
        assertEquals(2, driver.onEdt(() -> driver.window().pageView().marks().outlines().size()));
    }
}
