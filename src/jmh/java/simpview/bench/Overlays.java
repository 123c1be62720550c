package simpview.bench;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Rectangle2D;
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
import org.openjdk.jmh.annotations.Warmup;
import simpview.inspect.InspectedScene;
import simpview.inspect.Overdraw;
import simpview.inspect.SkippedPrimitives;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneDrawer;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.window.LineKeepingDownscale;
import simpview.window.instruments.BackFacePicture;
import simpview.window.instruments.DepthPicture;
import simpview.window.instruments.OverdrawPicture;
import simpview.window.instruments.Outlines;
import simpview.window.render.DrawSettings;
import simpview.window.render.RenderJob;
import simpview.window.render.RenderedView;
import simpview.window.render.SpareImages;
import simpview.window.render.View;

/**
 * What each overlay of the window costs against the page's own drawing, in
 * one run: {@code draw} is the page drawn as the command line draws it (one
 * thread, no record); {@code windowDraw} as the window draws it (who drew
 * each pixel and every primitive recorded, what the back-face and depth
 * overlays read); {@code overdraw} and {@code failures} the V and Shift+V
 * overlays (the scene replayed counting every write that reaches each
 * pixel's depth test, then the heat map with its scale); {@code backFaces}
 * the K overlay and {@code depth} the depth picture, from the facts the
 * window's drawing recorded; {@code culledAndClipped} the U overlay (a
 * replay that writes no pixel); {@code downscaleTo650} and
 * {@code downscaleTo400} the finished picture made smaller than 1:1 with its
 * lines kept, to 650/750 and 400/750 of its side (the view below 1:1, on
 * the EDT once per picture and zoom). Scenes: A4's page-d and A3's pageI from the
 * course folders beside -Dsimpview.courseSimp, and A2's page 7 as the page
 * draws it (depth-cued from its near colour). Sampled, in ms.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 4, time = 1)
@Fork(1)
public class Overlays {

    @Param({"a4/page-d", "a3/pageI", "a2/page7"})
    public String scene;

    private final SceneLibrary library = new SceneLibrary();
    private final PageCanvas canvas = new PageCanvas();
    private final PageRenderer renderer = new PageRenderer();
    private final PageRenderer windowRenderer = new PageRenderer();
    private final Provenance provenance = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
    /** A traced picture's image, which the window keeps and never gives back: each is drawn on a new one. */
    private final SpareImages nothingGivenBack = new SpareImages();
    private PageContext context;
    private InspectedScene inspected;
    private View view;
    private Path file;
    private RenderedView recorded;
    private Overdraw.Counts counted;

    @Setup(Level.Trial)
    public void setUp() throws SceneException {
        Path courseSimp = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        context = new PageContext(PageContext.DEFAULT_SEED, courseSimp, PageContext.PROJECT_SCENES, SceneMonitor.NONE);
        String[] parts = scene.split("/");
        if (parts[0].equals("a2")) {
            int page = Integer.parseInt(parts[1].substring("page".length()));
            inspected = InspectedScene.page(page, context);
            view = new View.OfPage(page);
            file = null;
        } else {
            file = LitPages.sceneFile(courseSimp.toAbsolutePath().getParent(), scene);
            if (!Files.isRegularFile(file)) {
                throw new IllegalStateException("no " + file + ": the course's files belong beside the project");
            }
            inspected = InspectedScene.of(file);
            view = new View.OfScene(file);
        }
        draw();
        recorded = windowDraw();
        if (recorded == null || recorded.facts().owners() == null) {
            throw new IllegalStateException(scene + ": the window's drawing recorded no owners");
        }
        Overdraw.Counts counts = Overdraw.counts(inspected, library);
        counted = counts;
        System.out.println(scene + ": up to " + Overdraw.max(counts.reached()) + " writes at a pixel, "
                + BackFacePicture.of(recorded.image(), recorded.facts()).backFacing() + " back faces");
    }

    @Benchmark
    public PageCanvas draw() throws SceneException {
        if (file == null) {
            return renderer.render(((View.OfPage) view).number(), context);
        }
        canvas.clear();
        ScenePipeline.draw(file, canvas, ScenePipeline.Options.byCommands(library), SceneMonitor.NONE);
        return canvas;
    }

    @Benchmark
    public RenderedView windowDraw() {
        return new RenderJob(view, context, DrawSettings.WINDOW).run(windowRenderer, SceneDrawer.SIMP, library,
                provenance, nothingGivenBack);
    }

    @Benchmark
    public BufferedImage overdraw() throws SceneException {
        return OverdrawPicture.of(Overdraw.counts(inspected, library).reached());
    }

    @Benchmark
    public BufferedImage failures() throws SceneException {
        return OverdrawPicture.of(Overdraw.counts(inspected, library).failed(), "depth-test failures");
    }

    /** The overdraw overlay's replay alone, without its picture. */
    @Benchmark
    public Overdraw.Counts counts() throws SceneException {
        return Overdraw.counts(inspected, library);
    }

    /** The overdraw overlay's picture alone, of counts made in the set-up. */
    @Benchmark
    public BufferedImage heatMap() {
        return OverdrawPicture.of(counted.reached());
    }

    @Benchmark
    public BackFacePicture.Tinted backFaces() {
        return BackFacePicture.of(recorded.image(), recorded.facts());
    }

    @Benchmark
    public BufferedImage depth() {
        return DepthPicture.of(recorded.facts().depths(), recorded.facts().depthStart());
    }

    @Benchmark
    public SkippedPrimitives.Found culledAndClipped() throws SceneException {
        return SkippedPrimitives.of(inspected, library);
    }

    @Benchmark
    public BufferedImage downscaleTo650() {
        return LineKeepingDownscale.of(recorded.image(), 650.0 / 750);
    }

    @Benchmark
    public BufferedImage downscaleTo400() {
        return LineKeepingDownscale.of(recorded.image(), 400.0 / 750);
    }

    /** Where wireOverFill draws: a page-sized picture, drawn over again at each call. */
    private final BufferedImage overlay = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);

    /**
     * W, wire over fill: every recorded primitive's outline drawn over the
     * page at 1:1 as the view draws it (one 1-px path, not antialiased, cut
     * to the panel), the outlines gathered from the record each time.
     */
    @Benchmark
    public BufferedImage wireOverFill() {
        Graphics2D g = overlay.createGraphics();
        try {
            g.clip(new Rectangle2D.Double(PageCanvas.MARGIN, PageCanvas.MARGIN, PageCanvas.PANEL, PageCanvas.PANEL));
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
            g.setStroke(new BasicStroke(1f));
            g.setColor(new Color(0x00FF80));
            g.draw(Outlines.path(Outlines.wire(recorded.facts().primitives()), x -> x, y -> y));
        } finally {
            g.dispose();
        }
        return overlay;
    }
}
