package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/**
 * The pixel grid's dots, written into a picture and copied over the page at once, are the pixels that filling
 * each dot's square over it, one fill a dot, gives: the same places and the same blend, at 8x and 16x, panned to a
 * part cell at the view's edges.
 */
class PixelGridTest {

    @Test
    void theDotsAreThePixelsOfOneFillADot() throws Throwable {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                page.setRGB(x, y, (x * 7 + y * 13) % 5 < 2 ? 0x203040 : 0xD0E0C0);
            }
        }
        DevicePixelsTest.onEdt(() -> {
            for (int zoom : new int[] {8, 16}) {
                PageView view = new PageView();
                view.show(page, null);
                view.setSize(1000, 900);
                view.zoomPan().zoomAbout(501.3, 449.7, zoom);
                ZoomPan zoomPan = view.zoomPan();
                assertTrue(PixelGrid.shows(zoomPan), zoom + "x");
                Rectangle clip = new Rectangle(0, 0, 1000, 900);
                BufferedImage drawn = under(page, zoomPan);
                Graphics2D g = drawn.createGraphics();
                PixelGrid.paint(g, zoomPan, page, clip);
                g.dispose();
                BufferedImage expected = under(page, zoomPan);
                Graphics2D e = expected.createGraphics();
                oneFillADot(e, zoomPan, page, clip);
                e.dispose();
                long differing = 0;
                for (int y = 0; y < 900; y++) {
                    for (int x = 0; x < 1000; x++) {
                        differing += drawn.getRGB(x, y) != expected.getRGB(x, y) ? 1 : 0;
                    }
                }
                assertEquals(0, differing, zoom + "x: pixels other than one fill a dot gives");
            }
        });
    }

    /** The page as the view shows it at this zoom: each pixel a square, so that the dots blend over its colours. */
    private static BufferedImage under(BufferedImage page, ZoomPan zoomPan) {
        BufferedImage screen = new BufferedImage(1000, 900, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 900; y++) {
            for (int x = 0; x < 1000; x++) {
                int ix = (int) Math.floor((x - zoomPan.originX()) / zoomPan.zoom());
                int iy = (int) Math.floor((y - zoomPan.originY()) / zoomPan.zoom());
                screen.setRGB(x, y, ix >= 0 && iy >= 0 && ix < 750 && iy < 750 ? page.getRGB(ix, iy) : 0);
            }
        }
        return screen;
    }

    /** The grid as it was drawn before: a fill for each line, then one for each dot, in its colour. */
    private static void oneFillADot(Graphics2D g, ZoomPan zoomPan, BufferedImage page, Rectangle clip) {
        int zoom = (int) zoomPan.zoom();
        int unit = zoomPan.unit();
        int fromCol = (int) Math.max(0, Math.floor((clip.x - zoomPan.originX()) / zoom));
        int toCol = (int) Math.min(750, Math.ceil((clip.x + clip.width - zoomPan.originX()) / zoom));
        int fromRow = (int) Math.max(0, Math.floor((clip.y - zoomPan.originY()) / zoom));
        int toRow = (int) Math.min(750, Math.ceil((clip.y + clip.height - zoomPan.originY()) / zoom));
        int top = (int) zoomPan.screenY(fromRow);
        int bottom = (int) zoomPan.screenY(toRow);
        int left = (int) zoomPan.screenX(fromCol);
        int right = (int) zoomPan.screenX(toCol);
        g.setColor(PixelGrid.LINE);
        for (int i = fromCol; i < toCol; i++) {
            g.fillRect((int) zoomPan.screenX(i), top, unit, bottom - top);
        }
        for (int j = fromRow; j < toRow; j++) {
            g.fillRect(left, (int) zoomPan.screenY(j), right - left, unit);
        }
        int dots = zoom >= 16 * unit ? 2 : 1;
        int dot = dots * unit;
        int inset = (zoom / unit / 2 - dots / 2) * unit;
        for (int j = fromRow; j < toRow; j++) {
            for (int i = fromCol; i < toCol; i++) {
                int rgb = page.getRGB(i, j);
                int luminance = (299 * (rgb >> 16 & 0xFF) + 587 * (rgb >> 8 & 0xFF) + 114 * (rgb & 0xFF)) / 1000;
                g.setColor(luminance < 128 ? new Color(255, 255, 255, 200) : new Color(0, 0, 0, 200));
                g.fillRect((int) zoomPan.screenX(i) + inset, (int) zoomPan.screenY(j) + inset, dot, dot);
            }
        }
    }
}
