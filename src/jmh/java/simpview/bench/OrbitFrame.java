package simpview.bench;

import java.awt.image.BufferedImage;
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
import simpview.geometry.Axis;
import simpview.geometry.Matrix4;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.surface.DrawingThreads;
import simpview.window.render.DrawSettings;
import simpview.window.render.SpareImages;

/**
 * One frame of a turning view, as the window's render thread makes it while
 * a right-drag turns a scene: clear, draw the whole scene turned (yaw 30°,
 * pitch 15°), then hand the image to the EDT, the canvas going on on the image
 * of the frame before, which the EDT gives back once it shows the next
 * ({@link PageCanvas#handOff}; until session 48 each frame's image was a new
 * copy). The window draws a drag's frames without the inspector's record,
 * and the frame after the drag with it: @Param record=true adds the
 * provenance decorator, a fresh {@link PrimitiveLog} and the copies of the
 * depths and the owners. A drag's frames keep their depths only while the
 * depth view is on: @Param depthView=true copies them out too
 * (DrawSettings.keepsDepths). @Param scene:
 * "page7" (depth-cued, turned about the view volume's centre) or a course
 * page of the third or fourth assignment, as "a3/pageI" or "a4/page-d" (lit: the camera
 * moves about the centre of what the unturned view showed, found in the
 * set-up by one traced drawing). Models are parsed once, in the set-up.
 * Not in it: the window's look through the scene's files for lit commands
 * and for files to watch. @Param turned=false draws the unturned view the
 * same way, and copy=false leaves out the hand-off and the copies, to show
 * what each costs.
 * Sampled, in ms; the target is 16 ms. Warmed up for 8 s: with two threads
 * a turned frame of a4/page-d took 6.8, 3.6, 3.4, 3.0 ... 2.9 ms in its first
 * ten seconds (both cores draw while C2 compiles), and after 3 s of warm-up
 * the median came out at 5.1 ms, against 2.8 after 10 (session 23).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 8, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class OrbitFrame {

    @Param({"page7", "a3/pageA", "a3/pageB", "a3/pageC", "a3/pageD", "a3/pageE", "a3/pageF", "a3/pageG",
            "a3/pageH", "a3/pageI", "a3/tomsPageJ",
            "a4/page-a1", "a4/page-a2", "a4/page-a3", "a4/page-b1", "a4/page-b2", "a4/page-b3",
            "a4/page-c1", "a4/page-c2", "a4/page-c3", "a4/page-d", "a4/page-e", "a4/page-f1", "a4/page-f2",
            "a4/page-g", "a4/page-h"})
    public String scene;

    @Param({"true", "false"})
    public boolean turned;

    @Param({"true"})
    public boolean copy;

    @Param({"false"})
    public boolean record;

    @Param({"false"})
    public boolean depthView;

    private static final double YAW = 30;
    private static final double PITCH = 15;

    /** Threads drawing each frame's bands (1: drawn as read, on the benchmark's thread; more: each batch drawn while the next is read). */
    @Param({"1"})
    public int threads;

    private PageRenderer renderer;
    private DrawingThreads drawing;
    /** The window's settings for such a frame: which copies it keeps ({@link DrawSettings#keepsDepths}). */
    private DrawSettings settings;
    private final SceneLibrary library = new SceneLibrary();
    private final Provenance provenance = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
    private final Turned monitor = new Turned();
    private PageContext context;
    private Path litFile;
    private boolean findingCentre;
    /** The images the EDT gave back, as the window's render thread keeps them. */
    private final SpareImages spares = new SpareImages();
    /** The image of the frame the EDT shows now: given back once the next frame is handed to it. */
    private BufferedImage shown;

    /** What the window's render job tells the scene: the turn, and a fresh trace per frame. */
    private static final class Turned implements SceneMonitor {
        private Matrix4 turn;
        private PrimitiveLog log;
        private double[] centre;

        @Override
        public PrimitiveTrace trace() {
            return log;
        }

        @Override
        public Matrix4 viewTurn() {
            return turn;
        }

        @Override
        public void shownCentre(double[] xyz) {
            centre = xyz;
        }
    }

    /** What the frame hands the EDT. */
    public record Frame(BufferedImage image, double[] depths, int[] owners) {
    }

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        drawing = DrawingThreads.of(threads);
        settings = DrawSettings.WINDOW.withRecord(record).withDepthView(depthView);
        renderer = new PageRenderer(drawing);
        Path course = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        context = new PageContext(PageContext.DEFAULT_SEED, course, PageContext.PROJECT_SCENES, monitor);
        renderer.canvas().recordProvenance(record ? provenance : null);
        double[] centre = {0, 0, -100};
        if (!scene.equals("page7")) {
            litFile = LitPages.sceneFile(course.toAbsolutePath().getParent(), scene);
            if (!Files.isRegularFile(litFile)) {
                throw new IllegalStateException("no " + litFile + ": the course's files belong beside the project");
            }
            findingCentre = true;
            frame(); // unturned: parses the models and finds what the view shows
            findingCentre = false;
            if (monitor.centre == null) {
                throw new IllegalStateException(scene + " showed nothing");
            }
            centre = monitor.centre;
        }
        monitor.turn = !turned ? null : Matrix4.translation(centre[0], centre[1], centre[2])
                .times(Matrix4.rotation(Axis.X, PITCH))
                .times(Matrix4.rotation(Axis.Y, YAW))
                .times(Matrix4.translation(-centre[0], -centre[1], -centre[2]));
        frame(); // fails the trial at once if the scene cannot be drawn
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        drawing.close();
    }

    @Benchmark
    public Frame frame() throws SceneException {
        monitor.log = record || findingCentre ? new PrimitiveLog(provenance, -1) : null;
        PageCanvas canvas = renderer.canvas();
        if (litFile == null) {
            renderer.render(7, context);
        } else {
            canvas.clear();
            ScenePipeline.draw(litFile, canvas, ScenePipeline.Options.lit(library), monitor);
        }
        if (!copy) {
            return null;
        }
        Frame frame = new Frame(canvas.handOff(spares.take()),
                settings.keepsDepths() ? canvas.zbuffer().copyDepths() : null, record ? provenance.copyOwners() : null);
        if (shown != null && !record) {
            spares.giveBack(shown); // the window gives back a drag's frames alone: a traced one may be kept
        }
        shown = frame.image();
        return frame;
    }
}
