package simpview.raster;

import simpview.geometry.Vertex;
import simpview.surface.Drawable;

/** Draws a line between two panel-space vertices, lerping colour and depth. */
public interface LineRenderer {

    void drawLine(Vertex p1, Vertex p2, Drawable drawable);

    /**
     * The same line given as plain numbers: its ends are the vertices at p[from]
     * and p[to], {@link Vertex#NUMBERS} numbers each. The project's renderers
     * draw this way without allocating; the default makes vertices.
     */
    default void drawLine(double[] p, int from, int to, Drawable drawable) {
        drawLine(Vertex.readFrom(p, from), Vertex.readFrom(p, to), drawable);
    }
}
