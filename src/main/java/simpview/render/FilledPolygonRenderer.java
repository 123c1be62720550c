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
    // The exact test over the canonical endpoints (x0, y0), (x1, y1), ex = x1 - x0, ey = y1 - y0:
    // f(px, py) = sign * (ex * (py - y0) - ey * (px - x0)); inside iff f > 0, or f == 0 on a top or left edge.
    private final double[] edgeSign = new double[3];
    private final boolean[] edgeTopLeft = new boolean[3];
    private final double[] crossX0 = new double[3];
    private final double[] crossY0 = new double[3];
    private final double[] crossEx = new double[3];
    private final double[] crossEy = new double[3];
    // Edges by role: inside to the right (dy < 0), to the left (dy > 0), horizontal (at most one).
    private final int[] leftEdges = new int[2];
    private final int[] rightEdges = new int[2];
    private int leftCount;
    private int rightCount;
    private int flatEdge;

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
        leftCount = 0;
        rightCount = 0;
        flatEdge = -1;
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

    /** The covered run of a row is the intersection of one half-row per edge. */
    private void drawRow(int row, int width, Drawable drawable) {
        double py = row + 0.5;
        if (flatEdge >= 0 && !inside(flatEdge, rowTerm(flatEdge, py), 0.5)) {
            return; // a horizontal edge excludes or admits the whole row
        }
        int from = 0;
        for (int k = 0; k < leftCount; k++) {
            from = Math.max(from, firstInside(leftEdges[k], py, width));
        }
        int to = width;
        for (int k = 0; k < rightCount && from < to; k++) {
            to = Math.min(to, endOfInside(rightEdges[k], py, width));
        }
        if (from < to) {
            emitSpan(row, from, to, drawable);
        }
    }

    /**
     * For an edge whose inside is to the right: the first pixel on the row
     * inside it, or width. Along a row the test is monotone in x, so the
     * crossing only gives a first guess; the exact test moves it to the
     * boundary. Pixel indices are kept as (exact) doubles.
     */
    private int firstInside(int e, double py, int width) {
        double term = rowTerm(e, py);
        double i = clampIndex(Math.ceil(crossing(e, py) - 0.5), width);
        while (i > 0 && inside(e, term, i - 0.5)) {
            i--;
        }
        while (i < width && !inside(e, term, i + 0.5)) {
            i++;
        }
        return (int) i;
    }

    /** For an edge whose inside is to the left: one past the last pixel on the row inside it. */
    private int endOfInside(int e, double py, int width) {
        double term = rowTerm(e, py);
        double i = clampIndex(Math.floor(crossing(e, py) - 0.5) + 1, width);
        while (i < width && inside(e, term, i + 0.5)) {
            i++;
        }
        while (i > 0 && !inside(e, term, i - 0.5)) {
            i--;
        }
        return (int) i;
    }

    /** Where the edge crosses the row's centre line, roughly (rounding here only costs steps). */
    private double crossing(int e, double py) {
        return edgePx[e] + (py - edgePy[e]) * edgeXPerY[e];
    }

    /** A guess clamped to [0, width]; NaN becomes 0. */
    private static double clampIndex(double estimate, int width) {
        return estimate >= 0 ? Math.min(estimate, width) : 0;
    }

    /** The part of the edge function that depends only on the row: ex * (py - y0). */
    private double rowTerm(int e, double py) {
        return crossEx[e] * (py - crossY0[e]);
    }

    /** The exact coverage test of one edge at (px, py), given rowTerm(e, py). */
    private boolean inside(int e, double rowTerm, double px) {
        double f = edgeSign[e] * (rowTerm - crossEy[e] * (px - crossX0[e]));
        return f > 0 || (f == 0 && edgeTopLeft[e]);
    }

    private void setUpEdge(int e, Vertex from, Vertex to) {
        edgePx[e] = from.x();
        edgePy[e] = from.y();
        edgeDx[e] = to.x() - from.x();
        edgeDy[e] = to.y() - from.y();
        edgeXPerY[e] = edgeDx[e] / edgeDy[e];
        // Canonical order: the lexicographically smaller endpoint first.
        boolean forward = from.x() < to.x() || (from.x() == to.x() && from.y() < to.y());
        Vertex first = forward ? from : to;
        Vertex second = forward ? to : from;
        crossX0[e] = first.x();
        crossY0[e] = first.y();
        crossEx[e] = second.x() - first.x();
        crossEy[e] = second.y() - first.y();
        edgeSign[e] = forward ? 1 : -1;
        // Counter-clockwise with y up: a left edge runs downward, a top edge runs in -x.
        edgeTopLeft[e] = edgeDy[e] < 0 || (edgeDy[e] == 0 && edgeDx[e] < 0);
        if (edgeDy[e] < 0) {
            leftEdges[leftCount++] = e;
        } else if (edgeDy[e] > 0) {
            rightEdges[rightCount++] = e;
        } else {
            flatEdge = e;
        }
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
