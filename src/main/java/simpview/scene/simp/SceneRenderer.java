package simpview.scene.simp;

import java.nio.file.Path;
import simpview.surface.Drawable;

/** Reads a SIMP file and draws it. */
public final class SceneRenderer {

    private SceneRenderer() {
    }

    /**
     * Draws the scene in {@code file} onto {@code panel}, a drawable in panel
     * coordinates (650x650, y up) that already does whatever the page wants
     * done per pixel (scissor, z-buffer, depth cue). Starts from a fresh
     * state: identity CTM, empty stacks, style filled.
     */
    public static void draw(Path file, Drawable panel, SceneMonitor monitor) throws SceneException {
        SimpClient client = new SimpClient(panel);
        client.follow(monitor.trace());
        client.turnWorld(monitor.worldTurn());
        new SimpInterpreter(client, monitor).run(file);
    }
}
