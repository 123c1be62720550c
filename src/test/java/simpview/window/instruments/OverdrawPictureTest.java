package simpview.window.instruments;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.util.Random;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import simpview.surface.PageCanvas;
import simpview.window.WindowAction;

/** The overdraw picture's panel pixels are their counts' heat, the margins white, the bar the ramp 0 to max. */
public class OverdrawPictureTest {

    @Test
    void everyPanelPixelIsTheHeatOfItsCount() {
        int panel = PageCanvas.PANEL;
        int[] counts = new int[panel * panel];
        Random random = new Random(3);
        for (int i = 0; i < counts.length; i++) {
            counts[i] = random.nextInt(4) == 0 ? 0 : random.nextInt(40);
        }
        counts[7] = 57;
        BufferedImage picture = OverdrawPicture.of(counts);
        int[] rgb = picture.getRGB(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, null, 0, PageCanvas.SIZE);
        for (int y = 0; y < panel; y++) {
            for (int x = 0; x < panel; x++) {
                int ix = PageCanvas.MARGIN + x;
                int iy = PageCanvas.MARGIN + panel - 1 - y;
                int expected = OverdrawPicture.heat(counts[y * panel + x], 57);
                if (expected != (rgb[iy * PageCanvas.SIZE + ix] & 0xFFFFFF)) {
                    assertEquals(expected, rgb[iy * PageCanvas.SIZE + ix] & 0xFFFFFF, "pixel (" + x + ", " + y + ")");
                }
            }
        }
        assertEquals(0x000000, OverdrawPicture.heat(0, 57));
        assertEquals(0xFFFFFF, picture.getRGB(10, 700) & 0xFFFFFF, "the margin");
        assertEquals(0xFFFFFF, picture.getRGB(PageCanvas.SIZE - 10, 300) & 0xFFFFFF, "the margin");
        // The bar, rows 22 to 31 over the panel's columns: 0 at its left end, the most at its right.
        assertEquals(OverdrawPicture.heat(0, 57), picture.getRGB(PageCanvas.MARGIN, 25) & 0xFFFFFF);
        assertEquals(OverdrawPicture.heat(57, 57), picture.getRGB(PageCanvas.MARGIN + panel - 1, 25) & 0xFFFFFF);
        assertEquals(OverdrawPicture.heat(Math.round(325f * 57 / 649), 57),
                picture.getRGB(PageCanvas.MARGIN + 325, 31) & 0xFFFFFF);
    }

    /** V's help names the ramp as it is drawn: black for none, blue for one, red, yellow, white for the most. */
    @Test
    void theKeyHelpNamesTheRampsColoursInOrder() {
        String help = WindowAction.OVERDRAW.help();
        assertTrue(help.contains("black (none), then a heat ramp from blue (one) through red and yellow to white (the most)"),
                help);
        int max = 61;
        assertEquals(0x000000, OverdrawPicture.heat(0, max), "none: black");
        assertEquals(Channel.BLUE, Channel.strongest(OverdrawPicture.heat(1, max)), "one: blue");
        assertEquals(Channel.RED, Channel.strongest(OverdrawPicture.heat(21, max)), "a third of the way: red");
        int yellow = OverdrawPicture.heat(41, max);
        assertTrue(((yellow >> 16) & 0xFF) > 200 && ((yellow >> 8) & 0xFF) > 200 && (yellow & 0xFF) < 60,
                "two thirds: yellow, " + Integer.toHexString(yellow));
        assertEquals(0xFFFFFF, OverdrawPicture.heat(max, max), "the most: white");
    }

    private enum Channel {
        RED, GREEN, BLUE;

        static Channel strongest(int rgb) {
            int r = (rgb >> 16) & 0xFF;
            int g = (rgb >> 8) & 0xFF;
            int b = rgb & 0xFF;
            return r >= g && r >= b ? RED : g >= b ? GREEN : BLUE;
        }
    }
}
