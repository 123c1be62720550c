package simpview.raster;

import static simpview.geometry.Vertex.B;
import static simpview.geometry.Vertex.G;
import static simpview.geometry.Vertex.R;
import static simpview.geometry.Vertex.X;
import static simpview.geometry.Vertex.Y;
import static simpview.geometry.Vertex.Z;

import simpview.geometry.Vertex;
import simpview.surface.Drawable;
import simpview.surface.Span;

/**
 * The filled triangle, one span per pixel row: which pixels, by
 * {@link TriangleCoverage} (centres, the top-left rule); what they carry, by
 * one {@link Plane} per attribute.
 *
 * <p>Attributes. Colour (in byte levels) and z are planes over the triangle,
 * evaluated at the first pixel centre of each span with their x slopes;
 * that is barycentric interpolation at every pixel centre. A drawable that
 * replaces colour (depth cueing) gets the depth plane only.
 *
 * <p>One instance reuses its scratch state and is not for use by two threads at once.
 */
public final class FilledPolygonRenderer implements PolygonRenderer {

    private final Span span = new Span();
    /** Room for a triangle given as vertices, so that both entries share one path. */
    private final double[] corners = new double[3 * Vertex.NUMBERS];
    private final TriangleCoverage coverage = new TriangleCoverage();
    private final Plane red = new Plane();
    private final Plane green = new Plane();
    private final Plane blue = new Plane();
    private final Plane depth = new Plane();
    // Every plane is given relative to vertex a: (originX, originY).
    private double originX;
    private double originY;
    /** False when the drawable replaces colour: then no colour plane is set up or evaluated. */
    private boolean shaded;
    // The last drawable asked: a drawable's answer never changes.
    private Drawable asked;
    private boolean askedUsesColour;

    @Override
    public void drawPolygon(Vertex p1, Vertex p2, Vertex p3, Drawable drawable) {
        p1.writeTo(corners, 0);
        p2.writeTo(corners, Vertex.NUMBERS);
        p3.writeTo(corners, 2 * Vertex.NUMBERS);
        drawPolygon(corners, 0, drawable);
    }

    @Override
    public void drawPolygon(double[] p, int at, Drawable drawable) {
        int i1 = at;
        int i2 = at + Vertex.NUMBERS;
        int i3 = at + 2 * Vertex.NUMBERS;
        if (!Vertex.isFinite(p, i1) || !Vertex.isFinite(p, i2) || !Vertex.isFinite(p, i3)) {
            return;
        }
        TriangleCoverage t = coverage;
        if (!t.set(p[i1 + X], p[i1 + Y], p[i2 + X], p[i2 + Y], p[i3 + X], p[i3 + Y])) {
            return;
        }
        // Counter-clockwise a, b, c.
        int a = i1;
        int b = t.clockwise ? i3 : i2;
        int c = t.clockwise ? i2 : i3;
        shaded = usesColour(drawable);
        setUpPlanes(p, a, b, c, t.area);
        int width = drawable.width();
        int height = drawable.height();
        int lastRow = t.lastRow(height);
        for (int row = t.firstRow(height); row <= lastRow; row++) {
            if (t.row(row, width)) {
                emitSpan(row, t.from, t.to, drawable);
            }
        }
    }

    private boolean usesColour(Drawable drawable) {
        if (drawable != asked) {
            asked = drawable;
            askedUsesColour = drawable.usesColour();
        }
        return askedUsesColour;
    }

    private void setUpPlanes(double[] p, int a, int b, int c, double area) {
        originX = p[a + X];
        originY = p[a + Y];
        double e1x = p[b + X] - p[a + X];
        double e1y = p[b + Y] - p[a + Y];
        double e2x = p[c + X] - p[a + X];
        double e2y = p[c + Y] - p[a + Y];
        depth.set(p[a + Z], p[b + Z], p[c + Z], e1x, e1y, e2x, e2y, area);
        if (shaded) {
            red.set(255 * p[a + R], 255 * p[b + R], 255 * p[c + R], e1x, e1y, e2x, e2y, area);
            green.set(255 * p[a + G], 255 * p[b + G], 255 * p[c + G], e1x, e1y, e2x, e2y, area);
            blue.set(255 * p[a + B], 255 * p[b + B], 255 * p[c + B], e1x, e1y, e2x, e2y, area);
        }
    }

    private void emitSpan(int row, int from, int to, Drawable drawable) {
        Span s = span;
        double dx = from + 0.5 - originX;
        double dy = row + 0.5 - originY;
        s.y = row;
        s.x0 = from;
        s.x1 = to;
        s.xBase = from;
        s.z = depth.valueAt(dx, dy);
        s.dz = depth.slopeX;
        if (shaded) {
            s.r = red.valueAt(dx, dy);
            s.dr = red.slopeX;
            s.g = green.valueAt(dx, dy);
            s.dg = green.slopeX;
            s.b = blue.valueAt(dx, dy);
            s.db = blue.slopeX;
        } else {
            s.r = s.dr = s.g = s.dg = s.b = s.db = 0;
        }
        drawable.fillSpan(s);
    }
}
