package simpview.testing;

import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.DirectColorModel;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;

/** Pixel comparisons for the tests, and the pictures they hand simpview. */
public final class Images {

    private Images() {
    }

    /** Page {@code number} of the eight as simpview draws it by default (seed 361, its own scene folder). */
    public static BufferedImage page(int number) throws SceneException {
        return new PageRenderer().renderImage(number, PageContext.defaults());
    }

    /** Writes {@code image} to {@code file} as a PNG, making its folders first; returns the file. */
    public static Path writePng(Path file, BufferedImage image) throws IOException {
        Files.createDirectories(file.getParent());
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    /** Paints the pixels x0 &lt;= x &lt; x1, y0 &lt;= y &lt; y1 of {@code image} (rows down from the top) {@code rgb}; returns it. */
    public static BufferedImage paint(BufferedImage image, int x0, int y0, int x1, int y1, int rgb) {
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                image.setRGB(x, y, rgb);
            }
        }
        return image;
    }

    /** How many pixels differ in colour (alpha ignored); every pixel counts when the sizes differ. */
    public static long differingPixels(BufferedImage expected, BufferedImage actual) {
        if (expected.getWidth() != actual.getWidth() || expected.getHeight() != actual.getHeight()) {
            return (long) expected.getWidth() * expected.getHeight();
        }
        return differingPixels(expected, actual, 0, expected.getHeight());
    }

    /** The same, over the rows {@code fromRow} (inclusive) to {@code toRow} (exclusive). */
    public static long differingPixels(BufferedImage expected, BufferedImage actual, int fromRow, int toRow) {
        int w = expected.getWidth();
        int[] a = rgb(expected, 0, fromRow, w, toRow - fromRow);
        int[] b = rgb(actual, 0, fromRow, w, toRow - fromRow);
        long count = 0;
        for (int i = 0; i < a.length; i++) {
            count += a[i] != b[i] ? 1 : 0;
        }
        return count;
    }

    /** Every pixel of {@code image} as {@code getRGB(x, y) & 0xFFFFFF} would give it, row by row from the top. */
    public static int[] rgb(BufferedImage image) {
        return rgb(image, 0, 0, image.getWidth(), image.getHeight());
    }

    /**
     * The pixels of the w x h rectangle whose top-left pixel is (left, top), each as
     * {@code getRGB(x, y) & 0xFFFFFF} would give it, row by row. getRGB converts every pixel through
     * the colour model, 20-30 ms a 750x750 picture; where that conversion gives the samples
     * themselves (red, green and blue of 8 bits in sRGB, alpha not multiplied in) they are read
     * from the raster at once, and any other picture is read by one getRGB over the rectangle.
     */
    public static int[] rgb(BufferedImage image, int left, int top, int w, int h) {
        int[] out = new int[w * h];
        if (packedRgb(image.getColorModel())) {
            image.getRaster().getDataElements(left, top, w, h, out);
            for (int i = 0; i < out.length; i++) {
                out[i] &= 0xFFFFFF;
            }
            return out;
        }
        if (!samplesAreSrgb(image.getColorModel())) {
            image.getRGB(left, top, w, h, out, 0, w);
            for (int i = 0; i < out.length; i++) {
                out[i] &= 0xFFFFFF;
            }
            return out;
        }
        int bands = image.getRaster().getNumBands();
        int[] samples = image.getRaster().getPixels(left, top, w, h, (int[]) null);
        for (int i = 0, s = 0; i < out.length; i++, s += bands) {
            out[i] = samples[s] << 16 | samples[s + 1] << 8 | samples[s + 2];
        }
        return out;
    }

    /** Pixels packed in an int as 0x..RRGGBB in sRGB, alpha (if any) not multiplied in: TYPE_INT_RGB and _ARGB. */
    private static boolean packedRgb(ColorModel model) {
        return model instanceof DirectColorModel direct && direct.getTransferType() == DataBuffer.TYPE_INT
                && direct.getRedMask() == 0xFF0000 && direct.getGreenMask() == 0xFF00 && direct.getBlueMask() == 0xFF
                && direct.getColorSpace().isCS_sRGB() && !direct.isAlphaPremultiplied();
    }

    private static boolean samplesAreSrgb(ColorModel model) {
        if (!(model instanceof DirectColorModel || model instanceof ComponentColorModel)
                || !model.getColorSpace().isCS_sRGB() || model.isAlphaPremultiplied()
                || model.getNumColorComponents() != 3) {
            return false;
        }
        for (int size : model.getComponentSize()) {
            if (size != 8) {
                return false;
            }
        }
        return true;
    }
}
