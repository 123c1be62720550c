package simpview.render;

import simpview.geometry.Vertex;
import simpview.raster.Drawable;

/** Draws a triangle given by three panel-space vertices. */
public interface PolygonRenderer {

    void drawPolygon(Vertex p1, Vertex p2, Vertex p3, Drawable drawable);
}
