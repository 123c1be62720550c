package simpview.testing;

import java.awt.image.BufferedImage;

/** Pixel comparisons for the tests. */
public final class Images {

    private Images() {
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
