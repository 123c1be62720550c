package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import simpview.scene.SceneException;
import simpview.surface.Colors;
import simpview.surface.PageCanvas;

/** The first assignment's five pages: layout, seeds, and what the ghost page must show exactly. */
class Assignment1PagesTest {

    private static BufferedImage draw(int page, long seed) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        Assignment1.page(page).draw(canvas, PageContext.defaults().withSeed(seed));
        return canvas.snapshot();
    }

    @Test
    void everyPageIsWhiteWithFourBlackFramedPanels() throws SceneException {
        for (int page = 1; page <= Assignment1.COUNT; page++) {
            BufferedImage image = draw(page, 7);
            for (int y = 0; y < 750; y++) {
                for (int x = 0; x < 750; x++) {
                    if (A1Layout.panelAt(x, y) == 0) {
                        assertEquals(0xFFFFFF, image.getRGB(x, y) & 0xFFFFFF, "page " + page + " margin at " + x + "," + y);
                    }
                }
            }
            // The panels' corners (a line may not reach them): black.
            for (int k = 1; k <= 4; k++) {
                assertEquals(0, image.getRGB(A1Layout.left(k), A1Layout.top(k)) & 0xFFFFFF, "page " + page + " panel " + k);
            }
        }
        assertEquals(1, A1Layout.panelAt(50, 50));
        assertEquals(2, A1Layout.panelAt(400, 349));
        assertEquals(3, A1Layout.panelAt(50, 400));
        assertEquals(4, A1Layout.panelAt(699, 699));
        assertEquals(0, A1Layout.panelAt(350, 200));
    }

    @Test
    void theSeedDecidesTheRandomPagesAndOnlyThem() throws SceneException {
        for (int page = 1; page <= Assignment1.COUNT; page++) {
            boolean seeded = Assignment1.page(page).usesSeed();
            assertEquals(page >= 3, seeded, "page " + page);
            int[] a = draw(page, 1).getRGB(0, 0, 750, 750, null, 0, 750);
            int[] b = draw(page, 1).getRGB(0, 0, 750, 750, null, 0, 750);
            int[] c = draw(page, 2).getRGB(0, 0, 750, 750, null, 0, 750);
            assertTrue(Arrays.equals(a, b), "page " + page + ": the same seed, the same picture");
            assertEquals(!seeded, Arrays.equals(a, c), "page " + page);
        }
    }

    /** Page 3: the same 30 lines on all four panels; the DDA panel and the Bresenham panel light the same pixels but at ties. */
    @Test
    void randomLinesAreTheSameOnEveryPanel() throws SceneException {
        A1Lines lines = A1Lines.random(5);
        assertEquals(30, lines.count());
        for (int i = 0; i < lines.count(); i++) {
            double x = lines.start(i).x();
            assertTrue(x == Math.floor(x) && x >= 0 && x < 300);
            assertEquals(lines.start(i).r(), lines.end(i).r());
        }
        assertNotEquals(A1Lines.random(5).start(0), A1Lines.random(6).start(0));
    }

    /**
     * Page 5's mesh panel: with the top-left rule no pixel is written twice,
     * so every pixel of the mesh is the one grey 0.14 * 255 = 35.7, 36.
     */
    @Test
    void theGhostMeshPanelIsOneFlatGrey() throws SceneException {
        BufferedImage image = draw(5, 361);
        Set<Integer> colours = new HashSet<>();
        int grey = 0;
        for (int y = 0; y < 300; y++) {
            for (int x = 0; x < 300; x++) {
                int c = image.getRGB(A1Layout.left(2) + x, A1Layout.top(2) + y) & 0xFFFFFF;
                colours.add(c);
                grey += c == 0x242424 ? 1 : 0;
            }
        }
        assertEquals(Set.of(0, 0x242424), colours);
        // The grid spans 15..285: 270 x 270 pixels.
        assertEquals(270 * 270, grey);
        // The perturbed mesh too: black and the one grey, nothing brighter.
        Set<Integer> perturbed = new HashSet<>();
        for (int y = 0; y < 300; y++) {
            for (int x = 0; x < 300; x++) {
                perturbed.add(image.getRGB(A1Layout.left(3) + x, A1Layout.top(3) + y) & 0xFFFFFF);
            }
        }
        assertEquals(Set.of(0, 0x242424), perturbed);
    }

    /** Page 5's random triangles: a pixel under n triangles has grey 1 - 0.86^n, each step rounded to a byte. */
    @Test
    void ghostGreysCountTheTrianglesOverAPixel() throws SceneException {
        BufferedImage image = draw(5, 361);
        Set<Integer> allowed = new HashSet<>();
        int level = 0;
        allowed.add(0);
        for (int n = 1; n <= 20; n++) {
            level = Colors.toByte(0.14 + 0.86 * level / 255.0);
            allowed.add(level);
        }
        for (int y = 0; y < 300; y++) {
            for (int x = 0; x < 300; x++) {
                int c = image.getRGB(A1Layout.left(4) + x, A1Layout.top(4) + y) & 0xFF;
                assertTrue(allowed.contains(c), "grey " + c + " at " + x + "," + y);
            }
        }
    }
}
