package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The two blending decorators: coverage (c colour + (1 - c) old) and the ghost (white at 0.14). */
class CoverageAndGhostTest {

    private static ImageDrawable image(int argb) {
        ImageDrawable d = new ImageDrawable(new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB));
        d.fillRect(0, 0, 4, 4, argb);
        return d;
    }

    @Test
    void coverageBlendsPerChannelAndOneWritesTheColour() {
        ImageDrawable target = image(Colors.pack(0.2, 0.4, 1));
        CoverageDrawable blend = new CoverageDrawable(target);
        blend.cover(0.25);
        blend.setPixel(1, 1, -1, Colors.pack(1, 0, 0.6));
        // Each channel in [0, 1]: 0.25 c + 0.75 old, then round(x * 255).
        double r = 0.25 * 1 + 0.75 * Colors.toByte(0.2) / 255.0;
        double g = 0.75 * Colors.toByte(0.4) / 255.0;
        double b = 0.25 * Colors.toByte(0.6) / 255.0 + 0.75;
        assertEquals(Colors.pack(r, g, b), target.getPixel(1, 1));
        blend.cover(1);
        blend.setPixel(2, 2, -1, 0xFF123456);
        assertEquals(0xFF123456, target.getPixel(2, 2));
    }

    @Test
    void aGhostWriteIsWhiteAtOpacity014WhateverTheColour() {
        ImageDrawable target = image(Colors.BLACK);
        GhostWritingDrawable ghost = new GhostWritingDrawable(target);
        ghost.setPixel(0, 0, 0, 0xFFFF0000);
        assertEquals(0xFF242424, target.getPixel(0, 0), "0.14 * 255 = 35.7: grey 36");
        ghost.setPixel(0, 0, 0, 0xFF00FF00);
        // 0.14 + 0.86 * 36/255 = 0.2614 -> 66.7: 67.
        assertEquals(0xFF434343, target.getPixel(0, 0));
    }

    @Test
    void aGhostSpanWritesEachPixelOnce() {
        ImageDrawable target = image(Colors.BLACK);
        Span span = new Span();
        span.y = 1;
        span.x0 = 1;
        span.x1 = 3;
        span.xBase = 1;
        new GhostWritingDrawable(target).fillSpan(span);
        assertEquals(0xFF000000, target.getPixel(0, 1));
        assertEquals(0xFF242424, target.getPixel(1, 1));
        assertEquals(0xFF242424, target.getPixel(2, 1));
        assertEquals(0xFF000000, target.getPixel(3, 1));
    }

    /** A ghost span means what its pixels one by one mean, over any greys and colours, clipped by a panel. */
    @Test
    void aGhostSpanIsItsPixelsOneByOne() {
        Random random = new Random(5);
        ImageDrawable spans = image(Colors.BLACK);
        ImageDrawable pixels = image(Colors.BLACK);
        ImageDrawable[] both = {spans, pixels};
        for (ImageDrawable d : both) {
            for (int i = 0; i < 16; i++) {
                d.setPixel(i % 4, i / 4, 0, 0xFF000000 | (i * 0x0B1D07 & 0xFFFFFF));
            }
        }
        GhostWritingDrawable bySpan = new GhostWritingDrawable(new PanelDrawable(spans, 1, 0, 3));
        GhostWritingDrawable byPixel = new GhostWritingDrawable(new PanelDrawable(pixels, 1, 0, 3));
        Span span = new Span();
        for (int trial = 0; trial < 40; trial++) {
            span.y = random.nextInt(5) - 1;
            span.x0 = random.nextInt(5) - 1;
            span.x1 = span.x0 + random.nextInt(5);
            span.xBase = span.x0;
            bySpan.fillSpan(span);
            for (int x = span.x0; x < span.x1; x++) {
                byPixel.setPixel(x, span.y, 0, 0xFFFFFFFF);
            }
        }
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 4; x++) {
                assertEquals(pixels.getPixel(x, y), spans.getPixel(x, y), x + "," + y);
            }
        }
        assertEquals(false, bySpan.usesColour(), "a ghost's colour is always white");
    }
}
