package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Dimension;
import java.awt.Rectangle;
import org.junit.jupiter.api.Test;

public class ZoomPanTest {

    private static ZoomPan in(int width, int height) {
        ZoomPan zoomPan = new ZoomPan(750, 50);
        zoomPan.resize(width, height);
        return zoomPan;
    }

    @Test
    void fitIsOneToOneWhenTheWholePageFitsAndCentresIt() {
        ZoomPan zoomPan = in(800, 760);
        assertEquals(1.0, zoomPan.zoom());
        assertEquals(25.0, zoomPan.originX());
        assertEquals(5.0, zoomPan.originY());
        assertEquals("1:1", zoomPan.describe());
    }

    @Test
    void onADesktopAt200PercentOneToOneIsTwoDevicePixelsAPagePixelAndThePanelComesBeforeAHalfSizePage() {
        ZoomPan zoomPan = new ZoomPan(750, 50);
        // 750 by 733 points: the whole page fits only at one device pixel a page pixel, the panel at two.
        zoomPan.resize(1500, 1466, 2);
        assertEquals(2.0, zoomPan.zoom());
        assertEquals("1:1, margins cropped", zoomPan.describe());
        // The origin is kept to whole points: a point of the desktop is in one page pixel, not across two.
        assertEquals(0, (int) zoomPan.originY() % 2);
        assertEquals(0, (int) zoomPan.originX() % 2);
        zoomPan.wheel(750, 733, -1);
        assertEquals(4.0, zoomPan.zoom());
        assertEquals("2x", zoomPan.describe());
        zoomPan.actualSize();
        assertEquals(2.0, zoomPan.zoom());
        zoomPan.wheel(750, 733, 1);
        assertEquals(1.0, zoomPan.zoom());
        assertTrue(zoomPan.describe().startsWith("below 1:1: 50 %, 1 screen pixel a page pixel"), zoomPan.describe());
        zoomPan.resize(1500, 1600, 2);
        zoomPan.fit();
        assertEquals(2.0, zoomPan.zoom());
        assertEquals("1:1", zoomPan.describe());
    }

    @Test
    void atHalfTheDesktopsSizeAt200PercentTheZoomIsBelowOneToOneAsItsWordsSay() {
        ZoomPan zoomPan = new ZoomPan(750, 50);
        zoomPan.resize(1500, 1466, 2);
        assertFalse(zoomPan.belowOneToOne(), zoomPan.describe());
        // The wheel out of 1:1 goes to one device pixel a page pixel: "below 1:1", so the status line puts it first.
        zoomPan.wheel(750, 733, 1);
        assertTrue(zoomPan.describe().startsWith("below 1:1"), zoomPan.describe());
        assertTrue(zoomPan.belowOneToOne(), "the status line would put '" + zoomPan.describe() + "' last, cut off");
        assertFalse(zoomPan.belowOneDevicePixel(), "one device pixel a page pixel is copied, not shrunk");
    }

    @Test
    void fitIsTheLargestIntegerZoomThatFits() {
        assertEquals(2.0, in(1600, 1520).zoom());
        assertEquals(1.0, in(1600, 1499).zoom());
    }

    @Test
    void aViewportSmallerThanThePageShowsThePanelAt1To1WithItsMarginsCropped() {
        // 1366x768 less the menu bar and the status line: 750 does not fit, 650 does.
        ZoomPan zoomPan = in(946, 700);
        assertEquals(1.0, zoomPan.zoom());
        assertTrue(zoomPan.cropped());
        // The panel (image 50..699) is centred: its first column and row at (148, 25).
        assertEquals(148.0, zoomPan.screenX(50));
        assertEquals(25.0, zoomPan.screenY(50));
        assertEquals(50, zoomPan.imageX(148));
        assertEquals("1:1, margins cropped", zoomPan.describe());
    }

    @Test
    void aViewportSmallerThanThePanelScalesThePanelBelow1To1AndSaysSo() {
        ZoomPan zoomPan = in(1366, 600);
        assertFalse(zoomPan.isIntegerZoom());
        assertEquals(600 / 650.0, zoomPan.zoom(), 1e-12);
        assertTrue(zoomPan.cropped());
        assertTrue(zoomPan.screenY(50) >= 0 && zoomPan.screenY(700) <= 601);
        assertTrue(zoomPan.describe().startsWith("below 1:1: 92 %, margins cropped, 1-px lines kept"), zoomPan.describe());
        zoomPan.actualSize();
        assertEquals(1.0, zoomPan.zoom());
        assertFalse(zoomPan.cropped(), "1:1 by Z is not a fit: it pans");
    }

    @Test
    void cropFitsThePanelAloneEvenWhenThePageFits() {
        ZoomPan zoomPan = in(800, 800);
        zoomPan.fitPanel();
        assertEquals(1.0, zoomPan.zoom());
        assertTrue(zoomPan.cropped());
        assertEquals(75.0, zoomPan.screenX(50));
        zoomPan.resize(1400, 1400);
        assertEquals(2.0, zoomPan.zoom(), "the crop follows the window: 650 fits twice in 1400");
        zoomPan.fit();
        assertEquals(1.0, zoomPan.zoom());
        assertFalse(zoomPan.cropped());
    }

    @Test
    void theWheelZoomsAboutThePointerUpTo32x() {
        ZoomPan zoomPan = in(750, 750);
        int imageX = zoomPan.imageX(300);
        int imageY = zoomPan.imageY(200);
        for (int i = 0; i < 20; i++) {
            zoomPan.wheel(300.5, 200.5, -1);
            assertEquals(imageX, zoomPan.imageX(300.5), "the pixel under the pointer stays under it");
            assertEquals(imageY, zoomPan.imageY(200.5));
            assertTrue(zoomPan.isIntegerZoom());
        }
        assertEquals(ZoomPan.MAX_ZOOM, zoomPan.zoom());
        for (int i = 0; i < 20; i++) {
            zoomPan.wheel(300.5, 200.5, 1);
        }
        assertEquals(1.0, zoomPan.zoom(), "never below the fit");
    }

    @Test
    void atAnIntegerZoomEveryImagePixelIsAWholeSquareOfScreenPixels() {
        ZoomPan zoomPan = in(750, 750);
        zoomPan.zoomAbout(333.3, 111.7, 8);
        int x = 500;
        int first = zoomPan.imageX(x);
        int start = (int) zoomPan.screenX(first);
        assertEquals(zoomPan.screenX(first), start, "pixel edges on whole screen pixels");
        for (int k = 0; k < 8; k++) {
            assertEquals(first, zoomPan.imageX(start + k + 0.5));
        }
        assertEquals(first + 1, zoomPan.imageX(start + 8.5));
    }

    @Test
    void panMovesTheImageKeepsSomeOfItInViewAndFitComesBack() {
        ZoomPan zoomPan = in(750, 750);
        zoomPan.zoomAbout(375, 375, 4);
        double x = zoomPan.originX();
        zoomPan.pan(40, -10);
        assertEquals(x + 40, zoomPan.originX());
        assertFalse(zoomPan.fitting());
        zoomPan.pan(1e6, 1e6);
        assertTrue(zoomPan.originX() < 750 && zoomPan.originY() < 750, "some of the image stays in view");
        zoomPan.fit();
        assertEquals(1.0, zoomPan.zoom());
        assertEquals(0.0, zoomPan.originX());
    }

    @Test
    void at200PercentAPanKeepsAsManyPointsOfThePageInViewAsAt100Percent() {
        ZoomPan unscaled = in(750, 750);
        unscaled.zoomAbout(375, 375, 4);
        unscaled.pan(1e6, -1e6);
        ZoomPan scaled = new ZoomPan(750, 50);
        scaled.resize(1500, 1500, 2);
        scaled.zoomAbout(750, 750, 8);
        scaled.pan(1e6, -1e6);
        // 48 points of the page stay in view: 96 device pixels at 200 %, not 48.
        assertEquals(750 - 48.0, unscaled.originX());
        assertEquals(2 * unscaled.originX(), scaled.originX());
        assertEquals(2 * unscaled.originY(), scaled.originY());
    }

    @Test
    void actualSizeIsOneToOneAboutTheMiddle() {
        ZoomPan zoomPan = in(700, 700);
        zoomPan.actualSize();
        assertEquals(1.0, zoomPan.zoom());
        assertEquals("1:1", zoomPan.describe());
    }

    /** After zooming in and panning, Z in a view the whole page fits at 1:1 centres it, as fit does. */
    @Test
    void actualSizeCentresAPageThatFits() {
        ZoomPan zoomPan = in(800, 760);
        zoomPan.wheel(100, 100, -2);
        zoomPan.pan(37, -12);
        zoomPan.actualSize();
        assertEquals(1.0, zoomPan.zoom());
        assertEquals(25.0, zoomPan.originX());
        assertEquals(5.0, zoomPan.originY());
    }

    @Test
    void aResizeInFitModeRefits() {
        ZoomPan zoomPan = in(750, 750);
        zoomPan.resize(500, 600);
        assertEquals(500 / 650.0, zoomPan.zoom(), 1e-12);
        // The panel, not the margins, fills the view.
        assertTrue(zoomPan.screenX(50) >= 0 && zoomPan.screenX(700) <= 501 && zoomPan.screenY(50) >= 0
                && zoomPan.screenY(700) <= 601);
    }

    @Test
    void pointsOffTheImageAreMinusOne() {
        ZoomPan zoomPan = in(800, 800);
        assertEquals(-1, zoomPan.imageX(10));
        assertEquals(-1, zoomPan.imageY(790));
        assertEquals(0, zoomPan.imageX(25));
    }

    @Test
    void theWindowOpensWithinALaptopScreenWithATaskbar() {
        // 1366x768 with a 40-pixel taskbar at the bottom; the frame would like 766x846.
        Rectangle usable = new Rectangle(0, 0, 1366, 728);
        Rectangle bounds = WindowPlacement.within(new Dimension(766, 846), usable);
        assertTrue(usable.contains(bounds), bounds.toString());
        assertEquals(728, bounds.height);
        assertEquals(766, bounds.width);
        Rectangle roomy = WindowPlacement.within(new Dimension(766, 846), new Rectangle(100, 50, 1920, 1050));
        assertEquals(new Rectangle(100 + (1920 - 766) / 2, 50 + (1050 - 846) / 2, 766, 846), roomy);
    }

    /** What a new page opens at: the fit last chosen, Fit or Crop, whatever zoom and pan came after it. */
    @Test
    void refitGoesBackToTheFitLastChosen() {
        ZoomPan zoomPan = in(800, 760);
        zoomPan.zoomAbout(100, 100, 8);
        zoomPan.pan(-300, 40);
        zoomPan.refit();
        assertTrue(zoomPan.fitting());
        assertEquals(1.0, zoomPan.zoom());
        assertEquals(25.0, zoomPan.originX());
        assertEquals("1:1", zoomPan.describe());
        zoomPan.fitPanel();
        zoomPan.zoomAbout(100, 100, 8);
        zoomPan.refit();
        assertTrue(zoomPan.fitting() && zoomPan.cropped(), zoomPan.describe());
        assertEquals("1:1, margins cropped", zoomPan.describe());
    }
}
