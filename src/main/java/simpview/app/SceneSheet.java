package simpview.app;

import java.nio.file.Path;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.scene.simp.SceneException;
import simpview.scene.simp.SceneMonitor;

/**
 * Any scene file shown as a whole page, like pages 4 to 8: cleared canvas,
 * z-buffer, depth cue from {@code near} at z = 0 to {@code far} at z = -200.
 */
record SceneSheet(Path file, Rgb near, Rgb far) {

    static SceneSheet of(Path file) {
        return new SceneSheet(file, Rgb.WHITE, Rgb.BLACK);
    }

    /** Clears the canvas and draws the scene; on an error what was drawn stays. */
    void drawOn(PageCanvas canvas, SceneMonitor monitor, SceneDrawer drawer) throws SceneException {
        drawOn(canvas, monitor, drawer, false);
    }

    /**
     * The same, or with {@code ownColours} the vertices' own colours (white
     * where a vertex has none) through the z-buffer, without the depth cue.
     */
    void drawOn(PageCanvas canvas, SceneMonitor monitor, SceneDrawer drawer, boolean ownColours) throws SceneException {
        canvas.clear();
        drawer.draw(file, ownColours ? canvas.depthTested() : canvas.depthCued(near, far), monitor);
    }
}
