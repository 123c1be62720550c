package simpview.testing;

import java.awt.image.BufferedImage;
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
        long count = 0;
        for (int y = fromRow; y < toRow; y++) {
            for (int x = 0; x < expected.getWidth(); x++) {
                if ((expected.getRGB(x, y) & 0xFFFFFF) != (actual.getRGB(x, y) & 0xFFFFFF)) {
                    count++;
                }
            }
        }
        return count;
    }
}
