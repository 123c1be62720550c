package simpview.inspect;

import java.util.List;
import java.util.Objects;
import java.util.function.Supplier;
import simpview.geometry.Camera;
import simpview.raster.FragmentSink;
import simpview.scene.SceneException;
import simpview.scene.simp.DrawingWatch;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.scene.simp.Setting;
import simpview.scene.simp.SourcePlace;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.stage.PrimitiveTrace;
import simpview.surface.DepthCueDrawable;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.surface.ScissorDrawable;
import simpview.surface.ZBufferDrawable;

/**
 * Answers "why is this pixel this colour": replays the scene through the
 * program's one pipeline ({@link ScenePipeline#draw}, the same rules, the
 * same decision lit or depth-cued, the same geometry, rasterizers and
 * per-pixel stages), onto a canvas of its own, with a one-pixel filter that
 * keeps a record of every write attempted at the pixel and lets no other
 * write through (what happens at a pixel depends on the writes at that
 * pixel alone), so a replay costs the scene's reading and geometry and
 * little of its rasterization. Depth-cued scenes draw on the canvas's chain
 * with probes between its decorators (before the scissor, after it, after
 * the z-buffer, after the depth cue); lit scenes' fragments pass a probe
 * before the fragment stage.
 *
 * <p>One inspector keeps one canvas for its replays; not for two threads at once.
 */
public final class PixelInspector {

    private final PageCanvas canvas = new PageCanvas();
    private final SceneLibrary library;
    private final SceneMonitor monitor;
    private boolean explaining = true;

    /** Models kept by this inspector across replays, warnings dropped. */
    public PixelInspector() {
        this(new SceneLibrary(), SceneMonitor.NONE);
    }

    /** @param monitor told the scene's warnings (its trace and turn are the inspector's own) */
    public PixelInspector(SceneLibrary library, SceneMonitor monitor) {
        this.library = Objects.requireNonNull(library, "library must not be null");
        this.monitor = Objects.requireNonNull(monitor, "monitor must not be null");
    }

    /**
     * With false, the replays give each write its colour but explain none
     * ({@link PixelReport#explanation()} is null): the history alone, for
     * measuring what explaining costs.
     */
    public PixelInspector explaining(boolean explain) {
        explaining = explain;
        return this;
    }

    /**
     * The history of panel pixel (x, y) (x right, y up, 0 to 649) in the
     * scene, and what the pixel shows at the end.
     *
     * @throws IllegalArgumentException when (x, y) is outside the panel
     * @throws SceneException when the scene cannot be read at all (its file is not there)
     */
    public PixelReport inspect(InspectedScene scene, int x, int y) throws SceneException {
        return inspect(scene, x, y, HistoryEntry.NO_NUMBER);
    }

    /**
     * As {@link #inspect(InspectedScene, int, int)}, also keeping primitive
     * {@code primitive}'s vertices for {@link PixelReport#vertices(int)}
     * whether or not it reaches the pixel ({@link HistoryEntry#NO_NUMBER}: only those that do).
     * A scene with an error is inspected as far as the error, as the page
     * shows it drawn that far: {@link PixelReport#error} names it.
     *
     * @throws SceneException when the scene cannot be read at all (its file is not there)
     */
    public PixelReport inspect(InspectedScene scene, int x, int y, int primitive) throws SceneException {
        Objects.requireNonNull(scene, "scene must not be null");
        if (x < 0 || x >= PageCanvas.PANEL || y < 0 || y >= PageCanvas.PANEL) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is outside the panel: x and y are 0 to "
                    + (PageCanvas.PANEL - 1) + ", from the panel's bottom-left pixel, y up");
        }
        canvas.clear();
        PixelWatch watch = new PixelWatch(x, y, canvas.zbuffer());
        watch.want(primitive);
        watch.explaining(explaining);
        Replay replay = new Replay(watch);
        ScenePipeline.Options options = ScenePipeline.Options.byCommands(library).withRules(scene.rules())
                .withCue(scene.near(), scene.far()).withOwnColours(scene.ownColours());
        ScenePipeline.Drawn drawn;
        SceneException error = null;
        try {
            drawn = ScenePipeline.draw(scene.file(), canvas, options, replay);
        } catch (SceneException e) {
            if (scene.nothingRead(e)) {
                throw e; // there is no history to tell
            }
            error = e;
            drawn = new ScenePipeline.Drawn(replay.lit, null, true, List.of());
        }
        int argb = canvas.panel().getPixel(x, y);
        return new PixelReport(scene, drawn, error, x, y, argb, canvas.zbuffer().depthAt(x, y), watch.entries(),
                watch::source, watch.camera());
    }

    /** What the last replay drew: the inspected pixel as the page has it, and little else (the filter drops the rest). */
    public PageCanvas canvas() {
        return canvas;
    }

    /** The replay's monitor: the watch follows the primitives and sets its probes into the drawing. */
    private final class Replay implements SceneMonitor, DrawingWatch {
        private final PixelWatch watch;
        private CueExplainer cue;
        /** Whether the rules last begun are the lit ones: what the report says of a scene that stops at an error. */
        private boolean lit;

        Replay(PixelWatch watch) {
            this.watch = watch;
        }

        @Override
        public void warning(String message) {
            monitor.warning(message);
        }

        /** The inspector's reader's name for it: the command line's option, not the library's method. */
        @Override
        public String nameOf(Setting setting) {
            return monitor.nameOf(setting);
        }

        @Override
        public PrimitiveTrace trace() {
            return watch;
        }

        @Override
        public DrawingWatch watch() {
            return this;
        }

        @Override
        public Drawable depthCued(PageCanvas on, Rgb near, Rgb far, boolean ownColours) {
            Camera view = Camera.PARALLEL;
            cue = new CueExplainer(ownColours ? null : near, far);
            Drawable shown = new WriteProbe(watch, WriteProbe.Point.SHOWN, on.panel());
            Drawable coloured = ownColours ? shown : new DepthCueDrawable(near, far, view, shown);
            return new WriteProbe(watch, WriteProbe.Point.ATTEMPTED, new ScissorDrawable(view,
                    new WriteProbe(watch, WriteProbe.Point.IN_RANGE, new ZBufferDrawable(on.zbuffer(),
                            new WriteProbe(watch, WriteProbe.Point.PASSED_DEPTH, coloured)))));
        }

        @Override
        public FragmentSink fragments(FragmentStage stage) {
            return new FragmentProbe(watch, stage, stage.width());
        }

        @Override
        public void began(Supplier<List<SourcePlace>> chain, LitState lit) {
            this.lit = lit != null;
            watch.begin(chain, lit, cue);
        }
    }
}
