package simpview.simp;

import java.nio.file.Path;
import simpview.raster.Drawable;

/** Reads a SIMP file and draws it. (Placeholder until the interpreter lands.) */
public final class SceneRenderer {

    private SceneRenderer() {
    }

    /**
     * Draws the scene in {@code file} onto {@code panel}, a drawable in panel
     * coordinates (650x650, y up) that already does whatever the page wants
     * done per pixel (scissor, z-buffer, depth cue).
     */
    public static void draw(Path file, Drawable panel, SceneMonitor monitor) throws SceneException {
        throw new SceneException(file, 0, 0, "", "SIMP scenes are not yet available");
    }
}
