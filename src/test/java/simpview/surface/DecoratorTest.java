package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;
import simpview.geometry.Vertex;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;

class DecoratorTest {

    private final FilledPolygonRenderer filled = new FilledPolygonRenderer();

    private static Vertex[] triangle(double z, double grey) {
        return new Vertex[] {new Vertex(100, 100, z, grey, grey, grey), new Vertex(500, 120, z, grey, grey, grey),
            new Vertex(300, 520, z, grey, grey, grey)};
    }

    private void draw(Vertex[] t, Drawable d) {
        filled.drawPolygon(t[0], t[1], t[2], d);
    }

    @Test
    void theZBufferKeepsTheNearerTriangleInEitherOrder() {
        Vertex[] near = triangle(-20, 1);
        Vertex[] far = triangle(-120, 0.5);
        for (boolean nearFirst : new boolean[] {true, false}) {
            PageCanvas canvas = new PageCanvas();
            Drawable target = canvas.depthTested();
            draw(nearFirst ? near : far, target);
            draw(nearFirst ? far : near, target);
            assertEquals(Colors.WHITE, canvas.panel().getPixel(300, 250), "near first: " + nearFirst);
            assertEquals(-20, canvas.zbuffer().depthAt(300, 250));
        }
    }

    @Test
    void ofTwoWritesAtEqualDepthTheFirstStays() {
        PageCanvas canvas = new PageCanvas();
        Drawable target = canvas.depthTested();
        draw(triangle(-50, 1), target);
        draw(triangle(-50, 0.5), target);
        assertEquals(Colors.WHITE, canvas.panel().getPixel(300, 250));
    }

    @Test
    void theZBufferStartsAtTheFarPlaneAndRejectsWritesThere() {
        PageCanvas canvas = new PageCanvas();
        assertEquals(-200, canvas.zbuffer().depthAt(0, 0));
        assertEquals(-200, canvas.zbuffer().depthAt(649, 649));
        draw(triangle(-200, 1), canvas.depthTested());
        assertEquals(Colors.BLACK, canvas.panel().getPixel(300, 250));
    }

    /** A reset skips the fill while nothing was written: each way of writing a depth must say it wrote. */
    @Test
    void aResetAfterWritingAnyWayBringsBackTheFarPlane() {
        PageCanvas canvas = new PageCanvas();
        ZBuffer z = canvas.zbuffer();
        canvas.depthTested().setPixel(10, 10, -50, Colors.WHITE);
        assertFalse(z.atFarPlane());
        canvas.clear();
        assertEquals(-200, z.depthAt(10, 10));
        assertTrue(z.atFarPlane());

        draw(triangle(-50, 1), canvas.depthCued(Rgb.WHITE, Rgb.BLACK));
        assertEquals(-50, z.depthAt(300, 250));
        canvas.clear();
        assertEquals(-200, z.depthAt(300, 250));
    }

    @Test
    void drawingWithoutDepthOrBehindEverythingLeavesTheResetNothingToDo() {
        PageCanvas canvas = new PageCanvas();
        draw(triangle(-50, 1), canvas.panel());
        draw(triangle(-200, 1), canvas.depthTested()); // at the far plane: every pixel loses
        canvas.depthTested().setPixel(10, 10, -250, Colors.WHITE);
        assertTrue(canvas.zbuffer().atFarPlane());
    }

    @Test
    void depthCueAtMinus150IsAQuarterOfTheNearColour() {
        // 0.25 * 255 = 63.75, which rounds to 64; a quarter of (0, 1, 0) is (0, 64, 0).
        PageCanvas canvas = new PageCanvas();
        draw(triangle(-150, 0.9), canvas.depthCued(Rgb.WHITE, Rgb.BLACK));
        assertEquals(0xFF404040, canvas.panel().getPixel(300, 250));
        canvas.clear();
        new DdaLineRenderer().drawLine(Vertex.of(10, 10, -150), Vertex.of(600, 10, -150),
                canvas.depthCued(Rgb.GREEN, Rgb.BLACK));
        assertEquals(0xFF004000, canvas.panel().getPixel(300, 10));
    }

    @Test
    void depthCueAtTheNearAndFarPlanes() {
        DepthCueDrawable cue = new DepthCueDrawable(new Rgb(1, 0.5, 0.2), new Rgb(0.2, 0.1, 0), Camera.PARALLEL, new ImageDrawable(
                new BufferedImage(4, 1, BufferedImage.TYPE_INT_RGB)));
        cue.setPixel(0, 0, 0, 0);
        cue.setPixel(1, 0, -200, 0);
        cue.setPixel(2, 0, -100, 0);
        assertEquals(Colors.pack(1, 0.5, 0.2), cue.getPixel(0, 0));
        assertEquals(Colors.pack(0.2, 0.1, 0), cue.getPixel(1, 0));
        assertEquals(Colors.pack(0.6, 0.3, 0.1), cue.getPixel(2, 0));
    }

    /**
     * SPEC's round(c * 255) of far + (near - far) (z + 200) / 200: from white
     * to black, z = -20, -60, -100, -140 and -180 put c * 255 exactly on a
     * half (229.5, 178.5, 127.5, 76.5, 25.5), which rounds up; so do whole
     * spans at those depths, and a span's run of pixels at one depth.
     */
    @Test
    void aDepthWhoseLevelIsExactlyAHalfRoundsUp() {
        int[] depths = {-20, -60, -100, -140, -180};
        int[] levels = {230, 179, 128, 77, 26};
        DepthCueDrawable cue = new DepthCueDrawable(Rgb.WHITE, Rgb.BLACK, Camera.PARALLEL, new ImageDrawable(
                new BufferedImage(5, 2, BufferedImage.TYPE_INT_RGB)));
        for (int k = 0; k < depths.length; k++) {
            cue.setPixel(k, 0, depths[k], 0);
            Span span = new Span();
            span.y = 1;
            span.x0 = k;
            span.x1 = k + 1;
            span.xBase = k;
            span.z = depths[k];
            cue.fillSpan(span);
            assertEquals(levels[k] * 0x010101, cue.getPixel(k, 0) & 0xFFFFFF, "setPixel at z = " + depths[k]);
            assertEquals(levels[k] * 0x010101, cue.getPixel(k, 1) & 0xFFFFFF, "a span at z = " + depths[k]);
        }
        // Black to white the other way round: 255 - those, less a half, rounds up too.
        DepthCueDrawable back = new DepthCueDrawable(Rgb.BLACK, Rgb.WHITE, Camera.PARALLEL, new ImageDrawable(
                new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB)));
        back.setPixel(0, 0, -100, 0);
        assertEquals(128 * 0x010101, back.getPixel(0, 0) & 0xFFFFFF);
    }

    @Test
    void writesOutsideThePanelNeverReachTheMargins() {
        PageCanvas canvas = new PageCanvas();
        Drawable[] targets = {canvas.panel(), canvas.depthTested(), canvas.depthCued(Rgb.WHITE, Rgb.BLACK)};
        for (Drawable target : targets) {
            filled.drawPolygon(new Vertex(-5000, -5000, -10, 1, 0, 0), new Vertex(9000, -4000, -10, 1, 0, 0),
                    new Vertex(200, 9000, -10, 1, 0, 0), target);
            new DdaLineRenderer().drawLine(Vertex.of(-300, -20, -10), Vertex.of(900, 700, -10), target);
            for (int x = -60; x < 720; x++) {
                target.setPixel(x, -1, -10, 0xFFFF0000);
                target.setPixel(x, 650, -10, 0xFFFF0000);
            }
        }
        BufferedImage image = canvas.image();
        for (int y = 0; y < PageCanvas.SIZE; y++) {
            for (int x = 0; x < PageCanvas.SIZE; x++) {
                boolean margin = x < 50 || x >= 700 || y < 50 || y >= 700;
                if (margin) {
                    assertEquals(0xFFFFFF, image.getRGB(x, y) & 0xFFFFFF, "margin pixel " + x + "," + y);
                } else {
                    assertNotEquals(0, image.getRGB(x, y) & 0xFFFFFF, "panel pixel " + x + "," + y + " not drawn");
                }
            }
        }
    }

    @Test
    void thePanelIsYUpWithItsOriginAtTheBottomLeft() {
        PageCanvas canvas = new PageCanvas();
        canvas.panel().setPixel(0, 0, 0, 0xFF123456);
        canvas.panel().setPixel(649, 649, 0, 0xFF654321);
        assertEquals(0x123456, canvas.image().getRGB(50, 699) & 0xFFFFFF);
        assertEquals(0x654321, canvas.image().getRGB(699, 50) & 0xFFFFFF);
    }

    @Test
    void theScissorDropsWritesInFrontOfTheNearOrBehindTheFarPlane() {
        PageCanvas canvas = new PageCanvas();
        Drawable target = canvas.depthCued(Rgb.WHITE, Rgb.BLACK);
        // z runs from +100 at the left to -300 at the right: only the middle half is in the volume.
        Vertex a = Vertex.of(0, 0, 100);
        Vertex b = Vertex.of(650, 0, -300);
        Vertex c = Vertex.of(0, 650, 100);
        Vertex d = Vertex.of(650, 650, -300);
        filled.drawPolygon(a, b, d, target);
        filled.drawPolygon(a, d, c, target);
        int row = 300;
        for (int x = 0; x < 650; x++) {
            double z = 100 - 400 * (x + 0.5) / 650;
            if (Math.abs(z) < 1e-6 || Math.abs(z + 200) < 1e-6) {
                continue; // on a plane: which side rounding puts it is not the point here
            }
            boolean visible = z < 0 && z > -200;
            boolean written = canvas.zbuffer().depthAt(x, row) > -200;
            assertEquals(visible, written, "x " + x + ", z " + z);
        }
    }

    /** The span fast path and the pixel path draw the same picture through every decorator. */
    @Test
    void spansAndPixelsDrawTheSamePicture() {
        Random random = new Random(5);
        PageCanvas bySpan = new PageCanvas();
        PageCanvas byPixel = new PageCanvas();
        Drawable spanTarget = bySpan.depthCued(new Rgb(1, 0.8, 0.3), new Rgb(0.1, 0, 0.2));
        Drawable pixelTarget = new PixelByPixel(byPixel.depthCued(new Rgb(1, 0.8, 0.3), new Rgb(0.1, 0, 0.2)));
        for (int i = 0; i < 300; i++) {
            Vertex[] t = new Vertex[3];
            for (int k = 0; k < 3; k++) {
                t[k] = new Vertex(random.nextDouble() * 800 - 75, random.nextDouble() * 800 - 75,
                        random.nextDouble() * 260 - 230, random.nextDouble(), random.nextDouble(), random.nextDouble());
            }
            filled.drawPolygon(t[0], t[1], t[2], spanTarget);
            filled.drawPolygon(t[0], t[1], t[2], pixelTarget);
        }
        int differing = 0;
        for (int y = 0; y < PageCanvas.SIZE; y++) {
            for (int x = 0; x < PageCanvas.SIZE; x++) {
                differing += bySpan.image().getRGB(x, y) != byPixel.image().getRGB(x, y) ? 1 : 0;
            }
        }
        assertEquals(0, differing);
    }

    /** Forces the pixel path: every span is split into setPixel calls before the chain sees it. */
    private static final class PixelByPixel extends DrawableDecorator {
        PixelByPixel(Drawable delegate) {
            super(delegate);
        }

        @Override
        public void fillSpan(Span span) {
            for (int x = span.x0; x < span.x1; x++) {
                delegate.setPixel(x, span.y, span.zAt(x), span.argbAt(x));
            }
        }
    }
}
