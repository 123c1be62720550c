package simpview.pages;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Objects;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * Renders whole pages: clears the canvas (fresh image, z-buffer, CTM, stacks
 * and style for every page) and draws one: a page of the eight
 * ({@link #render}, as {@code simpview render --page N} draws it) or any
 * scene file as a page ({@link #renderScene(Path)}, as {@code simpview render
 * --scene F.simp} draws it). Reuses one canvas, so the canvas returned is
 * overwritten by the next page: keep a copy ({@link PageCanvas#snapshot}) or
 * write it out first. Not for two threads at once.
 *
 * <p>The threads that draw scenes are given ({@link #PageRenderer(DrawingThreads)}):
 * whoever makes them closes them, after the last page ({@code try (DrawingThreads
 * threads = DrawingThreads.of(2)) { ... }}). README.md's "Using simpview from
 * Java" has examples.
 */
public final class PageRenderer {

    private final PageCanvas canvas = new PageCanvas();
    /** The files of the scenes {@link #renderScene(Path)} draws, kept from scene to scene while unchanged. */
    private final SceneLibrary library = new SceneLibrary();

    /** Draws every page on the caller's thread alone. */
    public PageRenderer() {
    }

    /**
     * Draws the scene pages with {@code threads} (see {@link PageCanvas#drawWith}),
     * to the same pictures as one thread; whoever gives them closes them.
     */
    public PageRenderer(DrawingThreads threads) {
        Objects.requireNonNull(threads, "threads must not be null");
        canvas.drawWith(threads);
    }

    /**
     * Draws page n. On a scene error the canvas keeps what was drawn before it
     * and the exception is thrown on.
     */
    public PageCanvas render(int pageNumber, PageContext context) throws SceneException {
        Objects.requireNonNull(context, "context must not be null");
        canvas.clear();
        Assignment2.page(pageNumber).draw(canvas, context);
        return canvas;
    }

    /** {@code page}, one of the eight or a page drawn as one of them is, as a new image (a copy, safe to keep). */
    public BufferedImage renderImage(Page page, PageContext context) throws SceneException {
        Objects.requireNonNull(context, "context must not be null");
        canvas.clear();
        page.draw(canvas, context);
        return canvas.snapshot();
    }

    /** Page n as a new image (a copy, safe to keep). */
    public BufferedImage renderImage(int pageNumber, PageContext context) throws SceneException {
        return render(pageNumber, context).snapshot();
    }

    /**
     * Draws the scene in {@code file} as a whole page, as {@code simpview
     * render --scene} draws it: lit when its commands say so (SPEC Part 2),
     * else depth-cued from white at z = 0 to black at z = -200; its warnings
     * dropped. The files it reads are kept by this renderer for its next
     * scenes while they are unchanged. On a scene error the canvas keeps
     * what was drawn before it and the exception is thrown on.
     *
     * @return the canvas, overwritten by the next page or scene
     * @throws SceneException where the scene is wrong: its file, line and column (or a file that is not there)
     */
    public PageCanvas renderScene(Path file) throws SceneException {
        Objects.requireNonNull(file, "file must not be null");
        renderScene(file, ScenePipeline.Options.byCommands(library), SceneMonitor.NONE);
        return canvas;
    }

    /**
     * As {@link #renderScene(Path)}, a {@code file} or {@code obj} name that is not beside the file naming it
     * looked for in {@code workingDir} instead of the Java process's working directory (SPEC's second place: the
     * folder the course's program ran in).
     *
     * @return the canvas, overwritten by the next page or scene
     * @throws SceneException where the scene is wrong: its file, line and column (or a file that is not there)
     */
    public PageCanvas renderScene(Path file, Path workingDir) throws SceneException {
        Objects.requireNonNull(file, "file must not be null");
        Objects.requireNonNull(workingDir, "workingDir must not be null");
        renderScene(file, ScenePipeline.Options.byCommands(library).withWorkingDir(workingDir), SceneMonitor.NONE);
        return canvas;
    }

    /**
     * Draws the scene in {@code file} as a whole page, by {@code options}
     * (other depth-cue colours, the vertices' own colours, which rules),
     * telling {@code monitor} its warnings and progress. The picture is on
     * {@link #canvas()}.
     *
     * @return what was drawn: lit or depth-cued, and why; every file read
     * @throws SceneException where the scene is wrong: its file, line and column (or a file that is not there)
     */
    public ScenePipeline.Drawn renderScene(Path file, ScenePipeline.Options options, SceneMonitor monitor)
            throws SceneException {
        Objects.requireNonNull(file, "file must not be null");
        Objects.requireNonNull(options, "options must not be null");
        Objects.requireNonNull(monitor, "monitor must not be null");
        canvas.clear();
        return ScenePipeline.draw(file, canvas, options, monitor);
    }

    /** The canvas every page and scene is drawn on, holding the last one drawn. */
    public PageCanvas canvas() {
        return canvas;
    }
}
