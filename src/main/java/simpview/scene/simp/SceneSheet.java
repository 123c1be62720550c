package simpview.scene.simp;

import simpview.scene.SceneException;
import java.nio.file.Path;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * Any scene file shown as a whole page, like pages 4 to 8. A depth-cued scene
 * is cued from {@code near} at z = 0 to {@code far} at z = -200; a lit scene
 * (SPEC Part 2, decided by {@link SceneRules}) is drawn by its own camera,
 * lights and fog.
 */
public record SceneSheet(Path file, Rgb near, Rgb far) {

    public static SceneSheet of(Path file) {
        return new SceneSheet(file, Rgb.WHITE, Rgb.BLACK);
    }

    /**
     * Why depth-cue colours cannot be given for this scene, or null when they
     * can: a lit scene has no depth cue, and the problem names the command
     * that made it lit.
     */
    public static String cueColoursProblem(Path scene, Rgb near, Rgb far) {
        if (near == null && far == null) {
            return null;
        }
        SceneRules rules = SceneRules.of(scene);
        return rules.lit() ? "--near-color and --far-color are for depth-cued scenes, and " + scene.getFileName()
                + " is lit (" + rules.reason() + ")" : null;
    }

    /** Clears the canvas and draws the scene; on an error what was drawn stays. */
    public void drawOn(PageCanvas canvas, SceneMonitor monitor, SceneDrawer drawer) throws SceneException {
        drawOn(canvas, monitor, drawer, false);
    }

    /**
     * The same, or with {@code ownColours} the vertices' own colours (white
     * where a vertex has none) through the z-buffer, without the depth cue.
     */
    public void drawOn(PageCanvas canvas, SceneMonitor monitor, SceneDrawer drawer, boolean ownColours) throws SceneException {
        canvas.clear();
        if (SceneRules.of(file).lit()) {
            drawer.drawLit(file, canvas, monitor);
        } else {
            drawer.draw(file, ownColours ? canvas.depthTested() : canvas.depthCued(near, far), monitor);
        }
    }
}
