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
 * @param depthView whether the window shows the picture's depths (its depth view) instead of its colours
 */
public record DrawSettings(boolean ownColours, boolean record, int stepLimit, Matrix4 viewTurn, boolean depthView) {

    /** The picture as the pages and the command line draw it. */
    static final DrawSettings PLAIN = new DrawSettings(false, false, -1, null, false);

    /** What the window draws at first: the plain picture, traced. */
    public static final DrawSettings WINDOW = new DrawSettings(false, true, -1, null, false);

    /**
     * Whether the finished picture's depths are copied out for the window:
     * for a traced picture (the inspector reads them under the pointer) and
     * for one the depth view shows. A frame of a drag that turns the view is
     * neither, unless the depth view is on: its copy of the 650 x 650
     * depths, 3.4 MB made and filled on the render thread after every
     * frame, is left out (docs/performance-log.md, session 38), and the frame
     * after the drag is traced again.
     */
    public boolean keepsDepths() {
        return record || depthView;
    }

    public DrawSettings withOwnColours(boolean own) {
        return new DrawSettings(own, record, stepLimit, viewTurn, depthView);
    }

    public DrawSettings withStepLimit(int limit) {
        return new DrawSettings(ownColours, record, limit, viewTurn, depthView);
    }

    public DrawSettings withRecord(boolean traced) {
        return new DrawSettings(ownColours, traced, stepLimit, viewTurn, depthView);
    }

    public DrawSettings withViewTurn(Matrix4 turn) {
        return new DrawSettings(ownColours, record, stepLimit, turn, depthView);
    }

    public DrawSettings withDepthView(boolean shown) {
        return new DrawSettings(ownColours, record, stepLimit, viewTurn, shown);
    }
}
