package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.DataBufferInt;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import simpview.scene.SceneException;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.Provenance;
import simpview.surface.Rgb;
import simpview.surface.Span;
import simpview.testing.CourseFiles;
import simpview.testing.DepthBits;
import simpview.testing.GoldenCase;

/**
 * A scene drawn by several threads, band by band, is the one-thread drawing
 * to the bit in everything the window's instruments read: every pixel, every
 * depth (its bits), every pixel's owner and the log of primitives, whole and
 * stopped part-way (stepping). Depth-cued and lit scenes, with and without
 * .obj models; the course's when they are present.
 */
class BandedDrawingTest {

    /** A scene, whether it is lit, and where stepping stops (-1: the whole scene). */
    record Case(String name, Path scene, boolean lit, int limit) {
        @Override
        public String toString() {
            return name + (limit < 0 ? "" : ", stopped before primitive " + limit);
        }
    }

    static Stream<Case> cases() {
        Path own = GoldenCase.ownSimpDir();
        List<Case> cases = new ArrayList<>();
        for (int limit : new int[] {-1, 37}) {
            cases.add(new Case("page5", own.resolve("page5.simp"), false, limit));
            cases.add(new Case("lit-lights", own.resolve("lit-lights.simp"), true, limit));
            cases.add(new Case("lit-shading", own.resolve("lit-shading.simp"), true, limit));
        }
        if (CourseFiles.present()) {
            cases.add(new Case("page7", CourseFiles.simpDir().resolve("page7.simp"), false, -1));
        }
        Path a3 = CourseFiles.folder("course-simp-a3");
        if (a3.toFile().isDirectory()) {
            cases.add(new Case("a3 pageI", a3.resolve("pageI.simp"), true, -1));
            cases.add(new Case("a3 pageF", a3.resolve("pageF.simp"), true, 5));
        }
        Path a4 = CourseFiles.folder("course-simp-a4");
        if (a4.toFile().isDirectory()) {
            cases.add(new Case("a4 page-f2", a4.resolve("page-f2.simp"), true, -1));
        }
        return cases.stream();
    }

    /** What the instruments read of one drawing. */
    private record Drawing(int[] pixels, long[] depths, int[] owners, int logged) {
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void severalThreadsDrawWhatOneDraws(Case c) throws Exception {
        Drawing one = draw(c, 1);
        assertTrue(one.logged() > 0, "something was drawn");
        // Every batch in bands by 2 threads (the default on two cores) or 7 (more than the bands' rows need).
        for (int count : new int[] {2, 7}) {
            try (DrawingThreads threads = DrawingThreads.of(count)) {
                assertSameDrawing(one, draw(c, threads), count + " threads");
            }
        }
    }

    /**
     * The threads keep each record's batches and the lit pictures' fragment
     * stages from one picture to the next (DrawingThreads.keep): what a
     * picture left in them, of its own scene or another, lit or depth-cued,
     * never reaches the next one, on one thread or two.
     */
    @Test
    void threadsThatDrewOtherScenesBeforeDrawWhatOneDraws() throws Exception {
        List<Case> all = cases().toList();
        List<Drawing> ones = new ArrayList<>();
        for (Case c : all) {
            ones.add(draw(c, 1));
        }
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads same = DrawingThreads.of(threads)) {
                for (int round = 1; round <= 2; round++) {
                    for (int i = 0; i < all.size(); i++) {
                        assertSameDrawing(ones.get(i), draw(all.get(i), same),
                                all.get(i) + ", round " + round + " on the same " + threads + " thread(s)");
                    }
                }
            }
        }
    }

    /**
     * One canvas drawing every case in turn, cleared between them (as the
     * window's is): its z-buffer's reset is owed by each clear and made by the
     * first depth-cued write or replaced by the lit reset, and each picture is
     * the one a fresh canvas gets, on one thread and on two.
     */
    @Test
    void aCanvasClearedAfterEveryOtherSceneDrawsWhatAFreshOneDraws() throws Exception {
        List<Case> all = cases().filter(c -> c.limit() < 0).toList();
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                PageCanvas canvas = new PageCanvas();
                canvas.drawWith(drawing);
                for (int round = 1; round <= 2; round++) {
                    for (Case c : all) {
                        canvas.clear();
                        ScenePipeline.draw(c.scene(), canvas, ScenePipeline.Options.byCommands(new SceneLibrary()),
                                SceneMonitor.NONE);
                        PageCanvas fresh = new PageCanvas();
                        ScenePipeline.draw(c.scene(), fresh, ScenePipeline.Options.byCommands(new SceneLibrary()),
                                SceneMonitor.NONE);
                        String how = c + ", round " + round + " on " + threads + " thread(s)";
                        assertArrayEquals(pixels(fresh), pixels(canvas), "pixels of " + how);
                        assertArrayEquals(fresh.zbuffer().copyDepths(), canvas.zbuffer().copyDepths(),
                                "depths of " + how);
                    }
                }
            }
        }
    }

    /**
     * A canvas cleared after a full picture, then given a scene that draws
     * nothing, or one that stops at an error after a primitive: the rows the
     * clear owes are made by the band drawers, or at the picture's end for
     * those no drawer reached, so the page is what a fresh canvas shows, on
     * one thread and on two; nothing of the picture before is left.
     */
    @Test
    void aCanvasClearedBeforeAnEmptyOrBrokenSceneShowsWhatAFreshOneDoes(@TempDir Path dir) throws Exception {
        String triangle = "{\n scale 100 100 1\n polygon (0, 0, -50) (1, 0, -50) (0, 1, -50)\n}\n";
        String lit = "ambient 0.5 0.5 0.5\nsurface 0.8 0.4 0.2 0 1\n";
        Map<String, String> scenes = new LinkedHashMap<>();
        scenes.put("empty.simp", "# nothing to draw\n");
        scenes.put("broken.simp", "filled\n" + triangle + "polygon (1, 2\n");
        scenes.put("lit-empty.simp", lit);
        scenes.put("lit-broken.simp", lit + "filled\n" + triangle + "polygon (oops\n");
        Path before = GoldenCase.ownSimpDir().resolve("page5.simp");
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                PageCanvas canvas = new PageCanvas();
                canvas.drawWith(drawing);
                for (Map.Entry<String, String> scene : scenes.entrySet()) {
                    Path file = Files.writeString(dir.resolve(scene.getKey()), scene.getValue());
                    canvas.clear();
                    ScenePipeline.draw(before, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()),
                            SceneMonitor.NONE);
                    canvas.clear();
                    boolean failed = drawToItsEnd(file, canvas);
                    PageCanvas fresh = new PageCanvas();
                    int[] cleared = pixels(fresh);
                    assertEquals(failed, drawToItsEnd(file, fresh), "the same end on a fresh canvas");
                    String how = scene.getKey() + " on " + threads + " thread(s)";
                    assertEquals(scene.getKey().contains("broken"), failed, how + " stops at its error");
                    assertArrayEquals(pixels(fresh), pixels(canvas), "pixels of " + how);
                    assertArrayEquals(fresh.zbuffer().copyDepths(), canvas.zbuffer().copyDepths(), "depths of " + how);
                    assertEquals(!scene.getKey().contains("empty"), !Arrays.equals(cleared, pixels(fresh)),
                            how + " draws its triangle, or nothing");
                }
            }
        }
    }

    /**
     * A canvas drawn by two threads, cleared after a full picture, then
     * given a scene by a chain of the caller's own, in bands
     * (ScenePipeline.drawDepthCued): the rows its clear owes are made on
     * the reading thread before the bands start, so the page is what a
     * canvas of one thread shows.
     */
    @Test
    void aChainOfTheCallersOwnOntoACanvasOfTwoThreadsDrawsWhatOneThreadDraws() throws Exception {
        Path scene = GoldenCase.ownSimpDir().resolve("page4.simp");
        PageCanvas one = new PageCanvas();
        ScenePipeline.drawDepthCued(scene, one.depthCued(Rgb.WHITE, Rgb.BLACK), SceneMonitor.NONE);
        try (DrawingThreads two = DrawingThreads.of(2)) {
            PageCanvas canvas = new PageCanvas();
            canvas.drawWith(two);
            for (int round = 1; round <= 2; round++) {
                canvas.clear();
                ScenePipeline.draw(GoldenCase.ownSimpDir().resolve("page5.simp"), canvas,
                        ScenePipeline.Options.byCommands(new SceneLibrary()), SceneMonitor.NONE);
                canvas.clear();
                ScenePipeline.drawDepthCued(scene, canvas.depthCued(Rgb.WHITE, Rgb.BLACK), SceneMonitor.NONE, two,
                        null);
                assertArrayEquals(pixels(one), pixels(canvas), "pixels, round " + round);
                assertArrayEquals(one.zbuffer().copyDepths(), canvas.zbuffer().copyDepths(), "depths, round " + round);
            }
            // How: the chain is settled on the reading thread before any band writes.
            canvas.clear();
            SettleWatch watched = new SettleWatch(canvas.depthCued(Rgb.WHITE, Rgb.BLACK));
            ScenePipeline.drawDepthCued(scene, watched, SceneMonitor.NONE, two, null);
            assertSame(Thread.currentThread(), watched.settledOn, "settled on the reading thread");
            assertEquals(0, watched.writesBefore.get(), "before any band wrote");
        }
    }

    /** A chain's head that notes where it was first settled, and how many writes came before. */
    private static final class SettleWatch extends DrawableDecorator {
        volatile Thread settledOn;
        final AtomicInteger writesBefore = new AtomicInteger();

        SettleWatch(Drawable delegate) {
            super(delegate);
        }

        @Override
        public void settle() {
            if (settledOn == null) {
                settledOn = Thread.currentThread();
            }
            super.settle();
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            noteWrite();
            super.setPixel(x, y, z, argb);
        }

        @Override
        public void fillSpan(Span span) {
            noteWrite();
            super.fillSpan(span);
        }

        private void noteWrite() {
            if (settledOn == null) {
                writesBefore.incrementAndGet();
            }
        }
    }

    /** Draws the scene on the canvas; true when it stopped at an error. */
    private static boolean drawToItsEnd(Path file, PageCanvas canvas) {
        try {
            ScenePipeline.draw(file, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()), SceneMonitor.NONE);
            return false;
        } catch (SceneException e) {
            return true;
        }
    }

    private static int[] pixels(PageCanvas canvas) {
        return ((DataBufferInt) canvas.image().getRaster().getDataBuffer()).getData().clone();
    }

    private static void assertSameDrawing(Drawing one, Drawing several, String how) {
        assertEquals(one.logged(), several.logged(), "primitives logged on " + how);
        assertArrayEquals(one.pixels(), several.pixels(), "pixels on " + how);
        assertArrayEquals(one.depths(), several.depths(), "depths on " + how);
        assertArrayEquals(one.owners(), several.owners(), "owners on " + how);
    }

    private static Drawing draw(Case c, int threads) throws Exception {
        try (DrawingThreads drawing = DrawingThreads.of(threads)) {
            return draw(c, drawing);
        }
    }

    /** One drawing of the case by {@code threads}, which it leaves open. */
    private static Drawing draw(Case c, DrawingThreads threads) throws Exception {
        PageCanvas canvas = new PageCanvas();
        Provenance provenance = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
        canvas.recordProvenance(provenance);
        PrimitiveLog log = new PrimitiveLog(provenance, c.limit());
        SceneMonitor monitor = new SceneMonitor() {
            @Override
            public PrimitiveTrace trace() {
                return log;
            }
        };
        canvas.drawWith(threads);
        ScenePipeline.Drawn drawn = ScenePipeline.draw(c.scene(), canvas,
                ScenePipeline.Options.byCommands(new SceneLibrary()), monitor);
        assertEquals(c.lit(), drawn.lit(), "drawn by the rules expected");
        int[] pixels = pixels(canvas);
        return new Drawing(pixels, DepthBits.of(canvas.zbuffer()), provenance.copyOwners(), log.size());
    }
}
