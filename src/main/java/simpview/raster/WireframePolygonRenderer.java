package simpview.raster;

import simpview.geometry.Vertex;
import simpview.surface.Drawable;

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

    @Override
    public void drawPolygon(double[] p, int at, Drawable drawable) {
        int second = at + Vertex.NUMBERS;
        int third = at + 2 * Vertex.NUMBERS;
        lines.drawLine(p, at, second, drawable);
        lines.drawLine(p, second, third, drawable);
        lines.drawLine(p, third, at, drawable);
    }
}
