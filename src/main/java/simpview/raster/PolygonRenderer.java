package simpview.raster;

import simpview.geometry.Vertex;
import simpview.surface.Drawable;

/** Draws a triangle given by three panel-space vertices. */
public interface PolygonRenderer {

    void drawPolygon(Vertex p1, Vertex p2, Vertex p3, Drawable drawable);

    /**
     * The same triangle given as plain numbers: its three vertices follow one
     * another from p[at], {@link Vertex#NUMBERS} numbers each. The project's
     * renderers draw this way without allocating; the default makes vertices.
     */
    default void drawPolygon(double[] p, int at, Drawable drawable) {
        drawPolygon(Vertex.readFrom(p, at), Vertex.readFrom(p, at + Vertex.NUMBERS),
                Vertex.readFrom(p, at + 2 * Vertex.NUMBERS), drawable);
    }
}
