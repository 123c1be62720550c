package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Below 1:1 no 1-px line is lost: every line is still a whole line in the smaller picture, in its own colour. */
class LineKeepingDownscaleTest {

    private static final int SIZE = 64;
    private static final int LINE = 0xFF40C0;

    @Test
    void everyHorizontalAndVerticalOnePixelLineStaysWholeAtEveryZoomBelow1To1() {
        for (double zoom : new double[] {0.5, 0.61, 0.866, 0.923, 0.999}) {
            for (int at = 1; at < SIZE - 1; at++) {
                BufferedImage rows = blank();
                BufferedImage cols = blank();
                for (int k = 6; k < 58; k++) {
                    rows.setRGB(k, at, LINE);
                    cols.setRGB(at, k, LINE);
                }
                BufferedImage smallRows = LineKeepingDownscale.of(rows, zoom);
                BufferedImage smallCols = LineKeepingDownscale.of(cols, zoom);
                // Some row of the result is the line from its first to its last whole column, unbroken.
                int from = (int) Math.ceil(6 * zoom);
                int to = (int) Math.floor(58 * zoom) - 1;
                assertTrue(unbroken(smallRows, from, to, true), "row " + at + " at zoom " + zoom);
                assertTrue(unbroken(smallCols, from, to, false), "column " + at + " at zoom " + zoom);
            }
        }
    }

    @Test
    void aPlainPictureStaysPlainAndNoColourIsMadeUp() {
        BufferedImage page = blank();
        int[] colours = {0xFFFFFF, 0x102030, 0xFF0000, 0x00FF00};
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                page.setRGB(x, y, x < 32 && y < 32 ? 0 : colours[(x * 7 + y * 13) % 4]);
            }
        }
        BufferedImage small = LineKeepingDownscale.of(page, 0.7);
        assertEquals(LineKeepingDownscale.shownSide(SIZE, 0.7), small.getWidth());
        Set<Integer> allowed = new HashSet<>();
        allowed.add(0);
        for (int c : colours) {
            allowed.add(c);
        }
        for (int y = 0; y < small.getHeight(); y++) {
            for (int x = 0; x < small.getWidth(); x++) {
                int c = small.getRGB(x, y) & 0xFFFFFF;
                assertTrue(allowed.contains(c), "a colour of the page: " + Integer.toHexString(c));
                if (x < 21 && y < 21) {
                    assertEquals(0, c, "the black quarter stays black at (" + x + ", " + y + ")");
                }
            }
        }
    }

    private static BufferedImage blank() {
        return new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
    }

    private static boolean unbroken(BufferedImage small, int from, int to, boolean alongRows) {
        for (int line = 0; line < small.getHeight(); line++) {
            boolean whole = true;
            for (int k = from; k <= to && whole; k++) {
                int c = alongRows ? small.getRGB(k, line) : small.getRGB(line, k);
                whole = (c & 0xFFFFFF) == LINE;
            }
            if (whole) {
                return true;
            }
        }
        return false;
    }
}
