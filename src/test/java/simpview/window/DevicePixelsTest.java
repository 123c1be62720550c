package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.lang.reflect.InvocationTargetException;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/**
 * The page view on a scaled desktop, painted as Swing paints it there: into
 * a picture of the device's pixels through a graphics scaled by the
 * desktop's scale (as on Windows at 150 %, which an X server cannot be made
 * to give: the JDK rounds its scale down to a whole number). No display is
 * needed. Each test runs on the EDT, as the view does, so that no resize
 * event comes between a paint and what is read of it.
 */
public class DevicePixelsTest {

    /** Runs {@code test} on the EDT, its failure thrown here (also for the other tests that paint a view off screen). */
    static void onEdt(Runnable test) throws Throwable {
        try {
            SwingUtilities.invokeAndWait(test);
        } catch (InvocationTargetException e) {
            throw e.getCause();
        }
    }

    /** A page whose every pixel has a colour of its own: its column and row in the channels. */
    private static BufferedImage numberedPage() {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                page.setRGB(x, y, (x & 0xFF) << 16 | (y & 0xFF) << 8 | (x >> 8) << 4 | (y >> 8));
            }
        }
        return page;
    }

    /** What the screen shows of {@code view}, {@code width} by {@code height} points, at {@code scale}. */
    private static BufferedImage painted(PageView view, int width, int height, double scale) {
        view.setSize(width, height);
        BufferedImage screen = new BufferedImage((int) Math.ceil(width * scale), (int) Math.ceil(height * scale),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = screen.createGraphics();
        g.scale(scale, scale);
        view.paint(g);
        g.dispose();
        return screen;
    }

    @Test
    void at150PercentEveryPagePixelIsOneDevicePixelNotOneOrTwo() throws Throwable {
        onEdt(() -> {
            PageView view = new PageView();
            BufferedImage page = numberedPage();
            view.show(page, null);
            BufferedImage screen = painted(view, 750, 750, 1.5);
            // 750 points are 1125 device pixels: the page at one device pixel a page pixel, centred.
            assertEquals(1.0, view.zoomPan().zoom());
            int origin = (1125 - 750) / 2;
            long differing = 0;
            for (int y = 0; y < 750; y++) {
                for (int x = 0; x < 750; x++) {
                    if ((screen.getRGB(origin + x, origin + y) & 0xFFFFFF) != page.getRGB(x, y) - 0xFF000000) {
                        differing++;
                    }
                }
            }
            assertEquals(0, differing, "page pixels not where a 1:1 copy puts them, at 150 %");
        });
    }

    @Test
    void at150PercentZoomedInEveryPagePixelIsTheSameWholeSquare() throws Throwable {
        onEdt(() -> {
            PageView view = new PageView();
            BufferedImage page = numberedPage();
            view.show(page, null);
            painted(view, 750, 750, 1.5);
            view.zoomPan().wheel(562, 562, -1);
            BufferedImage screen = painted(view, 750, 750, 1.5);
            assertEquals(2.0, view.zoomPan().zoom());
            // Each page pixel in view is two by two device pixels, from the origin on: none one or three wide.
            int ox = (int) view.zoomPan().originX();
            int oy = (int) view.zoomPan().originY();
            long differing = 0;
            for (int sy = 0; sy < screen.getHeight(); sy++) {
                for (int sx = 0; sx < screen.getWidth(); sx++) {
                    int ix = Math.floorDiv(sx - ox, 2);
                    int iy = Math.floorDiv(sy - oy, 2);
                    if (ix >= 0 && iy >= 0 && ix < 750 && iy < 750
                            && (screen.getRGB(sx, sy) & 0xFFFFFF) != (page.getRGB(ix, iy) & 0xFFFFFF)) {
                        differing++;
                    }
                }
            }
            assertEquals(0, differing, "device pixels not showing the page pixel a 2x zoom puts there, at 150 %");
        });
    }

    @Test
    void thePointerNamesThePagePixelShownUnderItAt150And200Percent() throws Throwable {
        onEdt(() -> {
            for (double scale : new double[] {1.5, 2}) {
                PageView view = new PageView();
                BufferedImage page = numberedPage();
                view.show(page, null);
                // 733 points high: at 200 % the panel at 1:1 with its margins cropped, its origin an odd device row
                // unless kept to whole points.
                BufferedImage screen = painted(view, 750, 733, scale);
                int ix = view.imageX(375);
                int deviceX = (int) Math.floor(375 * scale);
                for (int y = 0; y < 733; y++) {
                    int iy = view.imageY(y);
                    // The device rows the pointer may be on when the desktop says point row y: all of them at 200 %;
                    // at 150 % the one the point begins in (a point there is one device row or two, of two page rows).
                    int from = (int) Math.floor(y * scale);
                    int to = scale == Math.rint(scale) ? (int) ((y + 1) * scale) : from + 1;
                    for (int deviceY = from; deviceY < to && iy >= 0; deviceY++) {
                        int shown = screen.getRGB(deviceX, deviceY) & 0xFFFFFF;
                        assertEquals(Integer.toHexString(page.getRGB(ix, iy) & 0xFFFFFF), Integer.toHexString(shown),
                                "at " + scale + ": point row " + y + " named page row " + iy + ", device row " + deviceY);
                    }
                }
            }
        });
    }

    @Test
    void at200PercentThePixelGridShowsAsAt100PercentEachPointTwoByTwo() throws Throwable {
        onEdt(() -> {
            BufferedImage page = numberedPage();
            PageView unscaled = new PageView();
            unscaled.show(page, null);
            unscaled.setSize(750, 750);
            unscaled.zoomPan().resize(750, 750, 1);
            unscaled.zoomPan().zoomAbout(300.5, 410.5, 8);
            BufferedImage at100 = painted(unscaled, 750, 750, 1);
            PageView scaled = new PageView();
            scaled.show(page, null);
            painted(scaled, 750, 750, 2);
            scaled.zoomPan().zoomAbout(601, 821, 16);
            BufferedImage at200 = painted(scaled, 750, 750, 2);
            assertEquals(2 * unscaled.zoomPan().originX(), scaled.zoomPan().originX());
            // 8x: the grid's lines a point wide and its dots a point square, where they are at 100 %.
            long differing = 0;
            for (int sy = 0; sy < 1500; sy++) {
                for (int sx = 0; sx < 1500; sx++) {
                    if (at200.getRGB(sx, sy) != at100.getRGB(sx / 2, sy / 2)) {
                        differing++;
                    }
                }
            }
            assertEquals(0, differing, "device pixels at 200 % unlike the point they show at 100 %, at 8x");
        });
    }

    @Test
    void theViewAsksForRoomForTheWholePageAtWholeDevicePixels() {
        assertEquals(750, PageView.preferredSide(1));
        assertEquals(750, PageView.preferredSide(2));
        assertEquals(1000, PageView.preferredSide(1.5));
        assertEquals(600, PageView.preferredSide(1.25));
    }
}
