package simpview.window;

import java.util.function.Consumer;
import simpview.inspect.InspectedScene;
import simpview.window.render.DrawSettings;
import simpview.window.render.RenderedView;

/**
 * What the inspected pixel and the overlays read of the view on screen: the
 * finished picture, the settings it is drawn with, and the view as the
 * inspector replays it. The window answers; on the EDT.
 */
interface OnScreen {

    /** The finished picture on screen, or null before the first is finished. */
    RenderedView picture();

    /** The settings the view on screen is drawn with (its stepping, turn, depth view, own colours). */
    DrawSettings settings();

    /**
     * Whether the picture on screen shows its vertices' own colours in place of a depth cue: own colours (C) on,
     * and the picture a depth-cued scene's, the one kind of view C changes.
     */
    boolean ownColoursShown();

    /** The view on screen as the inspector replays it, or null (told to {@code why}) when it is not a scene. */
    InspectedScene inspectedScene(Consumer<String> why);
}
