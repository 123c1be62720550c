package simpview.window;

import simpview.testing.Images;
import simpview.scene.simp.SceneDrawer;
import simpview.window.instruments.DepthPicture;
import simpview.window.instruments.Inspector;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Insets;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import simpview.pages.ZBufferPage;
import simpview.surface.PageCanvas;
import java.awt.Component;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import java.awt.event.InputEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import simpview.scene.simp.SceneCancelledException;
import simpview.scene.simp.ScenePipeline;

/** The window's instruments under Xvfb, driven with java.awt.Robot: zoom, grid, inspector, depth view, reload. */
public class InstrumentsWindowTest extends WindowTestCase {

    private static final long SEED = 361;

    private WindowDriver open() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        return driver;
    }

    private SimpviewWindow window() {
        return driver.window();
    }

    @Test
    void theFrameFitsTheScreenAndAResizeKeepsThePageWhole() throws Exception {
        open();
        Rectangle usable = driver.onEdt(() -> {
            var screen = window().frame().getGraphicsConfiguration();
            Insets taken = Toolkit.getDefaultToolkit().getScreenInsets(screen);
            Rectangle b = screen.getBounds();
            return new Rectangle(b.x + taken.left, b.y + taken.top, b.width - taken.left - taken.right,
                    b.height - taken.top - taken.bottom);
        });
        Rectangle frame = driver.onEdt(() -> window().frame().getBounds());
        assertTrue(frame.width <= usable.width && frame.height <= usable.height, frame + " within " + usable);
        assertTrue(driver.onEdt(() -> window().frame().isResizable()));

        driver.onEdt(() -> window().frame().setSize(560, 480));
        driver.awaitEdt(() -> window().pageView().getHeight() < 480, "the smaller frame laid out");
        driver.settle();
        PageView view = window().pageView();
        ZoomPan zoomPan = view.zoomPan();
        int width = driver.onEdt(view::getWidth);
        int height = driver.onEdt(view::getHeight);
        // The panel (image 50 to 699) is whole in the view, scaled below 1:1; the white margins are cropped.
        double left = driver.onEdt(() -> zoomPan.screenX(PageCanvas.MARGIN));
        double top = driver.onEdt(() -> zoomPan.screenY(PageCanvas.MARGIN));
        double right = driver.onEdt(() -> zoomPan.screenX(PageCanvas.MARGIN + PageCanvas.PANEL));
        double bottom = driver.onEdt(() -> zoomPan.screenY(PageCanvas.MARGIN + PageCanvas.PANEL));
        assertTrue(left >= 0 && top >= 0 && right <= width + 1 && bottom <= height + 1,
                "the whole panel in the view: " + left + "," + top + " to " + right + "," + bottom + " in " + width + "x" + height);
        assertTrue(driver.onEdt(() -> zoomPan.cropped() && zoomPan.zoom() < 1));
        String said = driver.onEdt(() -> window().status().inspectorText());
        assertTrue(said.contains("below 1:1") && said.contains("margins cropped"), said);
        // On screen, exactly the picture the line-keeping filter makes (its lines whole), the margins gone.
        assertEquals(0, driver.screenDiffersFrom(driver.onEdt(() -> window().shown()).image()), "the scaled page on screen");
    }

    @Test
    void zoom8xShowsAGridLineBetweenTwoPixels() throws Exception {
        open();
        // Image pixels (52, 697) and (53, 697): panel (2, 2) and (3, 2), black on page 1 (the mesh keeps 10 px off the edge).
        Point at = driver.onScreen(52, 697);
        Point viewCorner = driver.onEdt(() -> window().pageView().getLocationOnScreen());
        driver.onEdt(() -> window().pageView().zoomPan().zoomAbout(at.x - viewCorner.x, at.y - viewCorner.y, 8));
        driver.onEdt(() -> window().pageView().repaint());
        driver.settle();
        Point left = driver.onScreen(52, 697);
        int lineX = left.x - 4 + 8; // the first screen column of pixel 53
        int y = left.y - 2;
        BufferedImage strip = driver.captureWhen(s -> true);
        assertEquals(8.0, driver.onEdt(() -> window().pageView().zoomPan().zoom()));
        int inside = driver.robot().getPixelColor(left.x - 2, y).getRGB() & 0xFFFFFF;
        int line = driver.robot().getPixelColor(lineX, y).getRGB() & 0xFFFFFF;
        int insideNext = driver.robot().getPixelColor(lineX + 2, y).getRGB() & 0xFFFFFF;
        assertEquals(0x000000, inside, "inside pixel 52 it is the page's black");
        assertEquals(0x000000, insideNext, "inside pixel 53 too");
        assertNotEquals(0x000000, line, "a grid line between them");
        assertEquals(PixelGrid.LINE.getRed() * PixelGrid.LINE.getAlpha() / 255, (line >> 16) & 0xFF, 2, "the grid's grey over black");
        assertNotNull(strip);
        assertEquals(0, Images.differingPixels(driver.onEdt(() -> window().shown()).image(),
                driver.onEdt(() -> window().pageView().image())), "the picture itself is unchanged");

        driver.onEdt(() -> window().pageView().zoomPan().zoomAbout(at.x - viewCorner.x, at.y - viewCorner.y, 4));
        driver.onEdt(() -> window().pageView().repaint());
        driver.settle();
        Point left4 = driver.onScreen(52, 697);
        assertEquals(0x000000, driver.robot().getPixelColor(left4.x - 2 + 4, left4.y).getRGB() & 0xFFFFFF,
                "no grid at 4x");
    }

    /** Page 2's mesh is drawn straight onto the panel: its pixels say no owner is recorded, not "background". */
    @Test
    void aPixelOfThePagesThatKeepNoOwnersIsNotCalledTheBackground() throws Exception {
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.awaitShown(new View.OfPage(2));
        driver.onEdt(() -> window().goToPixel("325, 325"));
        awaitInspector("drawn by: not recorded here");
        assertFalse(driver.onEdt(() -> window().status().inspectorText()).contains("background"));
        driver.onEdt(() -> window().perform(WindowAction.COPY_CHAIN));
        driver.awaitEdt(() -> window().status().messageText().startsWith("This page records no primitive"),
                "no chain to copy, and why");
    }

    @Test
    void hoveringAPixelOfPage3ShowsTheTrianglesColourDepthAndDrawingOrder() throws Exception {
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_3);
        RenderedView three = driver.awaitShown(new View.OfPage(3));
        // The panel's centre is inside all six triangles: the nearest one shows there.
        int px = PageCanvas.PANEL / 2;
        int py = PageCanvas.PANEL / 2;
        var triangles = ZBufferPage.triangles(SEED);
        int nearest = 0;
        for (int t = 1; t < triangles.length; t++) {
            if (triangles[t][0].z() > triangles[nearest][0].z()) {
                nearest = t;
            }
        }
        Point p = driver.onScreen(PageCanvas.MARGIN + px, PageCanvas.MARGIN + PageCanvas.PANEL - 1 - py);
        driver.movePointer(p.x, p.y);
        int grey = (int) Math.round(ZBufferPage.grey(nearest) * 255);
        String z = Inspector.number(triangles[nearest][0].z());
        // Scaled to fit on a small screen, the pointer may land a pixel off the centre: the same triangle is there.
        Pattern expected = Pattern.compile(
                "x (\\d+), y (\\d+) \\(image row \\d+\\) · rgb " + grey + " " + grey + " " + grey + " = .*");
        driver.awaitEdt(() -> expected.matcher(window().status().inspectorText()).matches(), "the inspector on the centre");
        String line = driver.onEdt(() -> window().status().inspectorText());
        Matcher at = expected.matcher(line);
        assertTrue(at.matches(), line);
        assertTrue(Math.abs(Integer.parseInt(at.group(1)) - px) <= 2 && Math.abs(Integer.parseInt(at.group(2)) - py) <= 2, line);
        assertTrue(line.contains("depth " + z), line);
        assertTrue(line.contains("drawn by primitive " + (nearest + 1) + " of 6"), line);
        assertTrue(line.contains("triangle " + (nearest + 1) + " of 6"), line);
        assertNull(three.error());

        // Pinned, it stays when the pointer moves on.
        driver.press(KeyEvent.VK_P);
        driver.movePointer(p.x + 200, p.y + 200);
        String pinned = driver.onEdt(() -> window().status().inspectorText());
        assertEquals("pinned · " + line, pinned);
    }

    @Test
    void aZoomByKeyInspectsThePixelNowUnderTheStillPointer() throws Exception {
        open();
        Point p = driver.onScreen(200, 300);
        driver.movePointer(p.x, p.y);
        awaitInspector("x 150, y 399 (image row 300)");

        driver.onEdt(() -> window().perform(WindowAction.ZOOM_IN));
        Point now = driver.onEdt(() -> {
            Point corner = window().pageView().getLocationOnScreen();
            ZoomPan zoomPan = window().pageView().zoomPan();
            return new Point(zoomPan.imageX(p.x - corner.x), zoomPan.imageY(p.y - corner.y));
        });
        assertNotEquals(new Point(200, 300), now, "the zoom moved another pixel under the pointer");
        String expected = "x " + (now.x - PageCanvas.MARGIN) + ", y " + (PageCanvas.MARGIN + PageCanvas.PANEL - 1 - now.y)
                + " (image row " + now.y + ")";
        awaitInspector(expected);
    }

    @Test
    void theInspectorsLineKeepsTheLastPixelsWholeTextAsItsTooltipWhenThePointerGoesToReadIt() throws Exception {
        Path scene = Files.writeString(dir.resolve("a-scene-with-a-long-name.simp"), "# one\n" + triangleAt(-150));
        open();
        driver.onEdt(() -> window().openScene(scene));
        driver.awaitShown(new View.OfScene(scene));
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.movePointer(centre.x, centre.y);
        awaitInspector("drawn by primitive 1 of 1: a-scene-with-a-long-name.simp:2 polygon");
        String line = driver.onEdt(() -> window().status().inspectorText());
        assertEquals(line, driver.onEdt(() -> window().status().inspectorToolTip()));

        Point onTheLine = driver.onEdt(() -> {
            Component strip = window().status().component();
            Point corner = strip.getLocationOnScreen();
            return new Point(corner.x + strip.getWidth() / 2, corner.y + 10);
        });
        driver.movePointer(onTheLine.x, onTheLine.y);
        driver.awaitEdt(() -> !window().status().inspectorText().contains("drawn by"), "the hover to end");
        assertEquals("the last pixel inspected: " + line, driver.onEdt(() -> window().status().inspectorToolTip()));

        // another picture (the scene saved again): the last pixel's line was of the one before, and is forgotten
        Files.writeString(scene, "# one, moved\n" + triangleAt(-150));
        driver.awaitEdt(() -> window().status().inspectorToolTip() == null
                || !window().status().inspectorToolTip().startsWith("the last pixel inspected"),
                "the last pixel forgotten with its picture");
    }

    @Test
    void withoutThePanelCopyingTheChainCopiesTheOwnersOwnFileAndLine() throws Exception {
        Path scene = Files.writeString(dir.resolve("own.simp"), "# one\n" + triangleAt(-150));
        open();
        driver.onEdt(() -> window().openScene(scene));
        driver.awaitShown(new View.OfScene(scene));
        driver.onEdt(() -> window().goToPixel("325, 325"));
        driver.onEdt(() -> window().perform(WindowAction.COPY_CHAIN));
        String place = scene.toAbsolutePath() + ":2";
        driver.awaitEdt(() -> window().status().messageText().startsWith("Copied: " + place + " (with the panel open"),
                "the owner's place copied: " + place);
        assertEquals(place, Toolkit.getDefaultToolkit().getSystemClipboard()
                .getData(DataFlavor.stringFlavor));
    }

    @Test
    void withNoPixelInspectedTheCopiesSaySoAndLeaveTheClipboard() throws Exception {
        Path scene = Files.writeString(dir.resolve("own.simp"), "# one\n" + triangleAt(-150));
        open();
        driver.onEdt(() -> window().openScene(scene));
        driver.awaitShown(new View.OfScene(scene));
        driver.movePointer(1, 1); // off the window: no pixel under the pointer, and none pinned
        driver.awaitEdt(() -> !window().status().inspectorText().contains("rgb"), "no pixel inspected");
        StringSelection before = new StringSelection("the student's own copy");
        driver.onEdt(() -> Toolkit.getDefaultToolkit().getSystemClipboard().setContents(before, null));

        driver.onEdt(() -> window().perform(WindowAction.COPY));
        driver.awaitEdt(() -> window().status().messageText().startsWith("Nothing to copy: no pixel is inspected"),
                "Ctrl+C to say there is nothing to copy");
        driver.onEdt(() -> window().perform(WindowAction.COPY_CHAIN));
        driver.awaitEdt(() -> window().status().messageText().startsWith("No chain to copy: no pixel is inspected"),
                "Ctrl+Shift+C to say there is no pixel to copy the chain of");
        assertEquals("the student's own copy", Toolkit.getDefaultToolkit().getSystemClipboard()
                .getData(DataFlavor.stringFlavor));
    }

    @Test
    void unpinningTakesAwayTheLineThatSaidWhatWasPinned() throws Exception {
        open();
        // A pixel as the inspector writes it, in parentheses, is one too; half a pair of them is not.
        driver.onEdt(() -> window().goToPixel(" (3, 4) "));
        assertTrue(driver.onEdt(() -> window().status().messageText()).startsWith("Pinned panel pixel (3, 4)"));
        driver.onEdt(() -> window().goToPixel("(3, 4"));
        assertEquals("'(3, 4' is not a pixel: its '(' is not closed; give x and y, two whole numbers in panel "
                + "coordinates, for example 325,400 or (325, 400).", driver.onEdt(() -> window().status().messageText()));
        // read as inspect --at reads it: a number too large for an int is a place outside the panel
        driver.onEdt(() -> window().goToPixel("99999999999, 1"));
        assertEquals("'99999999999, 1' is outside the panel: x is 99999999999, and x and y are 0 to 649, from the "
                + "panel's bottom-left pixel, y up.", driver.onEdt(() -> window().status().messageText()));
        driver.onEdt(() -> window().goToPixel("0, 0"));
        assertTrue(driver.onEdt(() -> window().status().messageText()).startsWith("Pinned panel pixel (0, 0)"));
        driver.onEdt(() -> window().perform(WindowAction.PIN));
        assertEquals("Unpinned: the inspector follows the pointer again.",
                driver.onEdt(() -> window().status().messageText()));
        assertFalse(driver.onEdt(() -> window().status().inspectorText()).startsWith("pinned"));
    }

    @Test
    void theDepthViewShowsTheZBuffer() throws Exception {
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_4);
        RenderedView four = driver.awaitShown(new View.OfPage(4));
        driver.press(KeyEvent.VK_D);
        BufferedImage depths = DepthPicture.of(four.facts().depths(), four.facts().depthStart());
        assertEquals(0, driver.screenDiffersFrom(depths), "the depth view on screen");
        driver.press(KeyEvent.VK_D);
        assertEquals(0, driver.screenDiffersFrom(four.image()), "the page again");
    }

    @Test
    @Tag("timed")
    void editingAnOpenSceneFileChangesTheScreenWithinTwoSeconds() throws Exception {
        Path scene = dir.resolve("edit.simp");
        Files.writeString(scene, triangleAt(-150));
        open();
        driver.onEdt(() -> window().openScene(scene));
        RenderedView before = driver.awaitShown(new View.OfScene(scene));
        assertEquals(0, driver.screenDiffersFrom(before.image()));
        driver.onEdt(() -> window().pageView().zoomPan().zoomAbout(375, 375, 2));
        Files.writeString(scene, triangleAt(-50));
        long saved = System.nanoTime();
        driver.awaitEdt(() -> window().shown().image().getRGB(375, 375) != before.image().getRGB(375, 375),
                "the picture to change after the save");
        long millis = (System.nanoTime() - saved) / 1_000_000;
        assertTrue(millis < 2000, "redrawn " + millis + " ms after the save");
        assertEquals(2.0, driver.onEdt(() -> window().pageView().zoomPan().zoom()), "zoom kept");
        // z = -50: three quarters of the way from black to white.
        assertEquals(0xBFBFBF, driver.onEdt(() -> window().shown()).image().getRGB(375, 375) & 0xFFFFFF);

        Files.writeString(scene, "polygon (-50, -50, -50) (50, -50\n");
        driver.awaitEdt(() -> window().shown().error() != null, "the broken save's error");
        assertTrue(driver.onEdt(() -> window().frame().getTitle()).endsWith("— error"));
        Files.writeString(scene, triangleAt(-120));
        driver.awaitEdt(() -> window().shown().error() == null, "recovery on the next save");
        assertEquals(0x666666, driver.onEdt(() -> window().shown()).image().getRGB(375, 375) & 0xFFFFFF);
    }

    @Test
    @Tag("timed")
    void editingAFileTheSceneIncludesRedrawsItToo() throws Exception {
        Path part = dir.resolve("part.simp");
        Files.writeString(part, triangleAt(-150));
        Path scene = Files.writeString(dir.resolve("whole.simp"), "# includes part\nfile \"part\"\n");
        open();
        driver.onEdt(() -> window().openScene(scene));
        RenderedView before = driver.awaitShown(new View.OfScene(scene));
        assertEquals(List.of(scene, part), driver.onEdt(() -> window().watcher().watched()));
        Files.writeString(part, triangleAt(-50));
        long saved = System.nanoTime();
        driver.awaitEdt(() -> window().shown().image().getRGB(375, 375) != before.image().getRGB(375, 375),
                "the picture to change after the included file's save");
        assertTrue((System.nanoTime() - saved) / 1_000_000 < 2000, "within 2 s");
    }

    @Test
    void ownColoursShowAScenesVertexColours() throws Exception {
        Path scene = Files.writeString(dir.resolve("red.simp"),
                "polygon (-50, -50, -150) (1, 0, 0) (50, -50, -150) (1, 0, 0) (0, 50, -150) (1, 0, 0)\n");
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.onEdt(() -> window().openScene(scene));
        RenderedView cued = driver.awaitShown(new View.OfScene(scene));
        assertEquals(0x404040, cued.image().getRGB(375, 375) & 0xFFFFFF);
        driver.press(KeyEvent.VK_C);
        driver.awaitEdt(() -> !window().busy() && (window().shown().image().getRGB(375, 375) & 0xFFFFFF) == 0xFF0000,
                "the scene in its own red");
    }

    /**
     * C on a lit scene: SPEC Part 2 colours it by its lights and fog, own
     * colours or not, so the picture stays as it is, and the status line says
     * why instead of claiming the scene now shows its vertices' colours.
     */
    @Test
    void ownColoursOnALitSceneSayItStaysAsItIs() throws Exception {
        Path scene = Files.writeString(dir.resolve("lit-red.simp"), "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                + "polygon (-5, -5, -10, 0, 1, 0) (5, -5, -10, 0, 1, 0) (0, 5, -10, 0, 1, 0)\n");
        openWindowOn(scene);
        RenderedView lit = driver.onEdt(() -> window().shown());
        assertEquals(0x00FF00, lit.image().getRGB(375, 375) & 0xFFFFFF);
        driver.press(KeyEvent.VK_C);
        driver.awaitEdt(() -> window().status().messageText().contains("This scene is lit"),
                "the status line saying a lit scene stays as it is");
        assertEquals("Own colours: on for depth-cued scenes. This scene is lit (its camera, lights and fog make its "
                + "colours, SPEC Part 2), so it looks the same either way.",
                driver.onEdt(() -> window().status().messageText()));
        assertEquals(0, Images.differingPixels(lit.image(), driver.onEdt(() -> window().shown().image())));
    }

    /**
     * U on a scene whose one clipped-away triangle lies past the view's
     * top-left corner: its outline is off the panel, cut away with it, and
     * the status line says so rather than leaving "1 clipped-away primitive
     * outlined" over a panel that shows none.
     */
    @Test
    void theOutlinesOffThePanelAreNamedAsSuch() throws Exception {
        Path scene = Files.writeString(dir.resolve("corner.simp"), "camera -1 -1 1 1 -1 -50\nambient 1 1 1\n"
                + "polygon (-3, -3, -8) (3, -3, -8) (0, 3, -8)\n"
                + "polygon (-30, 9, -10) (-9, 30, -10) (-30, 30, -10)\n");
        openWindowOn(scene);
        driver.press(KeyEvent.VK_U);
        driver.awaitEdt(() -> window().skippedShown() != null, "the clipped-away outlines");
        assertEquals("0 culled and 1 clipped-away primitives outlined; 1 of them lies wholly outside the panel, "
                + "where the outlines are cut away · U: off", driver.onEdt(() -> window().status().messageText()));
    }

    @Test
    void aRightDragTurnsTheSceneAndTheResetKeyRestoresItBitForBit() throws Exception {
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.press(KeyEvent.VK_4);
        RenderedView four = driver.awaitShown(new View.OfPage(4));
        assertEquals(0, driver.screenDiffersFrom(four.image()), "page 4 as drawn");
        Point from = driver.onScreen(375, 375);
        var robot = driver.robot();
        robot.mouseMove(from.x, from.y);
        robot.mousePress(InputEvent.BUTTON3_DOWN_MASK);
        for (int k = 1; k <= 6; k++) {
            robot.mouseMove(from.x + 10 * k, from.y + 4 * k);
        }
        robot.mouseRelease(InputEvent.BUTTON3_DOWN_MASK);
        robot.mouseMove(1, 1);
        driver.awaitEdt(() -> !window().busy() && Images.differingPixels(four.image(), window().shown().image()) > 1000
                && window().shown().facts().owners() != null, "a turned picture, recorded again once the drag ended");
        assertEquals(new View.OfPage(4), driver.onEdt(() -> window().shown()).view(), "a right-drag does not step");
        BufferedImage turned = driver.onEdt(() -> window().shown()).image();
        assertEquals(0, driver.screenDiffersFrom(turned), "the turned page on screen");
        driver.press(KeyEvent.VK_O);
        driver.awaitEdt(() -> !window().busy() && Images.differingPixels(four.image(), window().shown().image()) == 0,
                "the unturned picture");
        assertEquals(0, driver.screenDiffersFrom(four.image()), "back bit for bit");
    }

    @Test
    void stepKeysShowTheDrawingPrimitiveByPrimitive() throws Exception {
        Path scene = Files.writeString(dir.resolve("three.simp"), "# three\n" + triangleAt(-150) + "\n"
                + "polygon (-90, -90, -50) (-20, -90, -50) (-55, -20, -50)\n" + "line (60, 60, -10) (90, 90, -10)\n");
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.onEdt(() -> window().openScene(scene));
        RenderedView all = driver.awaitShown(new View.OfScene(scene));
        assertEquals(3, all.facts().primitives().size());
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !window().busy() && window().status().messageText().startsWith("primitive 1 of 3, three.simp:2"),
                "stepping at primitive 1: " + driver.onEdt(() -> window().status().messageText()));
        RenderedView first = driver.onEdt(() -> window().shown());
        int centre = PageCanvas.SIZE / 2;
        assertEquals(all.image().getRGB(centre, centre), first.image().getRGB(centre, centre), "the first triangle drawn");
        Point corner = new Point(PageCanvas.MARGIN + 65, PageCanvas.MARGIN + PageCanvas.PANEL - 65);
        assertEquals(0xFF000000, first.image().getRGB(corner.x, corner.y), "the second not yet");
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !window().busy() && window().status().messageText().startsWith("primitive 2 of 3, three.simp:4"),
                "stepping at primitive 2");
        assertEquals(all.image().getRGB(corner.x, corner.y), driver.onEdt(() -> window().shown()).image().getRGB(corner.x, corner.y));
        driver.press(KeyEvent.VK_BACK_SLASH);
        driver.awaitEdt(() -> !window().busy() && Images.differingPixels(all.image(), window().shown().image()) == 0,
                "the whole picture again");
    }

    @Test
    void aSceneThatShrinksWhileSteppedIsSteppedAtItsLastPrimitiveAndStaysThereWhenItGrowsAgain() throws Exception {
        String four = "# four\n" + triangleAt(-150) + "polygon (-90, -90, -50) (-20, -90, -50) (-55, -20, -50)\n"
                + "polygon (20, 20, -50) (90, 20, -50) (55, 90, -50)\n" + "polygon (20, -90, -50) (90, -90, -50) (55, -20, -50)\n";
        Path scene = Files.writeString(dir.resolve("four.simp"), four);
        open();
        driver.onEdt(() -> window().openScene(scene));
        RenderedView all = driver.awaitShown(new View.OfScene(scene));
        assertEquals(4, all.facts().primitives().size());
        driver.onEdt(() -> window().perform(WindowAction.STEP_ON));
        driver.onEdt(() -> window().perform(WindowAction.STEP_ON));
        driver.awaitEdt(() -> !window().busy() && window().status().messageText().startsWith("primitive 2 of 4, four.simp:3"),
                "stepping at primitive 2");

        Files.writeString(scene, "# one\n" + triangleAt(-150));
        driver.awaitEdt(() -> !window().busy() && window().status().messageText().startsWith("primitive 1 of 1, four.simp:2"),
                "stepping at the one primitive left: " + driver.onEdt(() -> window().status().messageText()));
        assertTrue(driver.onEdt(() -> window().status().messageText()).contains("stepping was at 2"));

        Files.writeString(scene, four);
        driver.awaitEdt(() -> !window().busy() && window().shown().facts().primitives().size() == 4,
                "the four primitives again");
        assertTrue(driver.onEdt(() -> window().status().messageText()).startsWith("primitive 1 of 4, four.simp:2"),
                driver.onEdt(() -> window().status().messageText()));
        Point second = new Point(PageCanvas.MARGIN + 65, PageCanvas.MARGIN + PageCanvas.PANEL - 65);
        assertEquals(0xFF000000, driver.onEdt(() -> window().shown()).image().getRGB(second.x, second.y),
                "only the first primitive drawn, as the line says");

        // a save with a typo (one primitive read before it) leaves the step where it was for when it is mended
        driver.onEdt(() -> window().perform(WindowAction.STEP_ON));
        driver.onEdt(() -> window().perform(WindowAction.STEP_ON));
        driver.awaitEdt(() -> !window().busy() && window().status().messageText().startsWith("primitive 3 of 4"),
                "stepping at primitive 3");
        Files.writeString(scene, "# one\n" + triangleAt(-150) + "polygonx 1 2\n");
        driver.awaitEdt(() -> !window().busy() && window().shown().error() != null, "the typo's error shown");
        Files.writeString(scene, four);
        driver.awaitEdt(() -> !window().busy() && window().shown().error() == null
                && window().shown().facts().primitives().size() == 4, "the file mended");
        assertTrue(driver.onEdt(() -> window().status().messageText()).startsWith("primitive 3 of 4"),
                driver.onEdt(() -> window().status().messageText()));
    }

    @Test
    void aLitSceneIsInspectedSteppedAndTurnedLikeTheOthers() throws Exception {
        Path scene = Files.writeString(dir.resolve("lit.simp"), String.join("\n",
                "# a lit scene: a wall, and a square in front of it",
                "ambient 0.2 0.2 0.2",
                "camera -1 -1 1 1 -1 -100",
                "light 1 1 1 1 0",
                "surface 0.2 0.4 0.9",
                "polygon (-30, -30, -40) (30, -30, -40) (30, 30, -40)",
                "polygon (-30, -30, -40) (30, 30, -40) (-30, 30, -40)",
                "surface 0.9 0.5 0.1",
                "polygon (-3, -3, -10) (3, -3, -10) (3, 3, -10)",
                "polygon (-3, -3, -10) (3, 3, -10) (-3, 3, -10)", ""));
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.onEdt(() -> window().openScene(scene));
        RenderedView all = driver.awaitShown(new View.OfScene(scene));
        assertNull(all.error());
        assertEquals(4, all.facts().primitives().size());

        // The inspector names the command that drew the centre, and its camera-space depth.
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.robot().mouseMove(centre.x, centre.y);
        driver.awaitEdt(() -> window().status().inspectorText().contains("lit.simp:"), "the inspector on the square");
        String line = driver.onEdt(() -> window().status().inspectorText());
        assertTrue(line.matches(".*depth -10(\\.\\d+)? · drawn by primitive [34] of 4: lit.simp:(9|10) polygon .*"), line);

        // The depth view: the nearest depth white, the farthest black, the lit z-buffer's start untouched.
        driver.press(KeyEvent.VK_D);
        assertEquals(0, driver.screenDiffersFrom(DepthPicture.of(all.facts().depths(), Double.NEGATIVE_INFINITY)));
        driver.press(KeyEvent.VK_D);

        // Stepping: primitive 1 is half the wall, without the square in front.
        driver.press(KeyEvent.VK_CLOSE_BRACKET);
        driver.awaitEdt(() -> !window().busy() && window().status().messageText().startsWith("primitive 1 of 4, lit.simp:6"),
                "stepping at primitive 1: " + driver.onEdt(() -> window().status().messageText()));
        int mid = PageCanvas.SIZE / 2;
        assertNotEquals(all.image().getRGB(mid, mid), driver.onEdt(() -> window().shown()).image().getRGB(mid, mid),
                "the square not drawn yet");
        driver.press(KeyEvent.VK_BACK_SLASH);
        driver.awaitEdt(() -> !window().busy() && Images.differingPixels(all.image(), window().shown().image()) == 0,
                "the whole picture again");

        // A right-drag moves the camera about the scene; O puts it back bit for bit.
        driver.robot().mouseMove(centre.x, centre.y);
        driver.robot().mousePress(InputEvent.BUTTON3_DOWN_MASK);
        for (int k = 1; k <= 6; k++) {
            driver.robot().mouseMove(centre.x + 12 * k, centre.y + 3 * k);
        }
        driver.robot().mouseRelease(InputEvent.BUTTON3_DOWN_MASK);
        driver.awaitEdt(() -> !window().busy() && Images.differingPixels(all.image(), window().shown().image()) > 1000
                && window().shown().facts().owners() != null, "a turned picture, recorded again once the drag ended");
        assertTrue(driver.onEdt(() -> window().status().messageText()).startsWith("turned "));
        driver.press(KeyEvent.VK_O);
        driver.awaitEdt(() -> !window().busy() && Images.differingPixels(all.image(), window().shown().image()) == 0,
                "the unturned picture");
        assertEquals(0, driver.screenDiffersFrom(all.image()), "back bit for bit");
    }

    @Test
    void aDragsFramesKeepNoDepthsUnlessTheDepthViewShowsThem() throws Exception {
        Path scene = litSquare();
        open();
        driver.focusByClicking(new View.OfPage(2));
        driver.onEdt(() -> window().openScene(scene));
        RenderedView unturned = driver.awaitShown(new View.OfScene(scene));
        assertNotNull(unturned.facts().depths(), "a traced picture keeps its depths");

        // While the right button is held, the frames are neither traced nor given their depths...
        dragTurning(unturned, first -> {
            assertNull(first.facts().depths(), "a drag's frame without its depths");

            // ... until the depth view asks for them: the frame is drawn again, with them, and shown as depths.
            driver.press(KeyEvent.VK_D);
            driver.awaitEdt(() -> !window().busy() && window().shown().facts().depths() != null,
                    "the drag's frame drawn again with its depths");
            RenderedView depths = driver.onEdt(() -> window().shown());
            assertNull(depths.facts().owners(), "still a frame of the drag");
            assertEquals(0, driver.screenDiffersFrom(DepthPicture.of(depths.facts().depths(),
                    Double.NEGATIVE_INFINITY)));
            assertNotNull(nextDragFrame(depths).facts().depths(), "with the depth view on, a drag's frames keep them");
        });
        driver.awaitEdt(() -> !window().busy() && window().shown().facts().owners() != null,
                "traced again once the drag ended");
        driver.press(KeyEvent.VK_D);
    }

    /**
     * A drag's frames are drawn on the images of frames shown before, given back once the next is shown: each
     * frame is on screen as its image holds it, none is drawn on the image of the frame on screen, and the
     * images do come back.
     */
    @Test
    void aDragsFramesAreDrawnOnTheImagesOfEarlierFrames() throws Exception {
        SimpviewWindow window = openWindowOn(litSquare());
        RenderedView unturned = driver.onEdt(() -> window.shown());
        dragTurning(unturned, first -> {
            Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
            List<BufferedImage> seen = new ArrayList<>();
            RenderedView frame = first;
            for (int k = 5; !containsSame(seen, frame.image()); k++) {
                assertTrue(k < 25, "no image of an earlier frame came back in " + seen.size() + " frames");
                assertEquals(0, driver.screenDiffersFrom(frame.image()), "the frame on screen");
                BufferedImage onScreen = frame.image();
                assertFalse(driver.onEdt(() -> window.mayBeDrawnOn(onScreen)), "not to be drawn on while shown");
                seen.add(onScreen);
                RenderedView last = frame;
                driver.robot().mouseMove(centre.x + 10 * k, centre.y + 2 * k);
                driver.awaitEdt(() -> !window.busy() && window.shown() != last, "another frame of the drag");
                frame = driver.onEdt(() -> window.shown());
                assertNotSame(last.image(), frame.image(), "not drawn on the image on screen");
            }
        });
    }

    private static boolean containsSame(List<BufferedImage> images, BufferedImage image) {
        return images.stream().anyMatch(seen -> seen == image);
    }

    @Test
    void theProgressBarShowsAFractionOfAFileWhoseSizeIsKnown() throws Exception {
        int lines = 40_000;
        StringBuilder text = new StringBuilder();
        for (int k = 0; k < lines; k++) {
            text.append("line (-50, -50, -10) (50, 50, -10)\n");
        }
        Path scene = Files.writeString(dir.resolve("long.simp"), text);
        assertTrue(Files.size(scene) > (1 << 20));
        // A stand-in that stops half way, still reporting, until the test has seen the fraction: however
        // busy the machine, the scene cannot end before the progress bar shows (and the count is known).
        AtomicBoolean seen = new AtomicBoolean();
        SceneDrawer halfWayUntilSeen = (file, canvas, options, monitor) -> {
            for (long read = 1000; read <= lines; read += 1000) {
                monitor.linesRead(read);
                monitor.topFileRead((double) read / lines);
                while (read == lines / 2 && !seen.get()) {
                    if (monitor.cancelled()) {
                        throw new SceneCancelledException();
                    }
                    monitor.linesRead(read);
                    try {
                        Thread.sleep(5);
                    } catch (InterruptedException e) {
                        throw new SceneCancelledException();
                    }
                }
            }
            return new ScenePipeline.Drawn(false, null, true, List.of(file));
        };
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()),
                halfWayUntilSeen);
        driver.onEdt(() -> window().openScene(scene));
        driver.awaitEdt(() -> window().status().showingProgress()
                && window().status().progressText().contains("lines read (50 % of the scene file)"),
                "a fraction on the progress bar");
        String said = driver.onEdt(() -> window().status().progressText());
        seen.set(true);
        assertEquals("20,000 lines read (50 % of the scene file)", said);
        driver.awaitShown(new View.OfScene(scene));
    }

    /** Until the status line's inspector says {@code part}; failing, with what it says instead. */
    private void awaitInspector(String part) throws Exception {
        try {
            driver.awaitEdt(() -> window().status().inspectorText().contains(part), "the inspector to say " + part);
        } catch (AssertionError e) {
            throw new AssertionError(e.getMessage() + "; it says " + driver.onEdt(() -> window().status().inspectorText()), e);
        }
    }

    private static String triangleAt(int z) {
        return "polygon (-60, -60, " + z + ") (60, -60, " + z + ") (0, 60, " + z + ")\n";
    }
}
