package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.AlphaComposite;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import simpview.surface.PageCanvas;
import simpview.window.instruments.Outlines;

/**
 * The wire's picture as {@link OutlinePictures} draws it, a slice at a time and only the outlines that meet the
 * panel's part in view: pixel for pixel the picture of every outline drawn at once, at every zoom and pan, and
 * shown only once done (the last one, moved to the new zoom, until then). Painted off screen, as
 * {@link OutlinesOverPageTest} paints.
 */
class OutlinePicturesTest {

    /** A slice long enough for every outline here, whatever else the machine does: an hour. */
    private static final long ONE_SLICE = 3_600_000_000_000L;

    /**
     * Triangles all over the page, some far outside it, and lines along the panel's edges and just outside them; the
     * last, far right, alone beside nothing but the panel's corner.
     */
    private static List<double[]> outlines() {
        Random random = new Random(43);
        List<double[]> shapes = new ArrayList<>();
        for (int k = 0; k < 3000; k++) {
            double x = random.nextDouble() * 900 - 75;
            double y = random.nextDouble() * 900 - 75;
            double size = k % 10 == 0 ? random.nextDouble() * 400 : random.nextDouble() * 20;
            shapes.add(new double[] {x, y, x + size, y + random.nextDouble() * size, x + random.nextDouble() * size,
                    y - size});
        }
        shapes.add(new double[] {699.5, 20, 699.5, 30, 720, 20});
        for (double at = 0; at < 750; at += 0.37) {
            shapes.add(new double[] {at, 50 + at % 3, at + 0.5, 52});
            shapes.add(new double[] {at, 699 + at % 2, at, 699.9});
        }
        return shapes;
    }

    @Test
    void aFewOutlinesAreCopiedToTheScreenWhole() throws Throwable {
        List<double[]> shapes = List.of(new double[] {250, 350, 350, 350, 300, 450},
                new double[] {300.5, 100, 300.5, 600}, new double[] {100, 400.5, 600, 400.5});
        DevicePixelsTest.onEdt(() -> {
            PageView view = new PageView();
            PageView bare = new PageView();
            view.wire(shapes);
            assertSameScreen(wireOver(bare, drawnAtOnce(view, shapes)), OutlinesOverPageTest.painted(view), "fit");
            for (PageView v : List.of(view, bare)) {
                v.zoomPan().zoomAbout(300, 400, 3);
            }
            BufferedImage zoomed = OutlinesOverPageTest.painted(view);
            assertTrue(view.outlinesFinished(), "3x");
            assertSamePixels(drawnAtOnce(view, shapes), view.outlinePictures().wirePicture(), "3x");
            assertSameScreen(wireOver(bare, drawnAtOnce(view, shapes)), zoomed, "3x");
        });
    }

    /**
     * A few outlines, one group, are drawn whole by the paint's own slice however long it took: with no time
     * at all to draw in, the slice that drew them all once left them waiting for a next one, and a paint on a
     * busy machine (a slice over 8 ms) showed none.
     */
    @Test
    void aFewOutlinesAreDrawnByTheFirstSliceHoweverLongItTakes() throws Throwable {
        List<double[]> shapes = List.of(new double[] {250, 350, 350, 350, 300, 450},
                new double[] {300.5, 100, 300.5, 600}, new double[] {100, 400.5, 600, 400.5});
        DevicePixelsTest.onEdt(() -> {
            PageView view = new PageView(0);
            view.wire(shapes);
            OutlinesOverPageTest.painted(view);
            assertTrue(view.outlinesFinished(), "drawn by the first slice");
            assertEquals(1, view.outlinePictures().slicesTaken());
            assertSamePixels(drawnAtOnce(view, shapes), view.outlinePictures().wirePicture(), "fit");
        });
    }

    /** The view without outlines painted, and {@code wire} over it at the wire's share: the screen before slices. */
    private static BufferedImage wireOver(PageView bare, BufferedImage wire) {
        BufferedImage screen = OutlinesOverPageTest.painted(bare);
        Graphics2D g = screen.createGraphics();
        g.setComposite(AlphaComposite.SrcOver.derive(200 / 255f));
        g.drawImage(wire, 0, 0, null);
        g.dispose();
        return screen;
    }

    /** All of {@code shapes} drawn at once as one path, where the view's zoom and pan put them: the wire before slices. */
    private static BufferedImage drawnAtOnce(PageView view, List<double[]> shapes) {
        ZoomPan zoomPan = view.zoomPan();
        BufferedImage picture = new BufferedImage(750, 750, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = picture.createGraphics();
        g.clip(new Rectangle2D.Double(zoomPan.screenX(PageCanvas.MARGIN), zoomPan.screenY(PageCanvas.MARGIN),
                PageCanvas.PANEL * zoomPan.zoom(), PageCanvas.PANEL * zoomPan.zoom()));
        g.setComposite(AlphaComposite.SrcOver);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setStroke(new BasicStroke(zoomPan.unit()));
        g.setColor(new Color(0, 255, 128));
        g.draw(Outlines.path(shapes, zoomPan::screenX, zoomPan::screenY));
        g.dispose();
        return picture;
    }

    private static void assertSamePixels(BufferedImage expected, BufferedImage got, String where) {
        int[] e = argb(expected);
        int[] g = argb(got);
        int differing = 0;
        int lit = 0;
        for (int i = 0; i < e.length; i++) {
            differing += e[i] != g[i] ? 1 : 0;
            lit += e[i] != 0 ? 1 : 0;
        }
        assertTrue(lit > 1000, where + ": the wire shows (" + lit + " pixels)");
        assertEquals(0, differing, where + ": pixels other than the whole wire's drawn at once");
    }

    private static void assertSameScreen(BufferedImage expected, BufferedImage got, String where) {
        int[] e = argb(expected);
        int[] g = argb(got);
        int differing = 0;
        for (int i = 0; i < e.length; i++) {
            differing += e[i] != g[i] ? 1 : 0;
        }
        assertEquals(0, differing, where + ": screen pixels other than under the whole wire drawn at once");
    }

    /** Every pixel with its alpha, as getRGB gives it, row by row. */
    private static int[] argb(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    /** The outlines whose box meets the view's part of the panel, grown by the stroke's reach: counted one by one. */
    private static int meetingTheView(PageView view, List<double[]> shapes) {
        ZoomPan zoomPan = view.zoomPan();
        double reach = (2 + zoomPan.unit()) / zoomPan.zoom();
        double left = Math.max(PageCanvas.MARGIN, -zoomPan.originX() / zoomPan.zoom()) - reach;
        double top = Math.max(PageCanvas.MARGIN, -zoomPan.originY() / zoomPan.zoom()) - reach;
        double right = Math.min(PageCanvas.MARGIN + PageCanvas.PANEL, (750 - zoomPan.originX()) / zoomPan.zoom()) + reach;
        double bottom = Math.min(PageCanvas.MARGIN + PageCanvas.PANEL, (750 - zoomPan.originY()) / zoomPan.zoom()) + reach;
        int meeting = 0;
        for (double[] points : shapes) {
            boolean leftOf = true;
            boolean rightOf = true;
            boolean above = true;
            boolean below = true;
            for (int k = 0; k + 1 < points.length; k += 2) {
                leftOf &= points[k] < left;
                rightOf &= points[k] > right;
                above &= points[k + 1] < top;
                below &= points[k + 1] > bottom;
            }
            if (!(leftOf || rightOf || above || below)) {
                meeting++;
            }
        }
        return meeting;
    }

    @Test
    void theWireIsTheWholeWiresPixelsAtEveryZoomAndPanDrawingOnlyTheOutlinesInView() throws Throwable {
        List<double[]> shapes = outlines();
        DevicePixelsTest.onEdt(() -> {
            PageView view = new PageView(ONE_SLICE);
            PageView bare = new PageView();
            view.wire(shapes);
            BufferedImage screen = OutlinesOverPageTest.painted(view);
            assertTrue(view.outlinesFinished(), "drawn in one slice");
            assertSamePixels(drawnAtOnce(view, shapes), view.outlinePictures().wirePicture(), "fit");
            assertSameScreen(wireOver(bare, drawnAtOnce(view, shapes)), screen, "fit");
            assertEquals(meetingTheView(view, shapes), view.outlinePictures().outlinesDrawn(), "fit");
            double[][] zooms = {{2, 375, 375}, {3, 60, 60}, {5, 700, 690}, {12, 380, 52}, {32, 200, 700},
                    {32, 745, 375}};
            for (double[] zoom : zooms) {
                view.zoomPan().zoomAbout(zoom[1], zoom[2], zoom[0]);
                bare.zoomPan().zoomAbout(zoom[1], zoom[2], zoom[0]);
                for (int pan = 0; pan < 2; pan++) {
                    String where = zoom[0] + "x about (" + zoom[1] + ", " + zoom[2] + ")" + (pan > 0 ? ", panned" : "");
                    BufferedImage zoomed = OutlinesOverPageTest.painted(view);
                    assertTrue(view.outlinesFinished(), where);
                    assertSamePixels(drawnAtOnce(view, shapes), view.outlinePictures().wirePicture(), where);
                    assertSameScreen(wireOver(bare, drawnAtOnce(view, shapes)), zoomed, where);
                    int drawn = view.outlinePictures().outlinesDrawn();
                    assertEquals(meetingTheView(view, shapes), drawn, where + ": the outlines drawn");
                    if (zoom[0] >= 12) {
                        assertTrue(drawn < shapes.size() / 10, where + ": " + drawn + " of " + shapes.size() + " drawn");
                    }
                    view.zoomPan().pan(-37.5, 21);
                    bare.zoomPan().pan(-37.5, 21);
                }
            }
        });
    }

    /** Runs {@code step} on the EDT and gives its answer. */
    private static <T> T onEdt(Supplier<T> step) throws Exception {
        AtomicReference<T> answer = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> answer.set(step.get()));
        return answer.get();
    }

    /** Until the view's outlines are drawn at its zoom and pan now, their slices run as the EDT comes to them. */
    private static void awaitFinished(PageView view) throws Exception {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (!onEdt(view::outlinesFinished)) {
            assertTrue(System.nanoTime() < deadline, "the outlines' slices did not finish in 20 s");
            Thread.yield();
        }
    }

    @Test
    void slicesFinishThePictureWhichReplacesTheLastOnlyOnceDone() throws Exception {
        List<double[]> shapes = outlines();
        PageView view = onEdt(() -> new PageView(0));
        AtomicBoolean finishedAtOnce = new AtomicBoolean(true);
        SwingUtilities.invokeAndWait(() -> {
            view.wire(shapes);
            OutlinesOverPageTest.painted(view);
            finishedAtOnce.set(view.outlinesFinished());
        });
        assertFalse(finishedAtOnce.get(), "one group a slice: not done in the paint");
        assertEquals(null, onEdt(() -> view.outlinePictures().wirePicture()), "no wire shown before it is done");
        awaitFinished(view);
        assertTrue(onEdt(() -> view.outlinePictures().slicesTaken()) > 10, "drawn in slices");
        BufferedImage atFit = onEdt(() -> drawnAtOnce(view, shapes));
        assertSamePixels(atFit, onEdt(() -> view.outlinePictures().wirePicture()), "fit, in slices");

        SwingUtilities.invokeAndWait(() -> {
            view.zoomPan().zoomAbout(300, 300, 3);
            OutlinesOverPageTest.painted(view);
            assertFalse(view.outlinesFinished(), "3x: not done in the paint");
            assertSamePixels(atFit, view.outlinePictures().wirePicture(), "the fit's wire, still shown");
            view.zoomPan().zoomAbout(300, 300, 4);
            OutlinesOverPageTest.painted(view);
        });
        awaitFinished(view);
        BufferedImage atFour = onEdt(() -> drawnAtOnce(view, shapes));
        assertSamePixels(atFour, onEdt(() -> view.outlinePictures().wirePicture()), "4x, the 3x dropped unfinished");
    }
}
