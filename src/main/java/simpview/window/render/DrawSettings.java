package simpview.window.render;

import simpview.geometry.Matrix4;

/**
 * How the window asks for a picture to be drawn, beyond which one.
 *
 * @param ownColours scenes in their vertices' own colours instead of the depth cue
 * @param record whether to trace the drawing (who drew each pixel, where each primitive came from);
 *     off on the command line, where it would only cost
 * @param stepLimit draw only the first this many primitives of a scene (stepping), or -1 for all
 * @param viewTurn the orbit's turn of the view, in camera space (see SceneMonitor.viewTurn), or null
 */
public record DrawSettings(boolean ownColours, boolean record, int stepLimit, Matrix4 viewTurn) {

    /** The picture as the pages and the command line draw it. */
    static final DrawSettings PLAIN = new DrawSettings(false, false, -1, null);

    /** What the window draws at first: the plain picture, traced. */
    public static final DrawSettings WINDOW = new DrawSettings(false, true, -1, null);

    public DrawSettings withOwnColours(boolean own) {
        return new DrawSettings(own, record, stepLimit, viewTurn);
    }

    public DrawSettings withStepLimit(int limit) {
        return new DrawSettings(ownColours, record, limit, viewTurn);
    }

    public DrawSettings withRecord(boolean traced) {
        return new DrawSettings(ownColours, traced, stepLimit, viewTurn);
    }

    public DrawSettings withViewTurn(Matrix4 turn) {
        return new DrawSettings(ownColours, record, stepLimit, turn);
    }
}
