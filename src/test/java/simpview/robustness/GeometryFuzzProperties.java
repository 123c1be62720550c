package simpview.robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.DataBufferInt;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import net.jqwik.api.Tuple;
import simpview.geometry.Vertex;
import simpview.surface.Colors;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.surface.ZBuffer;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.testing.CountingDrawable;
import simpview.testing.RecordingDrawable;
import simpview.testing.RecordingDrawable.Write;

/**
 * Hostile geometry straight into the renderers: coordinates up to +-1e12,
 * zero-area, collinear, sub-pixel, axis-parallel, NaN and infinities. Nothing
 * may be written outside the drawable, nothing may throw, and the work must be
 * bounded by the drawable, not by the size of the primitive.
 */
class GeometryFuzzProperties {

    /** Deliberately neither square nor a power of two, so width and height cannot be confused. */
    static final int W = 97;
    static final int H = 61;
    /** A single primitive on a drawable this small takes microseconds; a second means a runaway loop. */
    static final long LIMIT_MS = 1000;

    private final FilledPolygonRenderer filled = new FilledPolygonRenderer();
    private final DdaLineRenderer dda = new DdaLineRenderer();

    @Provide
    Arbitrary<Vertex[]> triangles() {
        return Hostile.triangle(Math.max(W, H));
    }

    @Provide
    Arbitrary<Vertex> vertices() {
        return Hostile.vertex(Math.max(W, H));
    }

    @Property(tries = 1500, seed = "20240611", shrinking = ShrinkingMode.BOUNDED)
    void aFilledTriangleStaysOnTheDrawableAndWritesEachPixelAtMostOnce(@ForAll("triangles") Vertex[] t)
            throws Exception {
        CountingDrawable d = new CountingDrawable(W, H);
        Watchdog.withinMillis(LIMIT_MS, "filled triangle", () -> {
            filled.drawPolygon(t[0], t[1], t[2], d);
            return null;
        });
        assertEquals(0, d.strays(), "writes outside the drawable");
        assertTrue(d.maxCount() <= 1, "a pixel written " + d.maxCount() + " times by one triangle");
        assertTrue(d.writes() <= (long) W * H, "more writes than pixels: " + d.writes());
        if (!Hostile.finite(t)) {
            assertEquals(0, d.writes(), "a triangle with a non-finite vertex draws nothing");
            return;
        }
        if (Hostile.orientation(t[0], t[1], t[2].x(), t[2].y()) == 0) {
            assertEquals(0, d.writes(), "a zero-area triangle draws nothing");
            return;
        }
        // A triangle that holds the drawable with a pixel to spare covers every pixel, however big it is.
        boolean holdsDrawable = Hostile.coversExactly(t[0], t[1], t[2], -1, -1)
                && Hostile.coversExactly(t[0], t[1], t[2], W + 1, -1)
                && Hostile.coversExactly(t[0], t[1], t[2], -1, H + 1)
                && Hostile.coversExactly(t[0], t[1], t[2], W + 1, H + 1);
        if (holdsDrawable) {
            assertEquals((long) W * H, d.writes(), "a triangle around the whole drawable misses pixels");
        }
    }

    /**
     * Where the arithmetic is exact (coordinates on a 1/8 grid, moderate size)
     * the triangle draws exactly the pixel centres inside it by the top-left
     * rule, with z interpolated from the vertices.
     */
    @Property(tries = 400, seed = "1207")
    void onAnExactGridCoverageIsExactlyTheTopLeftRule(@ForAll("gridTriangles") Vertex[] t) {
        CountingDrawable d = new CountingDrawable(W, H);
        filled.drawPolygon(t[0], t[1], t[2], d);
        // No pixel centre outside the box of the vertices is inside or on an edge: the exact test is asked of the
        // pixels of the box, and the writes counted there must be all the writes.
        int x0 = Math.max(0, (int) Math.floor(Math.min(t[0].x(), Math.min(t[1].x(), t[2].x()))) - 1);
        int x1 = Math.min(W - 1, (int) Math.ceil(Math.max(t[0].x(), Math.max(t[1].x(), t[2].x()))));
        int y0 = Math.max(0, (int) Math.floor(Math.min(t[0].y(), Math.min(t[1].y(), t[2].y()))) - 1);
        int y1 = Math.min(H - 1, (int) Math.ceil(Math.max(t[0].y(), Math.max(t[1].y(), t[2].y()))));
        long inBox = 0;
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                boolean inside = Hostile.coversExactly(t[0], t[1], t[2], x + 0.5, y + 0.5);
                assertEquals(inside ? 1 : 0, d.count(x, y), "pixel " + x + "," + y);
                inBox += d.count(x, y);
                if (inside) {
                    assertEquals(barycentricZ(t, x + 0.5, y + 0.5), d.depth(x, y), 1e-6, "z at " + x + "," + y);
                }
            }
        }
        assertEquals(d.writes(), inBox, "writes outside the box of the vertices, x " + x0 + "-" + x1 + ", y " + y0
                + "-" + y1);
    }

    @Provide
    Arbitrary<Vertex[]> gridTriangles() {
        Arbitrary<Double> gx = Arbitraries.integers().between(-80, (W + 10) * 8).map(i -> i / 8.0);
        Arbitrary<Double> gy = Arbitraries.integers().between(-80, (H + 10) * 8).map(i -> i / 8.0);
        Arbitrary<Double> z = Arbitraries.integers().between(-200, 0).map(i -> (double) i);
        Arbitrary<Vertex> v = Combinators.combine(gx, gy, z).as(Vertex::of);
        Arbitrary<Vertex[]> free = Combinators.combine(v, v, v).as((a, b, c) -> new Vertex[] {a, b, c});
        // Small triangles with edges through pixel centres and corners.
        Arbitrary<Vertex[]> small = Combinators.combine(v, Arbitraries.integers().between(-24, 24),
                Arbitraries.integers().between(-24, 24), Arbitraries.integers().between(-24, 24),
                Arbitraries.integers().between(-24, 24))
                .as((a, dx1, dy1, dx2, dy2) -> new Vertex[] {a, Vertex.of(a.x() + dx1 / 4.0, a.y() + dy1 / 4.0, a.z()),
                    Vertex.of(a.x() + dx2 / 4.0, a.y() + dy2 / 4.0, a.z())});
        return Arbitraries.oneOf(free, small);
    }

    private static double barycentricZ(Vertex[] t, double px, double py) {
        Vertex a = t[0];
        Vertex b = t[1];
        Vertex c = t[2];
        double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
        double wb = ((px - a.x()) * (c.y() - a.y()) - (py - a.y()) * (c.x() - a.x())) / area;
        double wc = ((b.x() - a.x()) * (py - a.y()) - (b.y() - a.y()) * (px - a.x())) / area;
        return (1 - wb - wc) * a.z() + wb * b.z() + wc * c.z();
    }

    @Property(tries = 1500, seed = "4711", shrinking = ShrinkingMode.BOUNDED)
    void aDdaLineStaysOnTheDrawableAndTakesAtMostOnePixelPerMajorStep(@ForAll("vertices") Vertex p,
            @ForAll("vertices") Vertex q) throws Exception {
        RecordingDrawable d = new RecordingDrawable(W, H);
        Watchdog.withinMillis(LIMIT_MS, "DDA line", () -> {
            dda.drawLine(p, q, d);
            return null;
        });
        List<Write> w = d.writes();
        assertEquals(0, d.strays(), "writes outside the drawable");
        assertTrue(w.size() <= Math.max(W, H), "more writes than the major axis is long: " + w.size());
        assertDistinct(w);
        if (!Hostile.finite(p, q)) {
            assertEquals(0, w.size(), "a line with a non-finite end draws nothing");
            return;
        }
        // SPEC: the ends rounded to the nearest pixel, drawn from the smaller x
        // (x-major) or the smaller y (y-major).
        int px = (int) Math.floor(p.x() + 0.5);
        int py = (int) Math.floor(p.y() + 0.5);
        int qx = (int) Math.floor(q.x() + 0.5);
        int qy = (int) Math.floor(q.y() + 0.5);
        boolean xMajor = Math.abs(qx - px) >= Math.abs(qy - py);
        if (xMajor ? qx < px : qy < py) {
            int x = px;
            int y = py;
            px = qx;
            py = qy;
            qx = x;
            qy = y;
        }
        boolean bothOn = px >= 0 && px < W && py >= 0 && py < H && qx >= 0 && qx < W && qy >= 0 && qy < H;
        if (bothOn) {
            assertEquals(Math.max(Math.abs(qx - px), Math.abs(qy - py)) + 1, w.size(), "pixels on the line");
            assertEquals(px + "," + py, w.get(0).x() + "," + w.get(0).y(), "first pixel: the start end's");
            assertEquals(qx + "," + qy, w.get(w.size() - 1).x() + "," + w.get(w.size() - 1).y(),
                    "last pixel: the other end's");
            for (int i = 1; i < w.size(); i++) {
                int dx = Math.abs(w.get(i).x() - w.get(i - 1).x());
                int dy = Math.abs(w.get(i).y() - w.get(i - 1).y());
                assertTrue(dx <= 1 && dy <= 1 && dx + dy >= 1, "the line is not 8-connected at step " + i);
            }
        }
    }

    private static boolean inside(Vertex v) {
        return v.x() >= 0 && v.x() < W && v.y() >= 0 && v.y() < H;
    }

    private static void assertDistinct(List<Write> writes) {
        boolean[] seen = new boolean[W * H];
        for (Write w : writes) {
            int i = w.y() * W + w.x();
            assertTrue(!seen[i], "pixel " + w.x() + "," + w.y() + " written twice by one line");
            seen[i] = true;
        }
    }

    /**
     * Lines and triangles beyond +-1e12, where a double no longer holds every
     * integer (2^53 ~ 9e15) or the difference of the ends overflows: still
     * no stray write and no endless loop.
     */
    @Property(tries = 300, seed = "99", shrinking = ShrinkingMode.OFF)
    void farBeyondIntRangeALineEnds(@ForAll("farVertices") Vertex p, @ForAll("farVertices") Vertex q)
            throws Exception {
        CountingDrawable d = new CountingDrawable(W, H);
        Watchdog.withinMillis(LIMIT_MS, "DDA line " + p + " to " + q, () -> {
            dda.drawLine(p, q, d);
            return null;
        });
        assertEquals(0, d.strays());
        assertTrue(d.writes() <= Math.max(W, H));
    }

    @Property(tries = 300, seed = "98", shrinking = ShrinkingMode.OFF)
    void farBeyondIntRangeATriangleEnds(@ForAll("farVertices") Vertex p, @ForAll("farVertices") Vertex q,
            @ForAll("farVertices") Vertex r) throws Exception {
        CountingDrawable d = new CountingDrawable(W, H);
        Watchdog.withinMillis(LIMIT_MS, "filled triangle " + p + " " + q + " " + r, () -> {
            filled.drawPolygon(p, q, r, d);
            return null;
        });
        assertEquals(0, d.strays());
        assertTrue(d.maxCount() <= 1);
        assertTrue(d.writes() <= (long) W * H);
    }

    @Provide
    Arbitrary<Vertex> farVertices() {
        Arbitrary<Double> far = Arbitraries.frequencyOf(
                Tuple.of(3, Hostile.coordinate(Math.max(W, H))),
                Tuple.of(3, Arbitraries.of(1e16, -1e16, 1e18, -1e18, 1e300, -1e300, Double.MAX_VALUE,
                        -Double.MAX_VALUE)),
                Tuple.of(2, Arbitraries.doubles().between(-1e300, 1e300)));
        return Combinators.combine(far, far).as((x, y) -> Vertex.of(x, y, -100));
    }

    /** The smallest case the property above finds, kept as a plain example. */
    @Example
    void aLineAcrossTheDrawableFromBeyondTwoToThe53Ends() throws Exception {
        CountingDrawable d = new CountingDrawable(W, H);
        Vertex p = Vertex.of(-1e16, 30.5, -100);
        Vertex q = Vertex.of(1e16, 30.5, -100);
        Watchdog.withinMillis(LIMIT_MS, "DDA line from x = -1e16 to 1e16", () -> {
            dda.drawLine(p, q, d);
            return null;
        });
        assertEquals(W, d.writes(), "a horizontal line across the drawable writes its whole row");
    }

    // ---- through the page's decorator chains ----

    private final PageCanvas canvas = new PageCanvas();

    enum Primitive { FILLED, WIREFRAME, LINE }

    enum Chain { PANEL, DEPTH_TESTED, DEPTH_CUED }

    private Drawable chain(PageCanvas c, Chain chain) {
        switch (chain) {
            case PANEL:
                return c.panel();
            case DEPTH_TESTED:
                return c.depthTested();
            default:
                return c.depthCued(new Rgb(0.2, 1, 0.6), Rgb.BLACK);
        }
    }

    private void draw(Primitive kind, Vertex[] t, Drawable d) {
        switch (kind) {
            case FILLED:
                filled.drawPolygon(t[0], t[1], t[2], d);
                break;
            case WIREFRAME:
                new WireframePolygonRenderer(dda).drawPolygon(t[0], t[1], t[2], d);
                break;
            default:
                dda.drawLine(t[0], t[1], d);
        }
    }

    @Provide
    Arbitrary<Vertex[]> panelTriangles() {
        return Hostile.triangle(PageCanvas.PANEL);
    }

    @Property(tries = 400, seed = "750", shrinking = ShrinkingMode.BOUNDED)
    void theMarginsStayWhiteThroughEveryChain(@ForAll Primitive kind, @ForAll Chain chain,
            @ForAll("panelTriangles") Vertex[] t) throws Exception {
        canvas.clear();
        Watchdog.withinMillis(LIMIT_MS, kind + " through " + chain, () -> {
            draw(kind, t, chain(canvas, chain));
            return null;
        });
        int size = PageCanvas.SIZE;
        int m = PageCanvas.MARGIN;
        int[] rgb = pixels(canvas);
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                boolean margin = x < m || y < m || x >= size - m || y >= size - m;
                if (margin) {
                    if ((rgb[y * size + x] & 0xFFFFFF) != 0xFFFFFF) {
                        assertEquals(Integer.toHexString(Colors.WHITE), Integer.toHexString(rgb[y * size + x]),
                                "margin pixel " + x + "," + y);
                    }
                }
            }
        }
        if (chain != Chain.PANEL) {
            ZBuffer zb = canvas.zbuffer();
            for (int y = 0; y < PageCanvas.PANEL; y++) {
                for (int x = 0; x < PageCanvas.PANEL; x++) {
                    double z = zb.depthAt(x, y);
                    if (!(z >= -200 && z <= 0)) {
                        fail("z-buffer holds " + z + " at " + x + "," + y);
                    }
                    int image = (m + PageCanvas.PANEL - 1 - y) * size + m + x;
                    if (z == -200 && (rgb[image] & 0xFFFFFF) != 0) {
                        fail("pixel " + x + "," + y + " changed though its depth test never passed");
                    }
                }
            }
        }
    }

    /**
     * The span fast path and the pixel path draw the same picture: the same
     * triangle through a chain directly, and through an adapter that turns
     * every span into setPixel calls, gives the same image and z-buffer.
     */
    @Property(tries = 300, seed = "31337")
    void spansAndPixelsDrawTheSamePicture(@ForAll Chain chain, @ForAll("panelTriangles") Vertex[] t) {
        PageCanvas spans = new PageCanvas();
        PageCanvas pixels = new PageCanvas();
        filled.drawPolygon(t[0], t[1], t[2], chain(spans, chain));
        filled.drawPolygon(t[0], t[1], t[2], new PixelsOnly(chain(pixels, chain)));
        int size = PageCanvas.SIZE;
        int[] a = pixels(spans);
        int[] b = pixels(pixels);
        for (int i = 0; i < a.length; i++) {
            if ((a[i] & 0xFFFFFF) != (b[i] & 0xFFFFFF)) {
                assertEquals(Integer.toHexString(b[i]), Integer.toHexString(a[i]),
                        "image pixel " + i % size + "," + i / size + ": span path vs pixel path");
            }
        }
        for (int y = 0; y < PageCanvas.PANEL; y++) {
            for (int x = 0; x < PageCanvas.PANEL; x++) {
                if (Double.compare(pixels.zbuffer().depthAt(x, y), spans.zbuffer().depthAt(x, y)) != 0) {
                    assertEquals(pixels.zbuffer().depthAt(x, y), spans.zbuffer().depthAt(x, y), "z at " + x + "," + y);
                }
            }
        }
    }

    /** The image's own pixel array (0xRRGGBB, the top byte is not kept by an INT_RGB image). */
    static int[] pixels(PageCanvas c) {
        return ((DataBufferInt) c.image().getRaster().getDataBuffer()).getData();
    }

    /** Hides a chain's span path: every span arrives as pixels. */
    private static final class PixelsOnly implements Drawable {
        private final Drawable inner;

        PixelsOnly(Drawable inner) {
            this.inner = inner;
        }

        @Override
        public int width() {
            return inner.width();
        }

        @Override
        public int height() {
            return inner.height();
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            inner.setPixel(x, y, z, argb);
        }

        @Override
        public int getPixel(int x, int y) {
            return inner.getPixel(x, y);
        }
    }
}
