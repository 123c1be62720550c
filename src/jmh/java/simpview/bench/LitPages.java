package simpview.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.DrawingThreads;

/**
 * One course page of the third or fourth assignment (@Param scene, as
 * "a3/pageI" or "a4/page-d"), from course-simp-a3 and course-simp-a4 beside
 * -Dsimpview.courseSimp: clear the canvas, then draw the lit scene, as the
 * window does. Its .simp files and .obj models are read once in the set-up
 * and kept by its {@code SceneLibrary} (as the window keeps them while their
 * files are unchanged), so one op is the warm redraw. Sampled, in ms.
 * Warmed for 8 s: with {@code -p threads=2} a page settles only after
 * 5-9 s (both cores draw while C2 compiles; A4 page-d's warm-up iterations
 * 7.2, 3.3, 3.0, 2.9, 2.9, 2.8, 2.7, 2.7, 2.6, 2.6 ms, session 24), one
 * thread after 2-4.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 8, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class LitPages {

    @Param({"a3/pageA", "a3/pageB", "a3/pageC", "a3/pageD", "a3/pageE", "a3/pageF", "a3/pageG", "a3/pageH",
            "a3/pageI", "a3/tomsPageJ",
            "a4/page-a1", "a4/page-a2", "a4/page-a3", "a4/page-b1", "a4/page-b2", "a4/page-b3",
            "a4/page-c1", "a4/page-c2", "a4/page-c3", "a4/page-d", "a4/page-e", "a4/page-f1", "a4/page-f2",
            "a4/page-g", "a4/page-h"})
    public String scene;

    /** Threads drawing each page's bands (1: drawn as read, on the benchmark's thread; more: each batch drawn while the next is read). */
    @Param({"1"})
    public int threads;

    private DrawingThreads drawing;
    private final PageCanvas canvas = new PageCanvas();
    private final SceneLibrary library = new SceneLibrary();
    private Path file;

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        drawing = DrawingThreads.of(threads);
        canvas.drawWith(drawing);
        Path courseSimp = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        file = sceneFile(courseSimp.toAbsolutePath().getParent(), scene);
        if (!Files.isRegularFile(file)) {
            throw new IllegalStateException("no " + file + ": the course's files belong beside the project");
        }
        clearAndDraw(); // parses the models, and fails the trial at once if the scene cannot be drawn
        if (library.models().parseCount() == 0 && scene.endsWith("pageI")) {
            throw new IllegalStateException("pageI drew no model");
        }
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        drawing.close();
    }

    /**
     * The .simp file of a lit course page named as the scene parameter names
     * it ("a3/pageI"), in {@code folder}, which holds course-simp-a3 and
     * course-simp-a4: for this benchmark and the measurements beside it.
     */
    static Path sceneFile(Path folder, String scene) {
        String[] parts = scene.split("/");
        return folder.resolve("course-simp-" + parts[0]).resolve(parts[1] + ".simp");
    }

    @Benchmark
    public PageCanvas clearAndDraw() throws SceneException {
        redraw(canvas, file, library);
        return canvas;
    }

    /**
     * One op of this benchmark, the warm redraw as the window makes it:
     * {@code canvas} cleared, then the lit scene in {@code file} drawn with
     * the models {@code library} keeps. The measurements beside the
     * benchmark time the same.
     */
    static void redraw(PageCanvas canvas, Path file, SceneLibrary library) throws SceneException {
        canvas.clear();
        ScenePipeline.draw(file, canvas, ScenePipeline.Options.lit(library), SceneMonitor.NONE);
    }
}
