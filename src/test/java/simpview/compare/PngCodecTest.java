package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.util.Arrays;
import java.util.Random;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** compare's own PNG reader and writer agree with ImageIO, pixel for pixel, and name damage. */
class PngCodecTest {

    private static BufferedImage noisy(int type, int width, int height) {
        BufferedImage image = new BufferedImage(width, height, type);
        Random random = new Random(type);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                // Smooth runs and noise both, so that every row filter gets chosen.
                int smooth = (x * 3 + y * 5) & 0xFF;
                image.setRGB(x, y, random.nextInt(4) == 0 ? random.nextInt() : 0xFF000000 | smooth << 16 | (255 - smooth) << 8 | y & 0xFF);
            }
        }
        return image;
    }

    private static byte[] png(BufferedImage image) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        assertTrue(ImageIO.write(image, "png", out));
        return out.toByteArray();
    }

    private static int[] imageIoPixels(byte[] file) throws Exception {
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(file));
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }

    @ParameterizedTest
    @ValueSource(ints = {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_INT_ARGB, BufferedImage.TYPE_3BYTE_BGR,
        BufferedImage.TYPE_BYTE_INDEXED})
    void decodesAsImageIoDoes(int type) throws Exception {
        byte[] file = png(noisy(type, 97, 61));
        PngCodec.Pixels pixels = PngCodec.decode(file);
        assertEquals(97, pixels.width());
        assertEquals(61, pixels.height());
        assertArrayEquals(imageIoPixels(file), pixels.rgb());
    }

    @Test
    void alphaIsReadAsImageIoReadsIt() throws Exception {
        byte[] file = png(noisy(BufferedImage.TYPE_INT_ARGB, 97, 61));
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(file));
        byte[] alpha = PngCodec.decode(file).alpha();
        for (int i = 0; i < alpha.length; i++) {
            assertEquals(image.getRGB(i % 97, i / 97) >>> 24, alpha[i] & 0xFF, "pixel " + i);
        }
    }

    @Test
    void greyIsTakenAsItsStoredLevels() throws Exception {
        BufferedImage grey = new BufferedImage(20, 10, BufferedImage.TYPE_BYTE_GRAY);
        grey.getRaster().setSample(3, 4, 0, 77);
        PngCodec.Pixels pixels = PngCodec.decode(png(grey));
        assertEquals(0x4D4D4D, pixels.rgb()[4 * 20 + 3]);
        assertEquals(0, pixels.rgb()[0]);
    }

    @Test
    void theCoursesPicturesDecodeAsImageIoDecodesThem() throws Exception {
        for (String name : new String[] {"a2/page6.png", "a3/pageE.png"}) {
            byte[] file = Files.readAllBytes(CourseFiles.require("reference/images/" + name));
            assertArrayEquals(imageIoPixels(file), PngCodec.decode(file).rgb(), name);
        }
    }

    @Test
    void whatItWritesImageIoReadsBack() throws Exception {
        BufferedImage image = noisy(BufferedImage.TYPE_INT_RGB, 123, 45);
        int[] rgb = image.getRGB(0, 0, 123, 45, null, 0, 123);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        byte[] file = PngCodec.encode(123, 45, rgb);
        assertArrayEquals(rgb, imageIoPixels(file));
        assertArrayEquals(rgb, PngCodec.decode(file).rgb());
    }

    @Test
    void damageIsNamed() throws Exception {
        byte[] whole = png(noisy(BufferedImage.TYPE_INT_RGB, 64, 64));
        byte[] cut = Arrays.copyOf(whole, whole.length / 2);
        assertTrue(assertThrows(CompareException.class, () -> PngCodec.decode(cut)).getMessage().contains("runs past the end"));
        byte[] flipped = whole.clone();
        flipped[whole.length / 2] ^= 0x40;
        assertTrue(assertThrows(CompareException.class, () -> PngCodec.decode(flipped)).getMessage().contains("fails its checksum"));
        byte[] signatureOnly = Arrays.copyOf(whole, 8);
        assertEquals("the file ends before its IEND chunk",
                assertThrows(CompareException.class, () -> PngCodec.decode(signatureOnly)).getMessage());
    }

    @Test
    void sixteenBitPicturesAreLeftToImageIo() throws Exception {
        BufferedImage deep = new BufferedImage(10, 10, BufferedImage.TYPE_USHORT_GRAY);
        byte[] file = png(deep);
        assertThrows(PngCodec.Unsupported.class, () -> PngCodec.decode(file));
    }
}
