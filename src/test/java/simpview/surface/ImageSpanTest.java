package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;

/**
 * A span filled into the image ({@link ImageDrawable#fillSpan}) gets, at
 * every pixel, what {@link Span#argbAt} gives that pixel alone: for spans
 * whose channels stay inside the byte range, end just outside it (where
 * truncating is not flooring, c + k dc + 0.5 in (-1, 0)), or need the clamp;
 * for short and long spans (longer than the packing loop's ramp), and spans
 * of one shade.
 */
class ImageSpanTest {

    private static final int WIDTH = 2100;

    /** A channel's start and slope over a span of {@code length} pixels. */
    private static double[] channel(Random random, int length) {
        double start;
        double end;
        switch (random.nextInt(5)) {
            case 0 -> { // ends just below the range: rounds to 0 by truncation, -1 by floor
                start = -0.5 - random.nextDouble() * 0.5;
                end = random.nextDouble() * 255;
            }
            case 1 -> { // ends just above it
                start = random.nextDouble() * 255;
                end = 254.5 + random.nextDouble() * 1.5;
            }
            case 2 -> { // needs the clamp
                start = -40 + random.nextDouble() * 20;
                end = 260 + random.nextDouble() * 40;
            }
            case 3 -> { // flat
                start = random.nextDouble() * 255;
                end = start;
            }
            default -> { // inside
                start = random.nextDouble() * 255;
                end = random.nextDouble() * 255;
            }
        }
        if (random.nextBoolean()) {
            double t = start;
            start = end;
            end = t;
        }
        return new double[] {start, length > 1 ? (end - start) / (length - 1) : 0};
    }

    @Property(tries = 300, seed = "1204010")
    void aFilledSpanIsEachPixelsOwnColour(@ForAll long seed) {
        Random random = new Random(seed);
        BufferedImage image = new BufferedImage(WIDTH, 3, BufferedImage.TYPE_INT_RGB);
        ImageDrawable drawable = new ImageDrawable(image);
        Span s = new Span();
        for (int round = 0; round < 8; round++) {
            int length = random.nextBoolean() ? 1 + random.nextInt(20) : 1 + random.nextInt(WIDTH);
            s.y = random.nextInt(3);
            s.x0 = random.nextInt(WIDTH - length + 1) - random.nextInt(3);
            s.x1 = s.x0 + length;
            s.xBase = s.x0 + random.nextInt(5) - 2;
            double[] r = channel(random, length);
            double[] g = random.nextInt(3) == 0 ? r : channel(random, length); // one shade now and then
            double[] b = random.nextInt(3) == 0 ? r : channel(random, length);
            s.r = r[0];
            s.dr = r[1];
            s.g = g[0];
            s.dg = g[1];
            s.b = b[0];
            s.db = b[1];
            drawable.fillSpan(s);
            for (int x = Math.max(s.x0, 0); x < Math.min(s.x1, WIDTH); x++) {
                assertEquals(s.argbAt(x) & 0xFFFFFF, image.getRGB(x, s.y) & 0xFFFFFF,
                        "pixel " + x + " of a span " + s.x0 + ".." + s.x1 + " from " + s.xBase);
            }
        }
    }

    @Test
    void aChannelEndingWhereTruncatingIsNotFlooringKeepsItsLevels() {
        BufferedImage image = new BufferedImage(64, 1, BufferedImage.TYPE_INT_RGB);
        Span s = new Span();
        s.x0 = 0;
        s.x1 = 40;
        s.r = -0.9; // + 0.5 is -0.4: level 0, where a floor would make it -1
        s.dr = 6;
        s.g = 100;
        s.dg = 1;
        s.b = 200;
        s.db = -1;
        new ImageDrawable(image).fillSpan(s);
        for (int x = 0; x < 40; x++) {
            assertEquals(s.argbAt(x) & 0xFFFFFF, image.getRGB(x, 0) & 0xFFFFFF, "pixel " + x);
        }
        assertEquals(0x0064C8, image.getRGB(0, 0) & 0xFFFFFF);
    }
}
