package simpview.render;

import simpview.geometry.Vertex;
import simpview.raster.Drawable;
import simpview.raster.Span;

/**
 * The filled triangle, one span per pixel row.
 *
 * <p>Coverage. Pixel (i, j) is drawn iff its centre (i + 0.5, j + 0.5) is
 * inside the triangle, a centre exactly on an edge only for a top or left
 * edge. The test is the sign of each edge function, evaluated with the edge's
 * endpoints in a canonical order: two triangles sharing an edge compute
 * bit-identical values there and differ only in sign, and the top-left rule
 * gives the tie to exactly one of them. Along a row each edge function is
 * monotone in x even in floating point (every operation in it rounds
 * monotonically), so the covered pixels form one run whose ends are found
 * from the edge crossings and then settled by that same exact test.
 *
 * <p>Attributes. Colour (in byte levels) and z are planes over the triangle,
 * evaluated at the first pixel centre of each span with their x slopes;
 * that is barycentric interpolation at every pixel centre.
 *
 * <p>Work is bounded by the drawable: rows and spans are clipped to it
 * before any pixel is visited. One instance reuses its scratch state and is
 * not for use by two threads at once.
 */
public final class FilledPolygonRenderer implements PolygonRenderer {

    private static final int RED = 0;
    private static final int GREEN = 1;
    private static final int BLUE = 2;
    private static final int DEPTH = 3;
    private static final int ATTRIBUTES = 4;

    private final Span span = new Span();

    // Edge e runs from vertex e to vertex (e + 1) % 3 of the counter-clockwise triangle.
    private final double[] edgePx = new double[3];
    private final double[] edgePy = new double[3];
    private final double[] edgeDx = new double[3];
    private final double[] edgeDy = new double[3];
    private final double[] edgeXPerY = new double[3];
    private final double[] edgeSign = new double[3];
    private final boolean[] edgeTopLeft = new boolean[3];
    private final double[] crossX0 = new double[3];
    private final double[] crossX1 = new double[3];
    private final double[] crossY0 = new double[3];
    private final double[] crossY1 = new double[3];
    // The edge function on the current row: f(px) = edgeSign * (rowTerm - crossEy * (px - crossX0)).
    private final double[] crossEx = new double[3];
    private final double[] crossEy = new double[3];
    private final double[] rowTerm = new double[3];

    // Attribute planes: value(px, py) = base + slopeX * (px - originX) + slopeY * (py - originY).
    private final double[] base = new double[ATTRIBUTES];
    private final double[] slopeX = new double[ATTRIBUTES];
    private final double[] slopeY = new double[ATTRIBUTES];
    private double originX;
    private double originY;

    @Override
    public void drawPolygon(Vertex p1, Vertex p2, Vertex p3, Drawable drawable) {
        if (!p1.isFinite() || !p2.isFinite() || !p3.isFinite()) {
            return;
        }
        double area = (p2.x() - p1.x()) * (p3.y() - p1.y()) - (p2.y() - p1.y()) * (p3.x() - p1.x());
        if (!(area != 0) || !Double.isFinite(area)) {
            return; // degenerate: no pixel centre lies strictly inside
        }
        Vertex a = p1;
        Vertex b = area > 0 ? p2 : p3;
        Vertex c = area > 0 ? p3 : p2;
        area = Math.abs(area);
        setUpEdge(0, a, b);
        setUpEdge(1, b, c);
        setUpEdge(2, c, a);
        setUpPlanes(a, b, c, area);

        int width = drawable.width();
        int height = drawable.height();
        double minY = Math.min(a.y(), Math.min(b.y(), c.y()));
        double maxY = Math.max(a.y(), Math.max(b.y(), c.y()));
        int firstRow = (int) Math.max(0, Math.min(height, Math.ceil(minY - 0.5)));
        int lastRow = (int) Math.max(-1, Math.min(height - 1, Math.floor(maxY - 0.5)));
        for (int row = firstRow; row <= lastRow; row++) {
            drawRow(row, width, drawable);
        }
    }

    private void drawRow(int row, int width, Drawable drawable) {
        double py = row + 0.5;
        for (int e = 0; e < 3; e++) {
            rowTerm[e] = crossEx[e] * (py - crossY0[e]);
        }
        int from = 0;
        int to = width;
        for (int e = 0; e < 3 && from < to; e++) {
            double dy = edgeDy[e];
            if (dy == 0) {
                if (!inside(e, 0.5)) {
                    return; // a horizontal edge excludes or admits the whole row
                }
            } else {
                // Only an estimate: the exact test settles the run's ends.
                double crossing = edgePx[e] + (py - edgePy[e]) * edgeXPerY[e];
                if (dy < 0) {
                    from = Math.max(from, firstInside(e, crossing, width));
                } else {
                    to = Math.min(to, endOfInside(e, crossing, width));
                }
            }
        }
        if (from < to) {
            emitSpan(row, from, to, drawable);
        }
    }

    /** For an edge whose inside is to the right: the first pixel on the row inside it, or width. */
    private int firstInside(int e, double crossing, int width) {
        int i = clampIndex(Math.ceil(crossing - 0.5), width);
        while (i > 0 && inside(e, i - 0.5)) {
            i--;
        }
        while (i < width && !inside(e, i + 0.5)) {
            i++;
        }
        return i;
    }

    /** For an edge whose inside is to the left: one past the last pixel on the row inside it. */
    private int endOfInside(int e, double crossing, int width) {
        int i = clampIndex(Math.floor(crossing - 0.5) + 1, width);
        while (i < width && inside(e, i + 0.5)) {
            i++;
        }
        while (i > 0 && !inside(e, i - 0.5)) {
            i--;
        }
        return i;
    }

    private static int clampIndex(double estimate, int width) {
        return (int) Math.max(0, Math.min(width, estimate));
    }

    /**
     * The exact coverage test of one edge at sample (px, row centre):
     * {@code sign * ((x1 - x0) * (py - y0) - (y1 - y0) * (px - x0))} over the
     * canonical endpoints, its first product taken from {@link #rowTerm}.
     */
    private boolean inside(int e, double px) {
        double f = edgeSign[e] * (rowTerm[e] - crossEy[e] * (px - crossX0[e]));
        return f > 0 || (f == 0 && edgeTopLeft[e]);
    }

    private void setUpEdge(int e, Vertex from, Vertex to) {
        edgePx[e] = from.x();
        edgePy[e] = from.y();
        edgeDx[e] = to.x() - from.x();
        edgeDy[e] = to.y() - from.y();
        // Canonical order: the lexicographically smaller endpoint first.
        boolean forward = from.x() < to.x() || (from.x() == to.x() && from.y() < to.y());
        Vertex first = forward ? from : to;
        Vertex second = forward ? to : from;
        crossX0[e] = first.x();
        crossY0[e] = first.y();
        crossX1[e] = second.x();
        crossY1[e] = second.y();
        crossEx[e] = second.x() - first.x();
        crossEy[e] = second.y() - first.y();
        edgeXPerY[e] = edgeDx[e] / edgeDy[e];
        edgeSign[e] = forward ? 1 : -1;
        // Counter-clockwise with y up: a left edge runs downward, a top edge runs in -x.
        edgeTopLeft[e] = edgeDy[e] < 0 || (edgeDy[e] == 0 && edgeDx[e] < 0);
    }

    private void setUpPlanes(Vertex a, Vertex b, Vertex c, double area) {
        originX = a.x();
        originY = a.y();
        double e1x = b.x() - a.x();
        double e1y = b.y() - a.y();
        double e2x = c.x() - a.x();
        double e2y = c.y() - a.y();
        plane(RED, 255 * a.r(), 255 * b.r(), 255 * c.r(), e1x, e1y, e2x, e2y, area);
        plane(GREEN, 255 * a.g(), 255 * b.g(), 255 * c.g(), e1x, e1y, e2x, e2y, area);
        plane(BLUE, 255 * a.b(), 255 * b.b(), 255 * c.b(), e1x, e1y, e2x, e2y, area);
        plane(DEPTH, a.z(), b.z(), c.z(), e1x, e1y, e2x, e2y, area);
    }

    private void plane(int attr, double va, double vb, double vc,
                       double e1x, double e1y, double e2x, double e2y, double area) {
        double d1 = vb - va;
        double d2 = vc - va;
        base[attr] = va;
        slopeX[attr] = (d1 * e2y - d2 * e1y) / area;
        slopeY[attr] = (d2 * e1x - d1 * e2x) / area;
    }

    private double valueAt(int attr, double px, double py) {
        return base[attr] + slopeX[attr] * (px - originX) + slopeY[attr] * (py - originY);
    }

    private void emitSpan(int row, int from, int to, Drawable drawable) {
        Span s = span;
        double px = from + 0.5;
        double py = row + 0.5;
        s.y = row;
        s.x0 = from;
        s.x1 = to;
        s.xBase = from;
        s.r = valueAt(RED, px, py);
        s.dr = slopeX[RED];
        s.g = valueAt(GREEN, px, py);
        s.dg = slopeX[GREEN];
        s.b = valueAt(BLUE, px, py);
        s.db = slopeX[BLUE];
        s.z = valueAt(DEPTH, px, py);
        s.dz = slopeX[DEPTH];
        drawable.fillSpan(s);
    }
}
