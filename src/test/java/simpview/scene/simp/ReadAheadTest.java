package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.IntPredicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Vertex;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * Reading ahead on a second thread changes nothing that can be seen: the
 * same pixels, primitives in the same order, the same error after exactly
 * the primitives before it, the same monitor calls; and cancelling, failing
 * or throwing from the drawing side leaves no reader thread behind.
 */
class ReadAheadTest {

    /** The start of every scene file's name here. */
    private static final String OURS = "read-ahead-";
    private static final long ALWAYS = 0;
    private static final long NEVER = Long.MAX_VALUE;

    @TempDir
    Path dir;

    /** What a run did: primitives drawn (as text), monitor calls, and how it ended. */
    private static final class Run {
        final List<String> drawn = new ArrayList<>();
        final List<String> monitor = new ArrayList<>();
        Throwable ended;
        FileStack files = new FileStack();
        /**
         * Whether a reader thread was alive when the second primitive was
         * drawn: the first is drawn on the calling thread, before reading
         * ahead starts (by then the scene's rules are known).
         */
        boolean readerAtSecondPrimitive;
    }

    private Run run(Path top, long readAheadFrom, int cancelAtReport, IntPredicate throwAtPrimitive) {
        Run run = new Run();
        LineRenderer lines = (p, q, d) -> record(run, throwAtPrimitive, "line", p, q);
        PolygonRenderer filled = (p, q, r, d) -> record(run, throwAtPrimitive, "filled", p, q, r);
        PolygonRenderer wire = (p, q, r, d) -> record(run, throwAtPrimitive, "wire", p, q, r);
        SimpClient client = new SimpClient(SceneFixture.NOWHERE, lines, filled, wire, run.files);
        SceneMonitor monitor = new SceneMonitor() {
            @Override
            public void linesRead(long n) {
                run.monitor.add("lines " + n);
            }

            @Override
            public boolean cancelled() {
                return run.monitor.size() >= cancelAtReport;
            }

            @Override
            public void warning(String message) {
                run.monitor.add("warning " + message);
            }
        };
        try {
            new SimpInterpreter(client, monitor, readAheadFrom).run(top);
        } catch (SceneException | RuntimeException e) {
            run.ended = e;
        }
        assertNoReaderThread();
        assertEquals(0, run.files.openFiles(), "files left open");
        return run;
    }

    private static void record(Run run, IntPredicate throwAt, String kind, Vertex... v) {
        if (throwAt.test(run.drawn.size())) {
            throw new IllegalStateException("renderer failed at " + run.drawn.size());
        }
        if (run.drawn.size() == 1) {
            run.readerAtSecondPrimitive = readerThreadAlive();
        }
        StringBuilder sb = new StringBuilder(kind);
        for (Vertex x : v) {
            sb.append(' ').append(x); // a record's toString shows every double exactly
        }
        run.drawn.add(sb.toString());
    }

    /**
     * A reader thread of this test's own scenes (named after the file it
     * reads): other test classes run at the same time, with readers of their own.
     */
    private static boolean isOurs(Thread t) {
        return t.getName().startsWith("simpview-reader " + OURS);
    }

    private static boolean readerThreadAlive() {
        return Thread.getAllStackTraces().keySet().stream()
                .anyMatch(t -> isOurs(t) && t.isAlive() && t != Thread.currentThread());
    }

    private static void assertNoReaderThread() {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            assertFalse(isOurs(t) && t.isAlive(), "left behind: " + t.getName());
        }
    }

    private static void assertSameRun(Run serial, Run ahead) {
        assertEquals(serial.drawn, ahead.drawn);
        assertEquals(serial.monitor, ahead.monitor);
        assertEquals(serial.ended == null ? null : serial.ended.getClass(),
                ahead.ended == null ? null : ahead.ended.getClass());
        if (serial.ended != null) {
            assertEquals(serial.ended.getMessage(), ahead.ended.getMessage());
        }
    }

    /** A scene of {@code count} random primitives in braces, with includes and style changes, then {@code tail}. */
    private Path scene(int count, String... tail) throws IOException {
        Files.write(dir.resolve(OURS + "part.simp"), List.of("wire", "line (0,0,-5) (10,10,-50) (1,0,0) (0,1,0)",
                "polygon (1,2,-3) (4,-5,-6) (7,8,-9)", "filled"));
        Random random = new Random(count);
        StringBuilder sb = new StringBuilder("{\nrotate Y 30\n");
        for (int k = 0; k < count; k++) {
            if (k % 97 == 0) {
                sb.append("file " + OURS + "part\n");
            } else if (k % 31 == 0) {
                sb.append("{\ntranslate ").append(random.nextInt(20) - 10).append(" 1, 0\n");
            } else if (k % 53 == 0) {
                sb.append("line (").append(coords(random)).append(") (").append(coords(random)).append(")\n");
            } else {
                sb.append("polygon (").append(coords(random)).append(") (1,0,0) (").append(coords(random))
                        .append(") (0,1,0) (").append(coords(random)).append(") (0,0,1)\n");
            }
        }
        for (String line : tail) {
            sb.append(line).append('\n');
        }
        Path top = dir.resolve(OURS + "top.simp");
        Files.write(top, sb.toString().getBytes(StandardCharsets.UTF_8));
        return top;
    }

    private static String coords(Random random) {
        return (random.nextDouble() * 200 - 100) + ", " + (random.nextDouble() * 200 - 100) + " "
                + (-random.nextDouble() * 200);
    }

    @Test
    void sameDrawingAndMonitorCalls() throws IOException {
        Path top = scene(5000);
        Run serial = run(top, NEVER, Integer.MAX_VALUE, k -> false);
        Run ahead = run(top, ALWAYS, Integer.MAX_VALUE, k -> false);
        assertSameRun(serial, ahead);
        assertTrue(serial.drawn.size() > 2000, "drew " + serial.drawn.size());
        // The scene has more commands than the reader's batches hold, so the
        // reader cannot have finished before the first batch was drawn: it
        // must be seen alive then, on its own thread, and only when reading ahead.
        assertTrue(5000 > ReadAhead.BATCHES * PrimitiveBatch.CAPACITY);
        assertTrue(ahead.readerAtSecondPrimitive, "no reader thread was running while the scene was drawn");
        assertFalse(serial.readerAtSecondPrimitive, "a reader thread ran although reading ahead was off");
        String last = serial.monitor.get(serial.monitor.size() - 1);
        assertTrue(last.startsWith("warning " + OURS + "top.simp:1: '{' never closed"), last);
    }

    @Test
    void samePixels() throws IOException, SceneException {
        Path top = scene(3000);
        int[] serial = pixels(top, NEVER);
        assertArrayEquals(serial, pixels(top, ALWAYS));
    }

    private static int[] pixels(Path top, long readAheadFrom) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        canvas.clear();
        SimpClient client = new SimpClient(canvas.depthCued(Rgb.WHITE, Rgb.BLACK), new DdaLineRenderer(),
                new FilledPolygonRenderer(), new WireframePolygonRenderer(new DdaLineRenderer()));
        new SimpInterpreter(client, SceneMonitor.NONE, readAheadFrom).run(top);
        return canvas.image().getRGB(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, null, 0, PageCanvas.SIZE);
    }

    @Test
    void errorComesAfterExactlyThePrimitivesBeforeIt() throws IOException {
        for (int count : new int[] {0, 1, 1023, 1024, 2500}) {
            Path top = scene(count, "polygon (1,2,3) (4,5,6) (7,8,x)", "polygon (1,2,-3) (4,5,-6) (7,8,-9)");
            Run serial = run(top, NEVER, Integer.MAX_VALUE, k -> false);
            Run ahead = run(top, ALWAYS, Integer.MAX_VALUE, k -> false);
            assertSameRun(serial, ahead);
            SceneException e = (SceneException) ahead.ended;
            assertEquals(OURS + "top.simp", e.file().getFileName().toString());
            assertEquals("expected a number, found 'x'", e.problem());
        }
    }

    @Test
    void errorInAnIncludedFileAndAMissingTopFile() throws IOException {
        String[] closing = new String[300];
        Arrays.fill(closing, "}");
        Path top = scene(1500, closing);
        Run serial = run(top, NEVER, Integer.MAX_VALUE, k -> false);
        assertSameRun(serial, run(top, ALWAYS, Integer.MAX_VALUE, k -> false));
        assertTrue(((SceneException) serial.ended).problem().startsWith("'}' has no '{'"));
        Path missing = dir.resolve(OURS + "missing.simp");
        assertSameRun(run(missing, NEVER, Integer.MAX_VALUE, k -> false),
                run(missing, ALWAYS, Integer.MAX_VALUE, k -> false));
    }

    @Test
    void cancelStopsAtTheSamePlaceAndLeavesNoThread() throws IOException {
        Path top = scene(20_000);
        Run serial = run(top, NEVER, 2, k -> false);
        Run ahead = run(top, ALWAYS, 2, k -> false);
        assertSameRun(serial, ahead);
        assertTrue(ahead.ended instanceof SceneCancelledException);
        assertEquals(2, ahead.monitor.size());
    }

    @Test
    void exceptionFromTheDrawingSideStopsTheReader() throws IOException {
        Path top = scene(20_000);
        Run serial = run(top, NEVER, Integer.MAX_VALUE, k -> k == 1500);
        Run ahead = run(top, ALWAYS, Integer.MAX_VALUE, k -> k == 1500);
        assertSameRun(serial, ahead);
        assertEquals("renderer failed at 1500", ahead.ended.getMessage());
        assertEquals(1500, ahead.drawn.size());
    }

    @Test
    void interruptOfTheDrawingThreadCancels() throws Exception {
        Path top = scene(20_000);
        Throwable[] ended = new Throwable[1];
        boolean[] stillInterrupted = new boolean[1];
        Thread drawer = new Thread(() -> {
            Thread.currentThread().interrupt();
            try {
                run(top, ALWAYS, Integer.MAX_VALUE, k -> false);
            } catch (Throwable t) {
                ended[0] = t;
            }
            stillInterrupted[0] = Thread.currentThread().isInterrupted();
        });
        drawer.start();
        drawer.join(10_000);
        assertFalse(drawer.isAlive());
        assertEquals(null, ended[0]);
        assertTrue(stillInterrupted[0]);
        assertNoReaderThread();
    }

    @Test
    void readerFailuresAreRethrownAsTheyAre() {
        SceneException scene = new SceneException(null, 1, 1, "", "bad");
        assertSame(scene, assertThrows(SceneException.class, () -> ReadAhead.rethrow(scene)));
        IllegalStateException runtime = new IllegalStateException("bug");
        assertSame(runtime, assertThrows(IllegalStateException.class, () -> ReadAhead.rethrow(runtime)));
        OutOfMemoryError error = new OutOfMemoryError("full");
        assertSame(error, assertThrows(OutOfMemoryError.class, () -> ReadAhead.rethrow(error)));
        assertNotNull(assertThrows(IllegalStateException.class, () -> ReadAhead.rethrow(new IOException())).getCause());
    }
}
