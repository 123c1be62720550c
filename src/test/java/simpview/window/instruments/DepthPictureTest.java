package simpview.window.instruments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.surface.PageCanvas;

/** The depth view's pixels are the z-buffer's values: near white, far black, untouched marked. */
public class DepthPictureTest {

    @Test
    void everyPanelPixelIsTheGreyOfItsDepthAndUntouchedOnesAreMarked() throws Exception {
        for (int page : new int[] {3, 4, 5}) {
            PageRenderer renderer = new PageRenderer();
            PageCanvas canvas = renderer.render(page, PageContext.defaults());
            double[] depths = canvas.zbuffer().copyDepths();
            BufferedImage picture = DepthPicture.of(depths, canvas.zbuffer().farthest());
            int[] shown = picture.getRGB(0, 0, picture.getWidth(), picture.getHeight(), null, 0, picture.getWidth());
            int touched = 0;
            int untouched = 0;
            for (int y = 0; y < PageCanvas.PANEL; y++) {
                for (int x = 0; x < PageCanvas.PANEL; x++) {
                    double z = canvas.zbuffer().depthAt(x, y);
                    int expected;
                    if (z == -200) {
                        expected = DepthPicture.UNTOUCHED;
                        untouched++;
                    } else {
                        int v = (int) Math.round(255 * (z + 200) / 200);
                        expected = 0xFF000000 | v << 16 | v << 8 | v;
                        touched++;
                    }
                    int ix = PageCanvas.MARGIN + x;
                    int iy = PageCanvas.MARGIN + PageCanvas.PANEL - 1 - y;
                    assertEquals(expected, shown[iy * picture.getWidth() + ix], "page " + page + " pixel (" + x + ", " + y + ") z " + z);
                }
            }
            assertTrue(touched > 10_000 && untouched > 1000, "page " + page + ": " + touched + " touched, " + untouched + " not");
            assertEquals(0xFFFFFFFF, picture.getRGB(10, 10), "margins white");
        }
    }
}
