package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import simpview.testing.Images;

/** The page view's picture below 1:1, which it keeps from paint to paint. */
class PageViewTest {

    private static BufferedImage page(int rgb) {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        Arrays.fill(((DataBufferInt) page.getRaster().getDataBuffer()).getData(), rgb);
        return page;
    }

    /**
     * A turning drag's frames are drawn on the images of frames shown before: an image may come back with
     * another picture in it, even before the picture shown between was ever painted. Its picture below 1:1 is
     * then made again, not kept from the first time.
     */
    @Test
    void anImageThatComesBackWithAnotherPictureIsMadeSmallAgain() throws Throwable {
        DevicePixelsTest.onEdt(() -> {
            PageView view = new PageView();
            view.zoomPan().zoomAbout(0, 0, 0.5);
            assertTrue(view.zoomPan().zoom() < 1, "below 1:1: " + view.zoomPan().zoom());
            BufferedImage first = page(0xFFFFFF);
            view.show(first, null);
            view.shownSmall();
            view.show(page(0x000000), null); // shown, never painted
            Arrays.fill(((DataBufferInt) first.getRaster().getDataBuffer()).getData(), 0x3366CC);
            view.show(first, null);
            assertEquals(0, Images.differingPixels(LineKeepingDownscale.of(first, view.zoomPan().zoom()),
                    view.shownSmall()), "the picture it holds now");
        });
    }
}
