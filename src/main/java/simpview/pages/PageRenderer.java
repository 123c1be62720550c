package simpview.pages;

import java.awt.image.BufferedImage;
import simpview.scene.SceneException;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * Renders whole pages: clears the canvas (fresh image, z-buffer, CTM, stacks
 * and style for every page) and draws one. Reuses one canvas; not for two
 * threads at once.
 */
public final class PageRenderer {

    private final PageCanvas canvas = new PageCanvas();

    /** Draws every page on the caller's thread alone. */
    public PageRenderer() {
    }

    /**
     * Draws the scene pages with {@code threads} (see {@link PageCanvas#drawWith}),
     * to the same pictures as one thread; whoever gives them closes them.
     */
    public PageRenderer(DrawingThreads threads) {
        canvas.drawWith(threads);
    }

    /**
     * Draws page n. On a scene error the canvas keeps what was drawn before it
     * and the exception is thrown on.
     */
    public PageCanvas render(int pageNumber, PageContext context) throws SceneException {
        canvas.clear();
        Assignment2.page(pageNumber).draw(canvas, context);
        return canvas;
    }

    /** Page n as a new image (a copy, safe to keep). */
    public BufferedImage renderImage(int pageNumber, PageContext context) throws SceneException {
        return render(pageNumber, context).snapshot();
    }

    public PageCanvas canvas() {
        return canvas;
    }
}
