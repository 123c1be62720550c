package simpview.window.instruments;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.surface.PageCanvas;

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
}
