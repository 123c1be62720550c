package simpview.render;

import simpview.geometry.Vertex;
import simpview.raster.Drawable;

/** Draws a line between two panel-space vertices, lerping colour and depth. */
public interface LineRenderer {

    void drawLine(Vertex p1, Vertex p2, Drawable drawable);
}
