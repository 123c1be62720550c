package simpview.window.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** The images a window gave back: each kept once, at most two, each taken once. */
class SpareImagesTest {

    private static BufferedImage page() {
        return new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
    }

    @Test
    void eachImageIsKeptOnceAndAtMostTwoAreKept() {
        SpareImages spares = new SpareImages();
        assertNull(spares.take(), "none given back yet");
        BufferedImage a = page();
        BufferedImage b = page();
        spares.giveBack(a);
        spares.giveBack(a);
        assertEquals(1, spares.count(), "given twice, kept once");
        spares.giveBack(b);
        spares.giveBack(page());
        assertEquals(SpareImages.KEPT, spares.count(), "the third left to the collector");
        assertSame(b, spares.take());
        assertSame(a, spares.take());
        assertNull(spares.take(), "each taken once");
    }
}
