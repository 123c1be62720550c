package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.DataBufferInt;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.SceneException;
import simpview.stage.CuedPrimitives;
import simpview.surface.Colors;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * When a record hands a batch off to be drawn in bands (BatchDrawing): a
 * picture's first batches are small, each later one twice the one before, a
 * lit batch goes once it covers many pixels, a depth-cued one by its count
 * alone; every batch in bands on every thread, to the one thread's pixels.
 */
class BatchHandOffTest {

    @TempDir
    Path dir;

    @Test
    void aSceneOfSmallFacesIsDrawnInBandsBatchByBatchToTheSamePixels() throws Exception {
        Path small = scene("small.simp", 4200, 1);
        Path large = scene("large.simp", 12, 120);
        int[] oneThread = pixels(small, DrawingThreads.one(), new long[1]);
        assertTrue(Arrays.stream(oneThread).filter(p -> p != Colors.BLACK && p != Colors.WHITE).count() > 1000,
                "the faces are drawn");
        long[] tasks = new long[1];
        // 4,200 faces: batches of 16, 32, ... 2,048 faces (4,080 in all), each handed off and drawn in bands,
        // then the other 120; the same pixels. Before the first, an empty batch in bands: each band's drawer
        // makes its rows ready (what the canvas's clear owes) while the first batch is read.
        try (DrawingThreads two = DrawingThreads.of(2)) {
            int bands = two.bands(PageCanvas.PANEL, CuedPrimitives.BANDS_PER_THREAD).count(); // depth-cued scenes
            assertArrayEquals(oneThread, pixels(small, DrawingThreads.of(2), tasks));
            assertEquals(bands + 9 * bands, tasks[0], "4,200 faces of a pixel or two: nine batches, in bands");
            // A depth-cued batch is handed off by its count alone, however many pixels it covers.
            assertArrayEquals(pixels(large, DrawingThreads.one(), new long[1]), pixels(large, DrawingThreads.of(2), tasks));
            assertEquals(bands + bands, tasks[0], "12 large depth-cued fills: one batch, in bands");
        }
    }

    @Test
    void aLitBatchIsHandedOffOnceItCoversManyPixelsToTheSamePixels() throws Exception {
        StringBuilder s = new StringBuilder("ambient 1 1 1\ncamera -1 -1 1 1 -1 -100\n");
        for (int i = 0; i < 6; i++) {
            // Corners at (-d, -d), (d, -d), (-d, d) at depth d reach the window's corners: half the panel,
            // 211,250 pixels, more than the 120,000 after which a lit batch is handed off (LitPrimitives).
            double d = 2 + 0.25 * i;
            double red = i / 6.0;
            s.append(String.format(Locale.ROOT, "polygon (%.2f, %.2f, %.2f, %.3f, 1, 0) (%.2f, %.2f, %.2f, %.3f, 1, 0)"
                    + " (%.2f, %.2f, %.2f, %.3f, 1, 0)%n", -d, -d, -d, red, d, -d, -d, red, -d, d, -d, red));
        }
        Path fills = dir.resolve("fills.simp");
        Files.writeString(fills, s);
        long[] tasks = new long[1];
        int[] oneThread = pixels(fills, DrawingThreads.one(), new long[1]);
        assertTrue(Arrays.stream(oneThread).filter(p -> p != Colors.BLACK && p != Colors.WHITE).count()
                > 100_000, "the fills are drawn");
        try (DrawingThreads two = DrawingThreads.of(2)) {
            int bands = two.bands(PageCanvas.PANEL).count();
            assertArrayEquals(oneThread, pixels(fills, DrawingThreads.of(2), tasks));
            // Lit by the ambient term alone: no pixel waits to be shaded, so no last batch is handed off for it;
            // the first, empty, makes the bands' rows ready.
            assertEquals(bands + 6 * bands, tasks[0], "6 lit fills of 211,250 pixels: each its own batch, in bands");
        }
    }

    /** The scene's pixels drawn by {@code drawing}; in tasks[0] how many tasks (bands of batches) it ran. */
    private static int[] pixels(Path scene, DrawingThreads drawing, long[] tasks) throws SceneException {
        try (drawing) {
            PageCanvas canvas = new PageCanvas();
            canvas.drawWith(drawing);
            ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()), new SceneMonitor() {
            });
            tasks[0] = drawing.tasks();
            return ((DataBufferInt) canvas.image().getRaster().getDataBuffer()).getData().clone();
        }
    }

    /** A depth-cued scene of {@code count} triangles of side {@code side} (world units; the panel is 200 wide). */
    private Path scene(String name, int count, double side) throws IOException {
        StringBuilder s = new StringBuilder("filled\n");
        for (int i = 0; i < count; i++) {
            // Spread over the panel, each corner inside it, nearer the later ones.
            double x = -95 + (i * 7.3) % (190 - side);
            double y = -95 + (i * 3.1) % (190 - side);
            double z = -190 + i % 180;
            s.append(String.format(Locale.ROOT, "polygon (%.3f, %.3f, %.3f) (%.3f, %.3f, %.3f) (%.3f, %.3f, %.3f)%n",
                    x, y, z, x + side, y, z, x, y + side, z));
        }
        Path file = dir.resolve(name);
        Files.writeString(file, s);
        return file;
    }
}
