package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.nio.file.Path;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * Every format a picture may come in is read as a viewer shows it: grey levels as they are stored
 * (ImageIO calls them linear, and getRGB brightened them), 16-bit levels scaled to 255, CMYK JPEGs
 * mixed as browsers mix them. Page 3 is grey, so each format can hold it exactly.
 */
class PictureFormatsTest {

    @TempDir
    Path dir;

    private static BufferedImage page3() throws Exception {
        return new PageRenderer().renderImage(3, PageContext.defaults());
    }

    /** Page 3's grey levels in a picture of {@code type}, 16-bit types at 257 times each 8-bit level. */
    private static BufferedImage grey(BufferedImage page, int type) {
        BufferedImage grey = new BufferedImage(page.getWidth(), page.getHeight(), type);
        int scale = type == BufferedImage.TYPE_USHORT_GRAY ? 257 : 1;
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                grey.getRaster().setSample(x, y, 0, (page.getRGB(x, y) & 0xFF) * scale);
            }
        }
        return grey;
    }

    private Path written(BufferedImage image, String format, String name) throws Exception {
        Path file = dir.resolve(name);
        assertTrue(ImageIO.write(image, format, file.toFile()), "no " + format + " writer for " + name);
        return file;
    }

    /** A JPEG at the best quality; of a raster alone (no colour model), ImageIO writes four bands as CMYK. */
    private Path jpeg(IIOImage image, String name) throws Exception {
        Path file = dir.resolve(name);
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        try (ImageOutputStream out = ImageIO.createImageOutputStream(file.toFile())) {
            writer.setOutput(out);
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality(1f);
            writer.write(null, image, param);
        } finally {
            writer.dispose();
        }
        return file;
    }

    private static void passes(BufferedImage page, Path file) throws Exception {
        Comparison c = Comparison.of(Picture.ofPage(page, "ours").panel(), Picture.read(file).panel());
        assertTrue(c.withSlack().within8() >= 0.99, file.getFileName() + ": within 8/255 " + c.withSlack().within8());
    }

    private static int colourSpace(Path file) throws Exception {
        return ImageIO.read(file.toFile()).getColorModel().getColorSpace().getType();
    }

    @Test
    void aGreyJpegOfThePagePasses() throws Exception {
        BufferedImage page = page3();
        Path file = jpeg(new IIOImage(grey(page, BufferedImage.TYPE_BYTE_GRAY), null, null), "page3.jpg");
        assertEquals(ColorSpace.TYPE_GRAY, colourSpace(file));
        passes(page, file);
    }

    @Test
    void aSixteenBitGreyPngOfThePagePasses() throws Exception {
        BufferedImage page = page3();
        passes(page, written(grey(page, BufferedImage.TYPE_USHORT_GRAY), "png", "page3.png"));
    }

    @Test
    void aSixteenBitGreyPngWithAlphaOfThePagePasses() throws Exception {
        BufferedImage page = page3();
        passes(page, written(greyWithAlpha16(page, 65535), "png", "page3.png"));
    }

    /** A grey page (its blue levels) as 16-bit grey with every pixel's alpha {@code alpha} (of 65535). */
    static BufferedImage greyWithAlpha16(BufferedImage page, int alpha) {
        ComponentColorModel model = new ComponentColorModel(ColorSpace.getInstance(ColorSpace.CS_GRAY), true, false,
                Transparency.TRANSLUCENT, DataBuffer.TYPE_USHORT);
        WritableRaster raster = model.createCompatibleWritableRaster(page.getWidth(), page.getHeight());
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                raster.setPixel(x, y, new int[] {(page.getRGB(x, y) & 0xFF) * 257, alpha});
            }
        }
        return new BufferedImage(model, raster, false, null);
    }

    @Test
    void sixteenBitGreyLevelsAreScaledTo255AndRounded() throws Exception {
        int[] levels = {0, 128, 255, 32767, 32768, 32895, 65278, 65407, 65535};
        BufferedImage deep = new BufferedImage(levels.length, 1, BufferedImage.TYPE_USHORT_GRAY);
        for (int x = 0; x < levels.length; x++) {
            deep.getRaster().setSample(x, 0, 0, levels[x]);
        }
        int[] rgb = Picture.readPixels(written(deep, "png", "deep.png")).rgb();
        int[] expected = {0, 0, 1, 127, 128, 128, 254, 255, 255};
        for (int x = 0; x < levels.length; x++) {
            assertEquals(expected[x] * 0x010101, rgb[x], "level " + levels[x]);
        }
    }

    @Test
    void aCmykJpegOfThePagePasses() throws Exception {
        // Java's JPEG writer stores a raster's four bands as CMYK without an Adobe marker, and readers
        // (ImageIO, Pillow) take ink 255 - s of each sample s: a viewer shows red c * k / 255 and so on,
        // so samples (v, v, v, 255) are grey v with no black ink.
        BufferedImage page = page3();
        WritableRaster cmyk = Raster.createInterleavedRaster(DataBuffer.TYPE_BYTE, page.getWidth(), page.getHeight(), 4,
                null);
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                int v = page.getRGB(x, y) & 0xFF;
                cmyk.setPixel(x, y, new int[] {v, v, v, 255});
            }
        }
        Path file = jpeg(new IIOImage(cmyk, null, null), "page3.jpg");
        assertEquals(ColorSpace.TYPE_CMYK, colourSpace(file));
        passes(page, file);
    }

    @Test
    void cmykIsMixedAsBrowsersMixIt() throws Exception {
        // 8x8 blocks of one colour each: a JPEG at the best quality keeps them to within a level or two
        int[][] samples = {{61, 100, 20, 30}, {255, 0, 128, 255}, {200, 200, 200, 128}};
        WritableRaster cmyk = Raster.createInterleavedRaster(DataBuffer.TYPE_BYTE, 8 * samples.length, 8, 4, null);
        for (int b = 0; b < samples.length; b++) {
            for (int y = 0; y < 8; y++) {
                for (int x = 0; x < 8; x++) {
                    cmyk.setPixel(8 * b + x, y, samples[b]);
                }
            }
        }
        int[] rgb = Picture.readPixels(jpeg(new IIOImage(cmyk, null, null), "mixed.jpg")).rgb();
        for (int b = 0; b < samples.length; b++) {
            int[] s = samples[b];
            int expected = Math.round(s[0] * s[3] / 255f) << 16 | Math.round(s[1] * s[3] / 255f) << 8
                    | Math.round(s[2] * s[3] / 255f);
            int read = rgb[3 * cmyk.getWidth() + 8 * b + 3];
            assertTrue(Rasters.distance(expected, read) <= 2,
                    "block " + b + ": " + Integer.toHexString(read) + " for " + Integer.toHexString(expected));
        }
    }
}
