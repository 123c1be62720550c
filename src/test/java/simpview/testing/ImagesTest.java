package simpview.testing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The tests' bulk pixel reading gives what getRGB gives pixel by pixel, on every kind of picture. */
class ImagesTest {

    @ParameterizedTest
    @ValueSource(ints = {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_INT_ARGB, BufferedImage.TYPE_INT_ARGB_PRE,
            BufferedImage.TYPE_INT_BGR, BufferedImage.TYPE_3BYTE_BGR, BufferedImage.TYPE_4BYTE_ABGR,
            BufferedImage.TYPE_4BYTE_ABGR_PRE, BufferedImage.TYPE_USHORT_565_RGB, BufferedImage.TYPE_USHORT_555_RGB,
            BufferedImage.TYPE_BYTE_GRAY, BufferedImage.TYPE_USHORT_GRAY, BufferedImage.TYPE_BYTE_BINARY,
            BufferedImage.TYPE_BYTE_INDEXED})
    void aRectangleIsWhatGetRgbGivesPixelByPixel(int type) {
        BufferedImage image = new BufferedImage(37, 23, type);
        Random random = new Random(type * 7919L);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                image.setRGB(x, y, random.nextInt());
            }
        }
        assertArrayEquals(perPixel(image, 0, 0, 37, 23), Images.rgb(image), "the whole picture");
        assertArrayEquals(perPixel(image, 5, 3, 20, 11), Images.rgb(image, 5, 3, 20, 11), "a rectangle within it");
        BufferedImage part = image.getSubimage(4, 2, 30, 19);
        assertArrayEquals(perPixel(part, 1, 1, 25, 15), Images.rgb(part, 1, 1, 25, 15), "a sub-image's rectangle");
    }

    @ParameterizedTest
    @ValueSource(ints = {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_3BYTE_BGR, BufferedImage.TYPE_BYTE_GRAY})
    void differingPixelsCountsTheColoursThatDifferAndNotAlpha(int type) {
        BufferedImage a = new BufferedImage(10, 8, type);
        BufferedImage b = new BufferedImage(10, 8, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 10; x++) {
                b.setRGB(x, y, a.getRGB(x, y) & 0xFFFFFF | (x + y) << 24);
            }
        }
        b.setRGB(3, 2, 0xFF010203);
        b.setRGB(9, 7, 0x00FFFFFF);
        assertEquals(2, Images.differingPixels(a, b));
        assertEquals(1, Images.differingPixels(a, b, 0, 3));
        assertEquals(0, Images.differingPixels(a, b, 3, 7));
    }

    private static int[] perPixel(BufferedImage image, int left, int top, int w, int h) {
        int[] out = new int[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                out[y * w + x] = image.getRGB(left + x, top + y) & 0xFFFFFF;
            }
        }
        return out;
    }
}
