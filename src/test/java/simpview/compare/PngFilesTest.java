package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What {@link PngFiles#write} puts in the file, read back by ImageIO (a
 * decoder that shares nothing with {@link PngCodec}): every pixel as the
 * picture has it, and the PNG of the picture's kind (opaque RGB as 8-bit
 * RGB, alpha kept, grey as grey).
 */
class PngFilesTest {

    @TempDir
    Path dir;

    private static BufferedImage noise(int type, long seed) {
        BufferedImage image = new BufferedImage(37, 23, type);
        Random random = new Random(seed);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                // runs of one colour beside noise, as a page has them
                int argb = x % 9 < 4 ? 0xFF000000 | y * 0x0B0D0F : random.nextInt();
                image.setRGB(x, y, type == BufferedImage.TYPE_INT_ARGB ? argb : argb | 0xFF000000);
            }
        }
        return image;
    }

    private BufferedImage writtenAndRead(BufferedImage image, String name) throws IOException {
        Path file = dir.resolve(name);
        PngFiles.write(image, file);
        BufferedImage read = ImageIO.read(file.toFile());
        assertNotNull(read, name + " is not a picture ImageIO reads");
        assertEquals(image.getWidth(), read.getWidth());
        assertEquals(image.getHeight(), read.getHeight());
        return read;
    }

    /** IHDR's bit depth and colour type: 8 and 2 for RGB, 0 for grey, 6 for RGBA. */
    private int[] depthAndColourType(String name) throws IOException {
        byte[] bytes = Files.readAllBytes(dir.resolve(name));
        return new int[] {bytes[24], bytes[25]};
    }

    @Test
    void anOpaquePictureIsEveryPixelIn8BitRgb() throws IOException {
        for (int type : new int[] {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_3BYTE_BGR,
            BufferedImage.TYPE_INT_BGR}) {
            BufferedImage image = noise(type, 45 + type);
            String name = "type" + type + ".png";
            BufferedImage read = writtenAndRead(image, name);
            for (int y = 0; y < image.getHeight(); y++) {
                for (int x = 0; x < image.getWidth(); x++) {
                    assertEquals(image.getRGB(x, y), read.getRGB(x, y), name + " at (" + x + ", " + y + ")");
                }
            }
            assertEquals(8, depthAndColourType(name)[0], name);
            assertEquals(2, depthAndColourType(name)[1], name);
        }
    }

    /** A picture that is part of another (its raster's rows longer than it): its own rows, not its parent's. */
    @Test
    void aPartOfAPictureIsItsOwnPixels() throws IOException {
        BufferedImage part = noise(BufferedImage.TYPE_INT_RGB, 3).getSubimage(5, 4, 21, 13);
        BufferedImage read = writtenAndRead(part, "part.png");
        for (int y = 0; y < part.getHeight(); y++) {
            for (int x = 0; x < part.getWidth(); x++) {
                assertEquals(part.getRGB(x, y), read.getRGB(x, y), "at (" + x + ", " + y + ")");
            }
        }
    }

    @Test
    void aPictureWithAlphaKeepsIt() throws IOException {
        BufferedImage image = noise(BufferedImage.TYPE_INT_ARGB, 7);
        BufferedImage read = writtenAndRead(image, "alpha.png");
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                assertEquals(image.getRGB(x, y), read.getRGB(x, y), "at (" + x + ", " + y + ")");
            }
        }
        assertEquals(6, depthAndColourType("alpha.png")[1]);
    }

    @Test
    void aGreyPictureKeepsItsLevels() throws IOException {
        BufferedImage image = new BufferedImage(16, 16, BufferedImage.TYPE_BYTE_GRAY);
        for (int i = 0; i < 256; i++) {
            image.getRaster().setSample(i % 16, i / 16, 0, i);
        }
        BufferedImage read = writtenAndRead(image, "grey.png");
        for (int i = 0; i < 256; i++) {
            assertEquals(i, read.getRaster().getSample(i % 16, i / 16, 0), "level " + i);
        }
        assertEquals(0, depthAndColourType("grey.png")[1]);
    }
}
