package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** The inspector's words for a pixel of the first assignment's pages. */
class A1PixelTest {

    @Test
    void aSpokesPixelNamesThePanelTheDrawerAndTheLine() {
        // Panel 1's (285, 150) is the end of spoke 1 (0 degrees): image (50 + 285, 50 + 299 - 150).
        assertEquals("panel 1, x 285, y 150 · DDA · line 1 of 90, (150, 150) to (285, 150)",
                A1Pixel.describe(1, 361, A1Rule.SPEC, 335, 199));
        assertEquals("panel 3, x 285, y 150 · alternating DDA / Bresenham · line 1 of 90, (150, 150) to (285, 150)",
                A1Pixel.describe(1, 361, A1Rule.SPEC, 335, 549));
    }

    @Test
    void anAntialiasedPixelAlsoGetsItsDistanceAndCoverage() {
        assertEquals("panel 4, x 200, y 150 · antialiased · line 1 of 90, (150, 150) to (285, 150)"
                + " · distance 0.000, coverage 0.818", A1Pixel.describe(1, 361, A1Rule.SPEC, 600, 549));
        assertEquals("panel 4, x 200, y 151 · antialiased · line 1 of 90, (150, 150) to (285, 150)"
                + " · distance 1.000, coverage 0.091", A1Pixel.describe(1, 361, A1Rule.SPEC, 600, 548));
    }

    @Test
    void theCentreIsTheLastOfManyAndTheGutterIsNoPanel() {
        assertEquals("panel 2, x 150, y 150 · Bresenham · line 90 of 90, (150, 150) to (285, 141), the last of 90 lines here",
                A1Pixel.describe(1, 361, A1Rule.SPEC, 550, 199));
        assertNull(A1Pixel.describe(1, 361, A1Rule.SPEC, 375, 100));
        assertEquals("panel 2, x 0, y 0 · filled · no triangle drew it (background)", A1Pixel.describe(4, 361, A1Rule.SPEC, 400, 349));
        assertEquals("panel 2, x 150, y 150 · ghost (white, opacity 0.14) · triangle 81 of 162",
                A1Pixel.describe(5, 361, A1Rule.SPEC, 550, 199));
    }
}
