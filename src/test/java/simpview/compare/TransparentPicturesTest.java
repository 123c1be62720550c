package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;

import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A picture whose panel is not opaque is refused, whatever its format: a viewer shows what lies
 * behind its pixels, not their colours. Transparency outside the panel (a window capture's
 * shadow) does not matter.
 */
class TransparentPicturesTest {

    @TempDir
    Path dir;

    /** The page in ARGB, each pixel's alpha {@code alpha.at(x, y)}. */
    private static BufferedImage withAlpha(BufferedImage page, Alpha alpha) {
        BufferedImage argb = new BufferedImage(page.getWidth(), page.getHeight(), BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                argb.setRGB(x, y, alpha.at(x, y) << 24 | page.getRGB(x, y) & 0xFFFFFF);
            }
        }
        return argb;
    }

    private interface Alpha {
        int at(int x, int y);
    }

    private Path png(BufferedImage image, String name) throws Exception {
        Path file = dir.resolve(name);
        assertTrue(ImageIO.write(image, "png", file.toFile()));
        return file;
    }

    private static String refusal(Path file) {
        return assertThrows(CompareException.class, () -> Picture.read(file)).getMessage();
    }

    @Test
    void aFullyTransparentPageIsRefused() throws Exception {
        Path file = png(withAlpha(page(4), (x, y) -> 0), "page4.png");
        assertEquals(file + ": 422,500 of the panel's 422,500 pixels are not opaque (alpha below 255), and a viewer "
                + "shows what lies behind them, not their colours: save the picture without transparency", refusal(file));
    }

    @Test
    void onePixelHalfTransparentIsEnough() throws Exception {
        Path file = png(withAlpha(page(4), (x, y) -> x == 300 && y == 400 ? 128 : 255), "page4.png");
        assertTrue(refusal(file).contains(": 1 of the panel's 422,500 pixels is not opaque"), refusal(file));
    }

    @Test
    void transparentMarginsOrAnOpaqueAlphaChannelAreNoMatter() throws Exception {
        BufferedImage page = page(4);
        Path opaque = png(withAlpha(page, (x, y) -> 255), "opaque.png");
        assertArrayEquals(Picture.ofPage(page, "ours").panel(), Picture.read(opaque).panel());
        Path corners = png(withAlpha(page, (x, y) -> x < 20 && y < 20 ? 0 : 255), "corners.png");
        assertArrayEquals(Picture.ofPage(page, "ours").panel(), Picture.read(corners).panel());
    }

    @Test
    void aPalettePictureWithATransparentColourIsRefused() throws Exception {
        // page 3 is grey: a palette of the 256 grey levels, black (its background) transparent
        BufferedImage page = page(3);
        byte[] levels = new byte[256];
        byte[] alpha = new byte[256];
        for (int i = 0; i < 256; i++) {
            levels[i] = (byte) i;
            alpha[i] = (byte) (i == 0 ? 0 : 255);
        }
        BufferedImage indexed = new BufferedImage(page.getWidth(), page.getHeight(), BufferedImage.TYPE_BYTE_INDEXED,
                new IndexColorModel(8, 256, levels, levels, levels, alpha));
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                indexed.getRaster().setSample(x, y, 0, page.getRGB(x, y) & 0xFF);
            }
        }
        Path file = png(indexed, "page3.png");
        PngCodec.Pixels decoded = PngCodec.decode(Files.readAllBytes(file));
        int black = 60 * page.getWidth() + 60;
        assertEquals(0, page.getRGB(60, 60) & 0xFFFFFF, "the panel's corner is background");
        assertEquals(0, decoded.alpha()[black], "the palette's tRNS chunk is read, not left to ImageIO");
        assertEquals(-1, decoded.alpha()[0], "white is opaque");
        assertTrue(refusal(file).contains("pixels are not opaque"), refusal(file));
    }

    @Test
    void aSixteenBitGreyPictureWithAlphaIsRefused() throws Exception {
        Path file = png(PictureFormatsTest.greyWithAlpha16(page(3), 1000), "page3.png");
        assertTrue(refusal(file).contains(": 422,500 of the panel's 422,500 pixels are not opaque"), refusal(file));
    }

    @Test
    void anOpaquePictureHasNoAlpha() throws Exception {
        assertNull(PngCodec.decode(Files.readAllBytes(png(page(4), "page4.png"))).alpha());
    }
}
