package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The outlines drawn over the page (W: wire over fill; U: culled and clipped
 * away), as the view paints them from pictures it keeps between repaints:
 * the wire at 200/255 over the page, the culled and clipped outlines opaque,
 * each where the zoom puts it now, and gone once turned off. Painted off
 * screen, on the EDT, as {@link DevicePixelsTest} paints.
 */
class OutlinesOverPageTest {

    private static final int GREY = 0x40;
    /** A horizontal outline along image row 200, from column 150 to 600 and back. */
    private static final List<double[]> ROW_200 = List.of(new double[] {150, 200.5, 600, 200.5});

    private static BufferedImage greyPage() {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                page.setRGB(x, y, GREY * 0x010101);
            }
        }
        return page;
    }

    /** The view painted whole at 750x750, as the screen would show it. */
    static BufferedImage painted(PageView view) {
        view.setSize(750, 750);
        BufferedImage screen = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = screen.createGraphics();
        view.paint(g);
        g.dispose();
        return screen;
    }

    /**
     * What the screen shows at image point (x, y): the pixel there, or, where an outline runs along that row, the
     * outline's (a one-pixel line along y + 0.5 may fall on the row on either side of it, as the stroke rounds).
     */
    private static int at(BufferedImage screen, PageView view, double x, double y) {
        int sx = (int) view.zoomPan().screenX(x + 0.5);
        int sy = (int) view.zoomPan().screenY(y + 0.5);
        for (int row = sy - 1; row <= sy + 1; row++) {
            int rgb = screen.getRGB(sx, row) & 0xFFFFFF;
            if (rgb != GREY * 0x010101) {
                return rgb;
            }
        }
        return GREY * 0x010101;
    }

    /** Channel c of the wire's colour at 200/255 over the grey page, to within one level. */
    private static void assertWireOverGrey(int rgb, String where) {
        int[] wire = {0, 255, 128};
        for (int c = 0; c < 3; c++) {
            double expected = (wire[c] * 200 + GREY * 55) / 255.0;
            int got = rgb >> (16 - 8 * c) & 0xFF;
            assertTrue(Math.abs(got - expected) <= 1, where + ": channel " + c + " is " + got + ", not about "
                    + expected + " (" + Integer.toHexString(rgb) + ")");
        }
    }

    @Test
    void theWireIsOverThePageWhereTheZoomPutsItAndGoneWhenTurnedOff() throws Throwable {
        DevicePixelsTest.onEdt(() -> {
            PageView view = new PageView();
            view.show(greyPage(), null);
            view.wire(ROW_200);
            BufferedImage fitted = painted(view);
            assertWireOverGrey(at(fitted, view, 375, 200), "on the wire");
            assertEquals(GREY * 0x010101, at(fitted, view, 375, 260), "off the wire");
            double before = view.zoomPan().screenY(200.5);

            view.zoomPan().zoomAbout(375, 375, 2 * view.zoomPan().zoom());
            BufferedImage zoomed = painted(view);
            assertNotEquals(before, view.zoomPan().screenY(200.5), "the zoom moved the row");
            assertWireOverGrey(at(zoomed, view, 375, 200), "on the wire, zoomed");
            for (int row = (int) before - 1; row <= (int) before + 1; row++) {
                assertEquals(GREY * 0x010101, zoomed.getRGB(375, row) & 0xFFFFFF, "where the wire was");
            }

            view.wire(null);
            assertEquals(GREY * 0x010101, at(painted(view), view, 375, 200), "the wire turned off");
        });
    }

    @Test
    void culledAndClippedOutlinesAreOpaqueAloneAndWithTheWire() throws Throwable {
        DevicePixelsTest.onEdt(() -> {
            PageView view = new PageView();
            view.show(greyPage(), null);
            List<double[]> row400 = List.of(new double[] {150, 400.5, 600, 400.5});
            view.skipped(ROW_200, row400);
            BufferedImage alone = painted(view);
            assertEquals(PageView.CULLED.getRGB() & 0xFFFFFF, at(alone, view, 375, 200), "culled");
            assertEquals(PageView.CLIPPED.getRGB() & 0xFFFFFF, at(alone, view, 375, 400), "clipped away");

            view.wire(List.of(new double[] {150, 300.5, 600, 300.5}));
            BufferedImage both = painted(view);
            assertWireOverGrey(at(both, view, 375, 300), "the wire beside them");
            assertEquals(PageView.CULLED.getRGB() & 0xFFFFFF, at(both, view, 375, 200), "culled, with the wire");

            view.skipped(null, null);
            BufferedImage wireOnly = painted(view);
            assertEquals(GREY * 0x010101, at(wireOnly, view, 375, 200), "culled turned off");
            assertWireOverGrey(at(wireOnly, view, 375, 300), "the wire stays");
        });
    }
}
