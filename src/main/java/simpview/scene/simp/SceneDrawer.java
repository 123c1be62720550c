package simpview.scene.simp;

import simpview.scene.SceneException;
import java.nio.file.Path;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/** What draws a SIMP file onto a panel; the real one is {@link SceneRenderer}. Tests may stand in. */
@FunctionalInterface
public interface SceneDrawer {

    SceneDrawer SIMP = new SceneDrawer() {
        @Override
        public void draw(Path file, Drawable panel, SceneMonitor monitor) throws SceneException {
            SceneRenderer.draw(file, panel, monitor);
        }

        @Override
        public void draw(Path file, Drawable panel, SceneMonitor monitor, PageCanvas canvas) throws SceneException {
            SceneRenderer.draw(file, panel, monitor, canvas.drawingThreads(), canvas.provenance());
        }
    };

    void draw(Path file, Drawable panel, SceneMonitor monitor) throws SceneException;

    /**
     * Draws a depth-cued scene onto {@code panel}, a chain onto {@code canvas},
     * with the canvas's drawing threads; the default draws on this thread.
     */
    default void draw(Path file, Drawable panel, SceneMonitor monitor, PageCanvas canvas) throws SceneException {
        draw(file, panel, monitor);
    }

    /** Draws a lit scene onto a cleared canvas. */
    default void drawLit(Path file, PageCanvas canvas, SceneMonitor monitor) throws SceneException {
        SceneRenderer.drawLit(file, canvas, monitor);
    }
}
