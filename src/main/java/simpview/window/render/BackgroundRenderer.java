package simpview.window.render;

import simpview.scene.simp.SceneDrawer;

import java.awt.image.BufferedImage;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BiConsumer;
import javax.swing.SwingUtilities;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneLibrary;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;

/**
 * Draws pictures one at a time on a thread of its own, so the window keeps
 * answering while a large scene is read. Only that thread touches the canvas;
 * the EDT gets each picture's image once the canvas has let go of it, and
 * may give it back ({@link #giveBack}) for a later picture to be drawn on.
 */
public final class BackgroundRenderer {

    private final ExecutorService thread = Executors.newSingleThreadExecutor(task -> {
        Thread t = new Thread(task, "simpview-render");
        t.setDaemon(true);
        return t;
    });
    /** simpview-render and its helpers, which draw each picture's bands with it; closed by {@link #shutdown}. */
    private final DrawingThreads drawing;
    private final PageRenderer renderer;
    private final SceneDrawer drawer;
    /** Who drew each pixel of the picture being drawn; only this thread writes it (each band its own rows). */
    private final Provenance provenance = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
    /** The window's scene files and obj models, kept across redraws while unchanged (thread safe). */
    private final SceneLibrary library = new SceneLibrary();
    /** The images of pictures the window has let go of, which the next pictures are drawn on (thread safe). */
    private final SpareImages spares = new SpareImages();

    /** Draws on the render thread alone. */
    public BackgroundRenderer(SceneDrawer drawer) {
        this(drawer, 1);
    }

    /** Draws each picture with {@code threads} threads, the render thread and threads - 1 helpers. */
    public BackgroundRenderer(SceneDrawer drawer, int threads) {
        this.drawer = drawer;
        this.drawing = DrawingThreads.of(threads);
        this.renderer = new PageRenderer(drawing);
    }

    /** Runs the job after those before it; {@code done} gets it and its picture (null if cancelled) on the EDT. */
    public void submit(RenderJob job, BiConsumer<RenderJob, RenderedView> done) {
        thread.execute(() -> {
            RenderedView result = job.run(renderer, drawer, library, provenance, spares);
            SwingUtilities.invokeLater(() -> done.accept(job, result));
        });
    }

    /**
     * {@code image}, a picture's that this renderer drew, is no longer shown
     * or held on the EDT: a later picture may be drawn on it.
     */
    public void giveBack(BufferedImage image) {
        spares.giveBack(image);
    }

    /** Whether {@code image} was given back and waits to be drawn on. */
    public boolean holdsSpare(BufferedImage image) {
        return spares.holds(image);
    }

    /**
     * Runs {@code task} on the render thread, after the pictures asked for before it and before those asked for
     * after: work on a finished picture that would hold the EDT (a dropped picture's comparison with it).
     */
    public void runAfterDrawing(Runnable task) {
        thread.execute(task);
    }

    /**
     * The files its pictures read, kept across redraws: thread safe, so that
     * whoever else draws the window's scenes (its inspector) may share them.
     */
    public SceneLibrary library() {
        return library;
    }

    /**
     * Makes the next picture read every file from disk again: the kept scene
     * files and models are dropped on the render thread, after the jobs
     * submitted before and before those submitted after.
     */
    public void forgetFiles() {
        thread.execute(library::clear);
    }

    public void shutdown() {
        thread.shutdownNow();
        drawing.close();
    }
}
