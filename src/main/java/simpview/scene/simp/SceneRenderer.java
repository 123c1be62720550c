package simpview.scene.simp;

import java.nio.file.Path;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.shading.FragmentStage;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/** Reads a SIMP file and draws it, by the depth-cued rules or the lit ones. */
public final class SceneRenderer {

    /** The models of every lit scene drawn in this program, kept while their files are unchanged. */
    private static final ObjLibrary MODELS = new ObjLibrary();

    private SceneRenderer() {
    }

    /**
     * Draws the depth-cued scene in {@code file} onto {@code panel}, a drawable
     * in panel coordinates (650x650, y up) that already does whatever the page
     * wants done per pixel (scissor, z-buffer, depth cue). Starts from a fresh
     * state: identity CTM, empty stacks, style filled.
     */
    public static void draw(Path file, Drawable panel, SceneMonitor monitor) throws SceneException {
        SimpClient client = new SimpClient(panel);
        client.follow(monitor.trace());
        client.turnView(monitor.viewTurn());
        new SimpInterpreter(client, monitor).run(file);
    }

    /**
     * Draws the lit scene in {@code file} onto the canvas's panel, depth-tested
     * against its z-buffer, which starts at -infinity; the canvas is expected
     * cleared. Models come from the program's shared library.
     */
    public static void drawLit(Path file, PageCanvas canvas, SceneMonitor monitor) throws SceneException {
        drawLit(file, canvas, monitor, MODELS);
    }

    /** {@link #drawLit(Path, PageCanvas, SceneMonitor)} with models from {@code models}. */
    public static void drawLit(Path file, PageCanvas canvas, SceneMonitor monitor, ObjLibrary models)
            throws SceneException {
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        FragmentStage fragments = new FragmentStage(canvas.zbuffer(), canvas.litPanel());
        SimpClient client = SimpClient.lit(fragments, models);
        client.follow(monitor.trace());
        client.turnView(monitor.viewTurn());
        new SimpInterpreter(client, monitor).run(file);
        double[] centre = client.shownCentre();
        if (centre != null) {
            monitor.shownCentre(centre);
        }
    }

    /** The library lit scenes take their models from. */
    public static ObjLibrary models() {
        return MODELS;
    }
}
