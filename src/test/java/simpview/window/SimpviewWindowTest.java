package simpview.window;

import simpview.testing.Images;
import simpview.scene.simp.SceneDrawer;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.Setting;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.Assignment2;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;

/** The real window under a real X server (Xvfb), driven with java.awt.Robot. */
public class SimpviewWindowTest extends WindowTestCase {

    private static final long SEED = 361;

    private WindowDriver open(Path simpDir, SceneDrawer drawer) throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, simpDir, Optional.empty()), drawer);
        return driver;
    }

    @Test
    void pageIsShownAtOneToOne() throws Exception {
        open(TestScenes.courseSimpDir(), SceneDrawer.SIMP);
        assertTrue(driver.onEdt(() -> driver.window().frame().getGraphicsConfiguration().getDefaultTransform().isIdentity()),
                "this X server scales the desktop; the window tests assume it does not");
        int room = driver.onEdt(() -> Math.min(driver.window().pageView().getWidth(), driver.window().pageView().getHeight()));
        double zoom = driver.onEdt(() -> driver.window().pageView().zoomPan().zoom());
        if (room >= PageCanvas.SIZE) {
            // Xvfb's default 1280x1024 screen has room for the page at 1:1, so that is how it opens.
            assertEquals(1.0, zoom);
        } else if (room >= PageCanvas.PANEL) {
            // A small screen (xvfb-run -s '-screen 0 1366x768x24'): the panel at 1:1, its margins cropped.
            assertEquals(1.0, zoom);
            assertTrue(driver.onEdt(() -> driver.window().status().inspectorText()).contains("1:1, margins cropped"));
        } else {
            assertEquals(room / (double) PageCanvas.PANEL, zoom, 1e-9);
            assertTrue(driver.onEdt(() -> driver.window().status().inspectorText()).contains("below 1:1"));
        }
        assertEquals(0, driver.screenDiffersFrom(driver.onEdt(() -> driver.window().shown()).image()), "the page on screen");
        assertEquals("simpview — page 1/8: Wireframe mesh (lerp) — seed 361",
                driver.onEdt(() -> driver.window().frame().getTitle()));
    }

    @Test
    void clickingStepsThroughAllPagesAndEachMatchesTheHeadlessRender() throws Exception {
        // The window's messages name settings as the command line that opens it does, by option (--simp-dir).
        SceneMonitor byOption = new SceneMonitor() {
            @Override
            public String nameOf(Setting setting) {
                return setting.option();
            }
        };
        PageContext context = PageContext.defaults().withSeed(SEED).withSimpDir(TestScenes.courseSimpDir())
                .withMonitor(byOption);
        open(context.simpDir(), SceneDrawer.SIMP);
        PageRenderer headless = new PageRenderer();
        for (int page = 1; page <= Assignment2.COUNT; page++) {
            RenderedView shown = driver.awaitShown(new View.OfPage(page));
            try {
                BufferedImage expected = headless.renderImage(page, context);
                assertNull(shown.error(), "page " + page);
                assertEquals(0, driver.screenDiffersFrom(expected), "pixels differing on page " + page);
            } catch (SceneException e) {
                // The page fails headless too: the window must show the same message over the page.
                assertEquals(e.getMessage(), shown.error(), "page " + page);
                assertEquals(e.getMessage(), driver.onEdt(() -> driver.window().pageView().error()));
            }
            driver.clickPage();
        }
        driver.awaitShown(new View.OfPage(1));
        assertEquals(0, driver.screenDiffersFrom(headless.renderImage(1, context)), "after page 8 comes page 1");
    }

    @Test
    void keysStepJumpAndWrapAround() throws Exception {
        open(TestScenes.courseSimpDir(), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_END);
        driver.awaitShown(new View.OfPage(8));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(1));
        driver.press(KeyEvent.VK_LEFT);
        driver.awaitShown(new View.OfPage(8));
        driver.press(KeyEvent.VK_HOME);
        driver.awaitShown(new View.OfPage(1));
        driver.press(KeyEvent.VK_5);
        driver.awaitShown(new View.OfPage(5));
        driver.press(KeyEvent.VK_SPACE);
        driver.awaitShown(new View.OfPage(6));
        driver.press(KeyEvent.VK_PAGE_UP);
        driver.awaitShown(new View.OfPage(5));
        driver.press(KeyEvent.VK_PAGE_DOWN);
        driver.awaitShown(new View.OfPage(6));
        driver.press(KeyEvent.VK_3);
        RenderedView three = driver.awaitShown(new View.OfPage(3));
        assertEquals("simpview — page 3/8: Z-buffer — seed 361", driver.onEdt(() -> driver.window().frame().getTitle()));
        BufferedImage expected = new PageRenderer().renderImage(3, PageContext.defaults().withSeed(SEED));
        assertEquals(0, Images.differingPixels(expected, three.image()));
    }

    @Test
    void newSeedRedrawsTheSeededPageWithTheSeedInTheTitle() throws Exception {
        open(TestScenes.courseSimpDir(), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_R);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().shown().seed() != SEED, "a new seed");
        RenderedView shown = driver.awaitShown(new View.OfPage(2));
        long seed = shown.seed();
        assertTrue(driver.onEdt(() -> driver.window().frame().getTitle()).endsWith("— seed " + seed));
        BufferedImage expected = new PageRenderer().renderImage(2, PageContext.defaults().withSeed(seed));
        assertEquals(0, driver.screenDiffersFrom(expected), "pixels differing from page 2 with seed " + seed);
    }

    @Test
    void sceneErrorsShowOverThePageWhileOtherPagesStillRender() throws Exception {
        Path bad = Files.writeString(dir.resolve("page6.simp"), "line (-50, -50, -10) (50, 50, -10)\nrotate x 30\n");
        open(dir, SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));

        driver.press(KeyEvent.VK_6);
        RenderedView six = driver.awaitShown(new View.OfPage(6));
        assertTrue(six.error() != null && six.error().contains(bad.toString()), "names the file: " + six.error());
        assertTrue(six.error().contains(bad + ":2:8"), "file:line:col of the bad axis: " + six.error());
        // The overlay is on screen: the capture differs from the page as drawn, at the bottom only
        // (compared at 1:1; on a screen too small for it, the page is scaled and the overlay only checked to show).
        if (driver.onEdt(() -> driver.window().pageView().zoomPan().zoom()) == 1) {
            BufferedImage shown = driver.shownPart(six.image()); // the whole page, or its panel on a small screen
            int half = shown.getHeight() / 2;
            BufferedImage screen = driver.captureWhen(capture -> Images.differingPixels(shown, capture, 0, half) == 0);
            if (Images.differingPixels(shown, screen, 0, half) != 0) {
                driver.keepEvidence("overlay", screen);
            }
            assertTrue(Images.differingPixels(shown, screen) > 1000, "overlay visible");
            assertEquals(0, Images.differingPixels(shown, screen, 0, half), "top half as drawn");
        } else {
            assertTrue(driver.screenDiffersFrom(six.image()) > 1000, "overlay visible");
        }

        driver.press(KeyEvent.VK_RIGHT);
        RenderedView seven = driver.awaitShown(new View.OfPage(7));
        assertTrue(seven.error().contains("page7.simp was not found in " + dir.toAbsolutePath().normalize()),
                "names the file and the folder: " + seven.error());

        driver.press(KeyEvent.VK_1);
        RenderedView one = driver.awaitShown(new View.OfPage(1));
        assertNull(one.error());
        assertNull(driver.onEdt(() -> driver.window().pageView().error()));
        BufferedImage expected = new PageRenderer().renderImage(1, PageContext.defaults().withSeed(SEED));
        assertEquals(0, driver.screenDiffersFrom(expected), "page 1 renders cleanly after the errors");
    }

    @Test
    void anOpenedSceneIsAnExtraViewAndSteppingReturnsToThePages() throws Exception {
        Path scene = StandInDrawers.sceneFile(dir, "diagonal.simp");
        open(TestScenes.courseSimpDir(), StandInDrawers.DIAGONAL);
        driver.onEdt(() -> driver.window().openScene(scene));
        RenderedView shown = driver.awaitShown(new View.OfScene(scene));
        assertNull(shown.error());
        assertEquals("simpview — scene: diagonal.simp", driver.onEdt(() -> driver.window().frame().getTitle()));
        int margin = PageCanvas.MARGIN;
        assertEquals(0xFFFFFF, shown.image().getRGB(margin + 10, PageCanvas.SIZE - margin - 11) & 0xFFFFFF, "diagonal drawn");
        assertEquals(0, driver.screenDiffersFrom(shown.image()));

        driver.clickPage();
        driver.awaitShown(new View.OfPage(2));
    }

    @Test
    void aSceneGivenAtStartIsWhatTheWindowShowsFirst() throws Exception {
        Path scene = StandInDrawers.sceneFile(dir, "start.simp");
        driver = WindowDriver.open(new WindowOptions(SEED, dir, Optional.of(scene)), StandInDrawers.DIAGONAL);
        assertEquals("simpview — scene: start.simp", driver.onEdt(() -> driver.window().frame().getTitle()));
        // A scene is an extra view: stepping on from it goes to the pages, from page 1.
        driver.clickPage();
        driver.awaitShown(new View.OfPage(2));
    }

    /** A step asked for while the scene given at start is still drawing overtakes it, as any newer request does. */
    @Test
    void aStepWhileTheSceneGivenAtStartDrawsOvertakesIt() throws Exception {
        Path scene = StandInDrawers.sceneFile(dir, "endless.simp");
        driver = WindowDriver.openWhileDrawing(new WindowOptions(SEED, dir, Optional.of(scene)),
                StandInDrawers.UNTIL_CANCELLED);
        SimpviewWindow window = driver.window();
        driver.awaitEdt(() -> window.status().showingProgress() && window.linesReadSoFar() > 0, "the scene's progress");
        assertNull(driver.onEdt(window::shown), "nothing shown while the scene draws");

        driver.clickPage();
        driver.awaitShown(new View.OfPage(2));
        assertFalse(driver.onEdt(window::busy), "still drawing after page 2 was shown");
        assertFalse(driver.onEdt(() -> window.status().animating()), "the progress bar still animating");
        assertNull(driver.onEdt(window::shown).error());
        BufferedImage page2 = new PageRenderer().renderImage(2, PageContext.defaults().withSeed(SEED));
        assertEquals(0, driver.screenDiffersFrom(page2), "pixels differing from page 2");
    }
}
