package simpview.scene.simp;

import simpview.scene.SceneException;
import java.nio.file.Path;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/** What draws a SIMP file onto a panel; the real one is {@link SceneRenderer}. Tests may stand in. */
@FunctionalInterface
public interface SceneDrawer {

    SceneDrawer SIMP = SceneRenderer::draw;

    void draw(Path file, Drawable panel, SceneMonitor monitor) throws SceneException;

    /** Draws a lit scene onto a cleared canvas. */
    default void drawLit(Path file, PageCanvas canvas, SceneMonitor monitor) throws SceneException {
        SceneRenderer.drawLit(file, canvas, monitor);
    }
}
