package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

public class ContactSheetTest {

    @Test
    void halvingAveragesEachTwoByTwoBlock() {
        BufferedImage page = new BufferedImage(4, 2, BufferedImage.TYPE_INT_RGB);
        page.setRGB(0, 0, 0xFFFFFF);
        page.setRGB(1, 0, 0xFFFFFF);
        page.setRGB(0, 1, 0x000000);
        page.setRGB(1, 1, 0x000000);
        page.setRGB(2, 0, 0x0000FF);
        page.setRGB(3, 0, 0x0000FF);
        page.setRGB(2, 1, 0x0000FF);
        page.setRGB(3, 1, 0x000001);
        BufferedImage half = ContactSheet.halved(page);
        assertEquals(2, half.getWidth());
        assertEquals(1, half.getHeight());
        assertEquals(0x808080, half.getRGB(0, 0) & 0xFFFFFF); // (255 + 255 + 0 + 0) / 4 rounds to 128
        assertEquals(0x0000C0, half.getRGB(1, 0) & 0xFFFFFF); // (3 * 255 + 1) / 4 rounds to 192
    }

    @Test
    void sheetHasFourColumnsAndAsManyRowsAsNeeded() {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        List<ContactSheet.Tile> five = Collections.nCopies(5, ContactSheet.Tile.of("x", page));
        BufferedImage sheet = ContactSheet.compose(five);
        int cell = ContactSheet.TILE + ContactSheet.GAP;
        assertEquals(ContactSheet.GAP + 4 * cell, sheet.getWidth());
        assertEquals(ContactSheet.GAP + 2 * (cell + ContactSheet.LABEL_HEIGHT), sheet.getHeight());
    }

    /** Every block of a noisy page of odd size (its last row and column left out), against the mean by hand. */
    @Test
    void everyBlockOfANoisyPageIsItsFourPixelsMean() {
        BufferedImage page = new BufferedImage(751, 749, BufferedImage.TYPE_INT_RGB);
        Random random = new Random(45);
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                page.setRGB(x, y, random.nextInt());
            }
        }
        BufferedImage half = ContactSheet.halved(page);
        assertEquals(375, half.getWidth());
        assertEquals(374, half.getHeight());
        for (int y = 0; y < half.getHeight(); y++) {
            for (int x = 0; x < half.getWidth(); x++) {
                int want = 0;
                for (int shift = 16; shift >= 0; shift -= 8) {
                    int sum = 0;
                    for (int j = 0; j < 4; j++) {
                        sum += page.getRGB(2 * x + j % 2, 2 * y + j / 2) >> shift & 0xFF;
                    }
                    want = want << 8 | (int) Math.floor(sum / 4.0 + 0.5);
                }
                assertEquals(want, half.getRGB(x, y) & 0xFFFFFF, "block (" + x + ", " + y + ")");
            }
        }
    }
}
