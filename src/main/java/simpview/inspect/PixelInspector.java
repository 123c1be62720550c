package simpview.inspect;

import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.SceneRenderer;
import simpview.scene.simp.SimpClient;
import simpview.scene.simp.SimpInterpreter;
import simpview.shading.FragmentStage;
import simpview.surface.DepthCueDrawable;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.ScissorDrawable;
import simpview.surface.ZBufferDrawable;

/**
 * Answers "why is this pixel this colour": replays the scene with the
 * program's own drawing code, onto a canvas of its own, with a one-pixel
 * filter that keeps a record of every write attempted at the pixel and lets
 * no other write through (what happens at a pixel depends on the writes at
 * that pixel alone), so a replay costs the scene's reading and geometry and
 * little of its rasterization. Depth-cued scenes go through the pages' drawable chain with
 * probes between its decorators (before the scissor, after it, after the
 * z-buffer, after the depth cue); lit scenes through their fragment stage,
 * with a probe between the rasterizers and it.
 *
 * <p>One inspector keeps one canvas for its replays; not for two threads at once.
 */
public final class PixelInspector {

    private final PageCanvas canvas = new PageCanvas();
    private final ObjLibrary models;
    private final SceneMonitor monitor;
    private boolean explaining = true;

    /** Models from the program's shared library, warnings dropped. */
    public PixelInspector() {
        this(SceneRenderer.models(), SceneMonitor.NONE);
    }

    public PixelInspector(ObjLibrary models, SceneMonitor monitor) {
        this.models = models;
        this.monitor = monitor;
    }

    /**
     * With false, the replays give each write its colour but explain none
     * ({@link PixelReport#explanation()} is null): the history alone, for
     * the window's overlays and for measuring what explaining costs.
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
     * @throws SceneException when the scene has an error (the history then goes up to it)
     */
    public PixelReport inspect(InspectedScene scene, int x, int y) throws SceneException {
        return inspect(scene, x, y, HistoryEntry.NO_NUMBER);
    }

    /**
     * As {@link #inspect(InspectedScene, int, int)}, also keeping primitive
     * {@code primitive}'s vertices for {@link PixelReport#vertices(int)}
     * whether or not it reaches the pixel ({@link HistoryEntry#NO_NUMBER}: only those that do).
     */
    public PixelReport inspect(InspectedScene scene, int x, int y, int primitive) throws SceneException {
        if (x < 0 || x >= PageCanvas.PANEL || y < 0 || y >= PageCanvas.PANEL) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is outside the panel: x and y are 0 to "
                    + (PageCanvas.PANEL - 1) + ", from the panel's bottom-left pixel, y up");
        }
        canvas.clear();
        PixelWatch watch = scene.lit() ? replayLit(scene, x, y, primitive) : replayCued(scene, x, y, primitive);
        int argb = canvas.panel().getPixel(x, y);
        return new PixelReport(scene, x, y, argb, canvas.zbuffer().depthAt(x, y), watch.entries(), watch::source);
    }

    private PixelWatch replayLit(InspectedScene scene, int x, int y, int wanted) throws SceneException {
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        FragmentStage stage = new FragmentStage(canvas.zbuffer(), canvas.panel());
        SimpClient client = SimpClient.lit(stage, models);
        PixelWatch watch = new PixelWatch(x, y, client::includeChain, () -> client.litState().camera(),
                () -> client.litState().worldToCamera(), true, canvas.zbuffer(), new LitExplainer(client.litState()));
        watch.want(wanted);
        watch.explaining(explaining);
        client.follow(watch);
        client.fragmentsThrough(new FragmentProbe(watch, stage, stage.width()));
        SimpInterpreter.onOneThread(client, monitor).run(scene.file());
        return watch;
    }

    private PixelWatch replayCued(InspectedScene scene, int x, int y, int wanted) throws SceneException {
        Camera view = Camera.PARALLEL;
        PixelWatch[] made = new PixelWatch[1];
        SimpClient[] client = new SimpClient[1];
        PixelWatch watch = new PixelWatch(x, y, () -> client[0].includeChain(), () -> view, Matrix4::identity, false,
                canvas.zbuffer(), new CueExplainer(scene.near(), scene.far()));
        watch.want(wanted);
        watch.explaining(explaining);
        made[0] = watch;
        Drawable shown = new WriteProbe(watch, WriteProbe.Point.SHOWN, canvas.panel());
        Drawable coloured = scene.near() == null ? shown : new DepthCueDrawable(scene.near(), scene.far(), view, shown);
        Drawable chain = new WriteProbe(watch, WriteProbe.Point.ATTEMPTED, new ScissorDrawable(view,
                new WriteProbe(watch, WriteProbe.Point.IN_RANGE, new ZBufferDrawable(canvas.zbuffer(),
                        new WriteProbe(watch, WriteProbe.Point.PASSED_DEPTH, coloured)))));
        client[0] = new SimpClient(chain);
        client[0].follow(watch);
        SimpInterpreter.onOneThread(client[0], monitor).run(scene.file());
        return made[0];
    }

    /** What the last replay drew: the inspected pixel as the page has it, and little else (the filter drops the rest). */
    public PageCanvas canvas() {
        return canvas;
    }
}
