package simpview.scene.simp;

import java.nio.file.Path;
import simpview.stage.CuedPrimitives;
import simpview.stage.LitPrimitives;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.shading.FragmentStage;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;

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
        draw(file, panel, monitor, DrawingThreads.one(), null);
    }

    /**
     * The same, drawn by {@code threads}: read and taken through the
     * geometry stage once, on this thread, then drawn band by band by all of
     * them (see {@link CuedPrimitives}), to the same picture, depths and
     * owners as one thread draws. {@code provenance} is the record the panel
     * writes owners into, or null.
     */
    public static void draw(Path file, Drawable panel, SceneMonitor monitor, DrawingThreads threads,
            Provenance provenance) throws SceneException {
        SimpClient client = new SimpClient(panel);
        CuedPrimitives record = threads.isOne() ? null : new CuedPrimitives(threads, panel, provenance);
        client.painter().recordTo(record);
        client.follow(monitor.trace());
        client.turnView(monitor.viewTurn());
        try {
            new SimpInterpreter(client, monitor).run(file);
        } finally {
            if (record != null) {
                record.flush(); // what was read before a failure is drawn, as one thread draws it
            }
        }
    }

    /**
     * Draws the lit scene in {@code file} onto the canvas's panel, depth-tested
     * against its z-buffer, which starts at -infinity; the canvas is expected
     * cleared. Models come from the program's shared library.
     */
    public static void drawLit(Path file, PageCanvas canvas, SceneMonitor monitor) throws SceneException {
        drawLit(file, canvas, monitor, MODELS);
    }

    /**
     * {@link #drawLit(Path, PageCanvas, SceneMonitor)} with models from
     * {@code models}, drawn by the canvas's threads: with more than one, the
     * scene goes through the geometry stage once, on this thread, and is
     * then drawn band by band by all of them (see {@link LitPrimitives}).
     */
    public static void drawLit(Path file, PageCanvas canvas, SceneMonitor monitor, ObjLibrary models)
            throws SceneException {
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        Drawable panel = canvas.litPanel();
        FragmentStage fragments = new FragmentStage(canvas.zbuffer(), panel);
        SimpClient client = SimpClient.lit(fragments, models);
        DrawingThreads threads = canvas.drawingThreads();
        LitPrimitives record = threads.isOne() ? null
                : new LitPrimitives(threads, canvas.zbuffer(), panel, canvas.provenance());
        client.recordTo(record);
        client.follow(monitor.trace());
        client.turnView(monitor.viewTurn());
        try {
            new SimpInterpreter(client, monitor).run(file);
        } finally {
            if (record != null) {
                record.flush();
            }
        }
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
