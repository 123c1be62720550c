package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * A page handed off whole instead of copied ({@link PageCanvas#handOff}):
 * the page as it was drawn, left alone from then on, and the canvas going on
 * on another image, every pixel of which its next clear makes, on one thread
 * and on two (where the clear owes the panel's rows).
 */
class HandOffTest {

    private static final int UNMADE = 0xABCDEF;

    private static int[] pixels(BufferedImage image) {
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData().clone();
    }

    /** A page image holding another picture: every pixel one colour no clear makes. */
    private static BufferedImage spare() {
        BufferedImage spare = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);
        Arrays.fill(((DataBufferInt) spare.getRaster().getDataBuffer()).getData(), UNMADE);
        return spare;
    }

    @Test
    void thePageHandedOffIsThePageAndTheClearMakesTheSpareWhole() {
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                PageCanvas canvas = new PageCanvas();
                canvas.drawWith(drawing);
                canvas.clear();
                for (int k = 0; k < 100; k++) {
                    canvas.panel().setPixel(3 * k, 2 * k, 0, 0x010203 * k);
                }
                int[] drawn = pixels(canvas.snapshot());
                BufferedImage spare = spare();
                BufferedImage page = canvas.handOff(spare);
                assertArrayEquals(drawn, pixels(page), threads + " thread(s): the page as drawn");
                assertThrows(IllegalStateException.class, canvas::image, "no page until the canvas is cleared");
                assertThrows(IllegalStateException.class, canvas::snapshot);

                canvas.clear();
                assertSame(spare, canvas.image(), "drawn on the spare from now on");
                PageCanvas fresh = new PageCanvas();
                fresh.drawWith(drawing);
                fresh.clear();
                assertArrayEquals(pixels(fresh.image()), pixels(spare), threads + " thread(s): every pixel made");
                canvas.panel().setPixel(5, 5, 0, 0x777777);
                assertArrayEquals(drawn, pixels(page), "the page handed off is not drawn on again");
            }
        }
    }

    @Test
    void withNoSpareOrOneThatIsNoPageTheCanvasGoesOnOnANewImage() {
        BufferedImage argb = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_ARGB);
        BufferedImage small = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE - 1, BufferedImage.TYPE_INT_RGB);
        for (BufferedImage spare : Arrays.asList(null, argb, small)) {
            PageCanvas canvas = new PageCanvas();
            BufferedImage page = canvas.handOff(spare);
            canvas.clear();
            BufferedImage next = canvas.image();
            assertNotSame(page, next);
            assertNotSame(spare, next);
            assertEquals(PageCanvas.SIZE, next.getWidth());
            assertEquals(PageCanvas.SIZE, next.getHeight());
            assertEquals(BufferedImage.TYPE_INT_RGB, next.getType());
        }
    }

    @Test
    void anImageOfAnotherSizeOrTypeIsRefused() {
        ImageDrawable drawable = new ImageDrawable(new BufferedImage(8, 6, BufferedImage.TYPE_INT_RGB));
        assertThrows(IllegalArgumentException.class,
                () -> drawable.exchange(new BufferedImage(8, 7, BufferedImage.TYPE_INT_RGB)));
        assertThrows(IllegalArgumentException.class,
                () -> drawable.exchange(new BufferedImage(9, 6, BufferedImage.TYPE_INT_RGB)));
        assertThrows(IllegalArgumentException.class,
                () -> drawable.exchange(new BufferedImage(8, 6, BufferedImage.TYPE_INT_ARGB)));
        BufferedImage next = new BufferedImage(8, 6, BufferedImage.TYPE_INT_RGB);
        drawable.exchange(next);
        drawable.setPixel(1, 1, 0, 0x123456);
        assertEquals(0x123456, pixels(next)[8 + 1], "written to the image exchanged for");
    }
}
