package simpview.render;

import simpview.geometry.Vertex;
import simpview.raster.Drawable;

/** A polygon renderer that draws only the three edges, with the line renderer it is given. */
public final class WireframePolygonRenderer implements PolygonRenderer {

    private final LineRenderer lines;

    public WireframePolygonRenderer(LineRenderer lines) {
        this.lines = lines;
    }

    @Override
    public void drawPolygon(Vertex p1, Vertex p2, Vertex p3, Drawable drawable) {
        lines.drawLine(p1, p2, drawable);
        lines.drawLine(p2, p3, drawable);
        lines.drawLine(p3, p1, drawable);
    }
}
