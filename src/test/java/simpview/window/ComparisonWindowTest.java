package simpview.window;

import simpview.scene.simp.SceneDrawer;
import simpview.window.instruments.ComparisonLayer;
import simpview.window.instruments.Inspector;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import simpview.compare.Comparison;
import simpview.compare.DiffRegions;
import simpview.compare.HeatMap;
import simpview.compare.Percent;
import simpview.compare.Picture;
import simpview.compare.WorstPixel;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import java.awt.Point;

/** Compare mode in the real window under Xvfb: drop a picture, flip with B, heat map with H, stop with Backspace. */
public class ComparisonWindowTest extends WindowTestCase {

    private static final long SEED = 361;

    /** Page 1 with a cyan square on it, as a window capture: 872x782, panel at (51, 81). */
    private Path theirPicture(BufferedImage page) throws Exception {
        BufferedImage capture = new BufferedImage(872, 782, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 782; y++) {
            for (int x = 0; x < 872; x++) {
                capture.setRGB(x, y, x < 751 && y > 30 ? 0xFFFFFF : 0xF0F0F0);
            }
        }
        for (int y = 0; y < 650; y++) {
            for (int x = 0; x < 650; x++) {
                boolean square = x >= 300 && x < 400 && y >= 300 && y < 400;
                capture.setRGB(51 + x, 81 + y, square ? 0x00FFFF : page.getRGB(50 + x, 50 + y));
            }
        }
        Path file = dir.resolve("mine.png");
        ImageIO.write(capture, "png", file.toFile());
        return file;
    }

    private void drop(Path file) throws Exception {
        assertTrue(DroppedFiles.dropOn(driver, file), "the window took the dropped picture");
    }

    @Test
    void aDroppedPictureIsComparedFlippedAndShownAsAHeatMap() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_1);
        driver.awaitShown(new View.OfPage(1));
        BufferedImage ours = new PageRenderer().renderImage(1, PageContext.defaults().withSeed(SEED));
        Path mine = theirPicture(ours);

        drop(mine);
        Comparison expected = Comparison.of(Picture.ofPage(ours, "ours").panel(), Picture.read(mine).panel());
        driver.awaitEdt(() -> driver.window().status().text().startsWith("vs mine.png"), "the comparison made");
        String status = driver.onEdt(() -> driver.window().status().text());
        assertTrue(status.startsWith("vs mine.png: identical " + Percent.of(expected.share(0, true))), status);
        assertTrue(status.contains("≤8/255 " + Percent.of(expected.share(8, true))), status);
        assertTrue(expected.share(0, true) < 0.99, "the square differs");
        // It fails: the status names the pixel to look at first, the one that differs most in the square.
        WorstPixel look = WorstPixel.in(expected, DiffRegions.of(expected, 8, 1).largest().get(0), 8);
        assertTrue(look.x() >= 300 && look.x() < 400 && look.y() >= 250 && look.y() < 350, look.toString());
        assertTrue(status.contains(" · look at x " + look.x() + ", y " + look.y() + " · showing ours"), status);
        assertEquals(0, driver.screenDiffersFrom(ours), "ours first");
        // The inspector shows both pictures at the pixel: in the square, ours and their cyan.
        Point inSquare = driver.onScreen(50 + 350, 50 + 350);
        driver.robot().mouseMove(inSquare.x, inSquare.y);
        String ourPixel = Inspector.rgb(ours.getRGB(400, 400));
        driver.awaitEdt(() -> driver.window().status().inspectorText().contains("rgb")
                && driver.window().status().inspectorText().contains(" · theirs rgb 0 255 255"), "both pictures' values");
        assertTrue(driver.onEdt(() -> driver.window().status().inspectorText()).contains(ourPixel));
        driver.robot().mouseMove(1, 1);
        // Compare's dialog opens in the pages' folder here (the shown scene's folder for a scene).
        assertEquals(TestScenes.courseSimpDir(), driver.onEdt(() -> driver.window().dialogFolder()));

        driver.press(KeyEvent.VK_B);
        assertEquals(ComparisonLayer.Showing.THEIRS, driver.onEdt(() -> driver.window().comparison().showing()));
        assertEquals(0, driver.screenDiffersFrom(HeatMap.asPage(Picture.read(mine).panel())), "theirs after B");
        driver.press(KeyEvent.VK_B);
        assertEquals(0, driver.screenDiffersFrom(ours), "ours after B again");

        driver.press(KeyEvent.VK_H);
        int[] heat = new int[Comparison.N * Comparison.N];
        HeatMap.fill(expected, 8, heat);
        BufferedImage heatPage = HeatMap.asPage(heat);
        assertEquals(0, driver.screenDiffersFrom(heatPage), "the heat map after H");
        assertEquals(0xFF0000, heatPage.getRGB(50 + 350, 50 + 350) & 0xFF0000, "the square is red on it");
        assertTrue(driver.onEdt(() -> driver.window().status().text()).contains("showing heat"));
        String legend = driver.onEdt(() -> driver.window().legendStrip().isShowing() ? driver.window().legendStrip().text() : "");
        assertTrue(legend.startsWith("heat map") && legend.contains("#0000a0 within 8/255")
                && legend.contains("#d0d000 only 1 px off"), legend);

        // The comparison stays with page 1: away and back, it is still there.
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(2));
        assertEquals("", driver.onEdt(() -> driver.window().comparison().statusText()));
        driver.press(KeyEvent.VK_LEFT);
        driver.awaitShown(new View.OfPage(1));
        driver.awaitEdt(() -> driver.window().status().text().startsWith("vs mine.png"), "page 1 compared again");

        driver.press(KeyEvent.VK_BACK_SPACE);
        assertEquals(0, driver.screenDiffersFrom(ours), "ours once stopped");
        assertEquals("Stopped comparing.", driver.onEdt(() -> driver.window().status().text()));
        assertTrue(driver.onEdt(() -> driver.window().legendStrip().empty()), "no legend once stopped");
    }

    /**
     * A drag that turns the compared scene does not compare each of its frames (each would hold the event thread
     * for the search for a mistake of the whole panel); the traced frame after it is compared.
     */
    @Test
    void aTurningDragLeavesTheComparisonToTheFrameAfterIt() throws Exception {
        SimpviewWindow window = openWindowOn(litSquare());
        RenderedView unturned = driver.onEdt(() -> window.shown());
        drop(theirPicture(unturned.image()));
        driver.awaitEdt(() -> window.comparison().comparison() != null, "the dropped picture compared");
        Comparison before = driver.onEdt(() -> window.comparison().comparison());

        dragTurning(unturned, first -> {
            nextDragFrame(first);
            assertSame(before, driver.onEdt(() -> window.comparison().comparison()), "not compared during the drag");
        });
        driver.awaitEdt(() -> !window.busy() && window.shown().facts().owners() != null
                && window.comparison().comparison() != before, "the frame after the drag compared");
    }

    /** A picture whose panel is simpview's upside down is said to look so in the status line. */
    @Test
    void aPanelUpsideDownIsNamedInTheStatusLine() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.awaitShown(new View.OfPage(2));
        BufferedImage ours = new PageRenderer().renderImage(2, PageContext.defaults().withSeed(SEED));
        BufferedImage over = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                boolean panel = x >= 50 && x < 700 && y >= 50 && y < 700;
                over.setRGB(x, y, ours.getRGB(x, panel ? 749 - y : y));
            }
        }
        Path file = dir.resolve("over.png");
        ImageIO.write(over, "png", file.toFile());
        drop(file);
        driver.awaitEdt(() -> driver.window().status().text().startsWith("vs over.png: "), "the comparison made");
        String status = driver.onEdt(() -> driver.window().status().text());
        assertTrue(status.startsWith("vs over.png: ") && status.contains(" (1 px slack) · looks upside down · showing ours"),
                status);
    }

    @Test
    void aPictureWithoutAPanelIsRefusedInTheStatusLine() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        Path blank = dir.resolve("blank.png");
        ImageIO.write(new BufferedImage(800, 800, BufferedImage.TYPE_INT_RGB), "png", blank.toFile());
        drop(blank);
        driver.awaitEdt(() -> driver.window().status().text().startsWith("Cannot compare"), "the picture refused");
        String status = driver.onEdt(() -> driver.window().status().text());
        assertTrue(status.startsWith("Cannot compare: no 650x650 panel found in " + blank), status);
        assertEquals(null, driver.onEdt(() -> driver.window().comparison().comparison()));
    }
}
