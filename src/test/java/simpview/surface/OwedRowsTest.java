package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Rows an image owes a fill (a page canvas's clear): made by the first read
 * or write, or handed to the band drawers, who each make their own rows.
 */
class OwedRowsTest {

    private static final int RED = 0xFF0000;
    private static final int BLUE = 0x0000FF;
    private static final int W = 8;
    private static final int H = 6;

    /** An image all red, its raw pixels, and a drawable over it. */
    private final BufferedImage image = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
    private final int[] raw = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    private final ImageDrawable drawable = new ImageDrawable(image);
    private final int[] blueRow = new int[W];

    OwedRowsTest() {
        Arrays.fill(raw, RED);
        Arrays.fill(blueRow, BLUE);
    }

    private int rawAt(int x, int y) {
        return raw[y * W + x];
    }

    @Test
    void owedRowsAreMadeBeforeTheImageIsReadOrWritten() {
        drawable.oweRows(1, 4, blueRow);
        assertEquals(RED, rawAt(0, 2), "owed, not made");
        drawable.setPixel(5, 2, 0, 0x123456);
        assertEquals(BLUE, rawAt(0, 2), "made before the write");
        assertEquals(0x123456, rawAt(5, 2), "and the write kept");
        assertEquals(RED, rawAt(0, 0), "row 0 is not owed");
        assertEquals(RED, rawAt(0, 4), "nor row 4");

        drawable.oweRows(1, 4, blueRow);
        assertEquals(0xFF0000FF, drawable.getPixel(5, 2), "made before a read");
        drawable.oweRows(1, 4, blueRow);
        assertSame(image, drawable.image());
        assertEquals(BLUE, rawAt(5, 2), "made before the image is handed out");
    }

    @Test
    void eachWayToWriteMakesTheRowsFirst() {
        Span span = new Span();
        span.y = 3;
        span.x0 = 2;
        span.x1 = 4;
        span.r = 100;
        span.dr = 1;
        List<Runnable> writes = List.of(
                () -> drawable.setRun(2, 3, 2, new double[2], new int[] {7, 7}, 0),
                () -> drawable.fillSpan(span),
                () -> drawable.fillRect(2, 3, 4, 4, 7));
        for (Runnable write : writes) {
            Arrays.fill(raw, RED);
            drawable.oweRows(1, 4, blueRow);
            write.run();
            assertEquals(BLUE, rawAt(0, 1), "made first");
            assertTrue(rawAt(2, 3) != BLUE && rawAt(2, 3) != RED, "the write kept");
        }
    }

    @Test
    void aFillOutsideTheOwedRowsLeavesThemOwed() {
        drawable.oweRows(1, 4, blueRow);
        drawable.fillRect(0, 4, W, H, 7);
        assertEquals(RED, rawAt(0, 2), "still owed");
        assertEquals(7, rawAt(0, 5));
    }

    @Test
    void rowsHandedToTheBandsAreMadeByTheirRowsAlone() {
        drawable.oweRows(1, 4, blueRow);
        assertTrue(drawable.fillOwedByRows());
        drawable.setPixel(0, 0, 0, 7);
        assertEquals(RED, rawAt(0, 2), "a write no longer makes them");
        drawable.fillOwedRows(2, 3);
        assertEquals(BLUE, rawAt(0, 2));
        assertEquals(RED, rawAt(0, 3), "only the band's rows");
        drawable.fillOwedRows(0, H);
        assertEquals(7, rawAt(0, 0), "row 0 was never owed");
        assertEquals(BLUE, rawAt(0, 3));
        assertEquals(RED, rawAt(0, 4), "nor row 4");
    }

    @Test
    void nothingOwedHandsNothingToTheBands() {
        assertFalse(drawable.fillOwedByRows());
        drawable.oweRows(1, 4, blueRow);
        drawable.getPixel(0, 0);
        drawable.setPixel(0, 2, 0, 7);
        assertFalse(drawable.fillOwedByRows(), "made already");
        drawable.fillOwedRows(0, H);
        assertEquals(7, rawAt(0, 2), "the write after the fill stays");
    }

    @Test
    void rowsOwedBeforeAndNotCoveredAgainAreMadeFirst() {
        drawable.oweRows(0, 4, blueRow);
        int[] greenRow = new int[W];
        Arrays.fill(greenRow, 0x00FF00);
        drawable.oweRows(1, 3, greenRow);
        assertEquals(BLUE, rawAt(0, 0), "the first owe, made");
        assertEquals(BLUE, rawAt(0, 3));
        drawable.getPixel(0, 0);
        assertEquals(0x00FF00, rawAt(0, 1), "the second");

        Arrays.fill(raw, RED);
        drawable.oweRows(1, 3, greenRow);
        drawable.oweRows(0, H, blueRow);
        assertEquals(RED, rawAt(0, 1), "covered again: owed once, not made twice");
    }

    @Test
    void aRowOfAnotherWidthIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> drawable.oweRows(0, 1, new int[W + 1]));
    }

    /**
     * Threads writing at once through the image after a clear (a chain of
     * a test's own drawn in bands): settled first, on the thread that
     * cleared, so no write is lost to the fill.
     */
    @Test
    void rowsSettledBeforeThreadsWriteAtOnceLoseNoWrite() throws Exception {
        int size = 200;
        BufferedImage picture = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
        int[] every = ((DataBufferInt) picture.getRaster().getDataBuffer()).getData();
        ImageDrawable big = new ImageDrawable(picture);
        int[] black = new int[size];
        for (int round = 0; round < 20; round++) {
            Arrays.fill(every, RED);
            big.oweRows(0, size, black);
            big.settle();
            assertEquals(0, every[size * size - 1], "made on this thread");
            int threads = 4;
            List<Thread> running = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                int own = t;
                Thread writer = new Thread(() -> {
                    for (int y = own; y < size; y += threads) {
                        for (int x = 0; x < size; x++) {
                            big.setPixel(x, y, 0, 0xFFFFFF);
                        }
                    }
                }, "owed-rows-writer-" + t);
                running.add(writer);
                writer.start();
            }
            for (Thread writer : running) {
                writer.join();
            }
            int[] white = new int[every.length];
            Arrays.fill(white, 0xFFFFFF);
            assertArrayEquals(white, every, "round " + round);
        }
    }

    /** A canvas drawn on one thread clears every pixel at once: nothing is owed, nothing handed to bands. */
    @Test
    void aCanvasOfOneThreadClearsAtOnce() {
        PageCanvas canvas = new PageCanvas();
        canvas.panel().setPixel(3, 3, 0, RED);
        canvas.clear();
        assertSame(OwedRows.NONE, canvas.owedPanelRows());
        assertEquals(0xFF000000, canvas.image().getRGB(PageCanvas.MARGIN + 3, PageCanvas.MARGIN + PageCanvas.PANEL - 4));
    }

    @Test
    void aCanvasHandsItsPanelRowsToTheBandsYUp() {
        try (DrawingThreads two = DrawingThreads.of(2)) {
            PageCanvas canvas = new PageCanvas();
            canvas.drawWith(two);
            Drawable panel = canvas.panel();
            for (int y = 0; y < PageCanvas.PANEL; y++) {
                panel.setPixel(3, y, 0, RED);
            }
            canvas.clear();
            OwedRows rows = canvas.owedPanelRows();
            assertSame(OwedRows.NONE, canvas.owedPanelRows(), "handed over once");
            rows.make(0, 10);
            BufferedImage page = canvas.image();
            int bottom = PageCanvas.MARGIN + PageCanvas.PANEL - 1;
            int x = PageCanvas.MARGIN + 3;
            assertEquals(0xFF000000, page.getRGB(x, bottom), "panel row 0, made black");
            assertEquals(0xFF000000, page.getRGB(x, bottom - 9), "panel row 9");
            assertEquals(0xFFFFFFFF, page.getRGB(0, bottom - 9), "its margin, white");
            assertEquals(0xFFFF0000, page.getRGB(x, bottom - 10), "panel row 10 is not the band's");
            assertEquals(0xFFFFFFFF, page.getRGB(x, 0), "the top margin, filled by the clear");
            rows.make(10, PageCanvas.PANEL);
            assertEquals(0xFF000000, page.getRGB(x, PageCanvas.MARGIN), "the panel's top row");
        }
    }
}
