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
 * one {@link Plane} per attribute; both set up by {@link TriangleSetup}.
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
    private final TriangleSetup triangle = new TriangleSetup();
    private final Plane red = new Plane();
    private final Plane green = new Plane();
    private final Plane blue = new Plane();
    private final Plane depth = new Plane();
    /** False when the drawable replaces colour: then no colour plane is set up or evaluated. */
    private boolean shaded;
    // The last drawable asked: a drawable's answer never changes.
    private Drawable asked;
    private boolean askedUsesColour;
    // The rows drawn: all of them, or one band's.
    private int rowFrom;
    private int rowTo = Integer.MAX_VALUE;

    /** From now on draws only the rows {@code from <= y < to} of each triangle (one band of a picture). */
    public void rows(int from, int to) {
        rowFrom = from;
        rowTo = to;
    }

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
        TriangleSetup t = triangle;
        if (!t.set(p, i1, i2, i3, X, Y)) {
            return;
        }
        shaded = usesColour(drawable);
        t.plane(depth, p, Z);
        if (shaded) {
            t.plane(red, p, R, 255);
            t.plane(green, p, G, 255);
            t.plane(blue, p, B, 255);
        }
        int width = drawable.width();
        int height = drawable.height();
        int lastRow = t.lastRow(height, rowTo);
        for (int row = t.firstRow(height, rowFrom); row <= lastRow; row++) {
            if (t.row(row, width)) {
                emitSpan(row, drawable);
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

    private void emitSpan(int row, Drawable drawable) {
        TriangleSetup t = triangle;
        Span s = span;
        double dx = t.dx();
        double dy = t.dy(row);
        s.y = row;
        s.x0 = t.from();
        s.x1 = t.to();
        s.xBase = t.from();
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
