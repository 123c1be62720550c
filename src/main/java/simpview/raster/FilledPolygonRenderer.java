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
 * that is barycentric interpolation at every pixel centre. A drawable that
 * replaces colour (depth cueing) gets the depth plane only.
 *
 * <p>Work is bounded by the drawable: rows and spans are clipped to it
 * before any pixel is visited. One instance reuses its scratch state and is
 * not for use by two threads at once.
 */
public final class FilledPolygonRenderer implements PolygonRenderer {

    private final Span span = new Span();
    /** Room for a triangle given as vertices, so that both entries share one path. */
    private final double[] corners = new double[3 * Vertex.NUMBERS];
    private final Edge[] edges = {new Edge(), new Edge(), new Edge()};
    // Edges by role: inside to the right (dy < 0), to the left (dy > 0),
    // horizontal (at most one); null where the triangle has none.
    private Edge left0;
    private Edge left1;
    private Edge right0;
    private Edge right1;
    private Edge flat;

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
        double area = (p[i2 + X] - p[i1 + X]) * (p[i3 + Y] - p[i1 + Y])
                - (p[i2 + Y] - p[i1 + Y]) * (p[i3 + X] - p[i1 + X]);
        if (!(area != 0) || !Double.isFinite(area)) {
            return; // degenerate: no pixel centre lies strictly inside
        }
        // Counter-clockwise a, b, c.
        int a = i1;
        int b = area > 0 ? i2 : i3;
        int c = area > 0 ? i3 : i2;
        area = Math.abs(area);
        left0 = left1 = right0 = right1 = flat = null;
        setUpEdge(edges[0], p, a, b);
        setUpEdge(edges[1], p, b, c);
        setUpEdge(edges[2], p, c, a);
        shaded = usesColour(drawable);
        setUpPlanes(p, a, b, c, area);

        int width = drawable.width();
        int height = drawable.height();
        double minY = Math.min(p[a + Y], Math.min(p[b + Y], p[c + Y]));
        double maxY = Math.max(p[a + Y], Math.max(p[b + Y], p[c + Y]));
        int firstRow = (int) Math.max(0, Math.min(height, Math.ceil(minY - 0.5)));
        int lastRow = (int) Math.max(-1, Math.min(height - 1, Math.floor(maxY - 0.5)));
        for (int row = firstRow; row <= lastRow; row++) {
            drawRow(row, width, drawable);
        }
    }

    private boolean usesColour(Drawable drawable) {
        if (drawable != asked) {
            asked = drawable;
            askedUsesColour = drawable.usesColour();
        }
        return askedUsesColour;
    }

    /** The covered run of a row is the intersection of one half-row per edge. */
    private void drawRow(int row, int width, Drawable drawable) {
        double py = row + 0.5;
        if (flat != null && !flat.inside(flat.rowTerm(py), 0.5)) {
            return; // a horizontal edge excludes or admits the whole row
        }
        int from = left0.firstInside(py, width);
        if (left1 != null) {
            from = Math.max(from, left1.firstInside(py, width));
        }
        int to = width;
        if (from < to) {
            to = right0.endOfInside(py, width);
        }
        if (right1 != null && from < to) {
            to = Math.min(to, right1.endOfInside(py, width));
        }
        if (from < to) {
            emitSpan(row, from, to, drawable);
        }
    }

    private void setUpEdge(Edge e, double[] p, int from, int to) {
        e.set(p[from + X], p[from + Y], p[to + X], p[to + Y]);
        if (e.dy < 0) {
            if (left0 == null) {
                left0 = e;
            } else {
                left1 = e;
            }
        } else if (e.dy > 0) {
            if (right0 == null) {
                right0 = e;
            } else {
                right1 = e;
            }
        } else {
            flat = e;
        }
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

    /**
     * One edge of the counter-clockwise triangle, from (ax, ay) to (bx, by):
     * its exact coverage test and a guess of where it crosses a row.
     */
    private static final class Edge {
        // The exact test over the canonical endpoints (x0, y0), (x1, y1), ex = x1 - x0, ey = y1 - y0:
        // f(px, py) = sign * (ex * (py - y0) - ey * (px - x0)); inside iff f > 0, or f == 0 on a top or
        // left edge. sign is +-1 and IEEE rounding is symmetric under negation, so f has the same sign
        // (and zeros) as (sign * ex) * (py - y0) - (sign * ey) * (px - x0): the sign is folded in.
        private double x0;
        private double y0;
        private double signedEx;
        private double signedEy;
        private boolean topLeft;
        // The crossing guess, in the edge's own direction.
        private double fromX;
        private double fromY;
        private double xPerY;
        double dy;

        void set(double ax, double ay, double bx, double by) {
            double dx = bx - ax;
            dy = by - ay;
            fromX = ax;
            fromY = ay;
            xPerY = dx / dy;
            // Canonical order: the lexicographically smaller endpoint first.
            boolean forward = ax < bx || (ax == bx && ay < by);
            x0 = forward ? ax : bx;
            y0 = forward ? ay : by;
            double sign = forward ? 1 : -1;
            signedEx = sign * (forward ? bx - ax : ax - bx);
            signedEy = sign * (forward ? by - ay : ay - by);
            // Counter-clockwise with y up: a left edge runs downward, a top edge runs in -x.
            topLeft = dy < 0 || (dy == 0 && dx < 0);
        }

        /** The part of the edge function that depends only on the row: sign * ex * (py - y0). */
        double rowTerm(double py) {
            return signedEx * (py - y0);
        }

        /** The edge function at (px, py), given rowTerm(py). */
        private double f(double rowTerm, double px) {
            return rowTerm - signedEy * (px - x0);
        }

        /** The exact coverage test at (px, py), given rowTerm(py). */
        boolean inside(double rowTerm, double px) {
            double f = f(rowTerm, px);
            return f > 0 || (f == 0 && topLeft);
        }

        /** inside() for an edge running downward, always a left edge: f == 0 is in. */
        private boolean insideLeft(double rowTerm, double px) {
            return f(rowTerm, px) >= 0;
        }

        /** inside() for an edge running upward, never top or left: f == 0 is out. */
        private boolean insideRight(double rowTerm, double px) {
            return f(rowTerm, px) > 0;
        }

        /** Where the edge crosses the row's centre line, roughly (rounding here only costs steps). */
        private double crossing(double py) {
            return fromX + (py - fromY) * xPerY;
        }

        /**
         * For an edge whose inside is to the right: the first pixel on the row
         * inside it, or width. Along a row the test is monotone in x, so the
         * crossing only gives a first guess; the exact test moves it to the
         * boundary. Pixel indices are kept as (exact) doubles. The common
         * case, the guess already on the boundary, is told by two independent
         * tests and one branch; the loops then would not move.
         */
        int firstInside(double py, int width) {
            double term = rowTerm(py);
            double i = clampIndex(Math.ceil(crossing(py) - 0.5), width);
            if (!insideLeft(term, i - 0.5) & insideLeft(term, i + 0.5)) {
                return (int) i;
            }
            while (i > 0 && insideLeft(term, i - 0.5)) {
                i--;
            }
            while (i < width && !insideLeft(term, i + 0.5)) {
                i++;
            }
            return (int) i;
        }

        /** For an edge whose inside is to the left: one past the last pixel on the row inside it. */
        int endOfInside(double py, int width) {
            double term = rowTerm(py);
            double i = clampIndex(Math.floor(crossing(py) - 0.5) + 1, width);
            if (insideRight(term, i - 0.5) & !insideRight(term, i + 0.5)) {
                return (int) i;
            }
            while (i < width && insideRight(term, i + 0.5)) {
                i++;
            }
            while (i > 0 && !insideRight(term, i - 0.5)) {
                i--;
            }
            return (int) i;
        }

        /** A guess clamped to [0, width]; NaN becomes 0. */
        private static double clampIndex(double estimate, int width) {
            return estimate >= 0 ? Math.min(estimate, width) : 0;
        }
    }

    /** One attribute over the triangle: value = base + slopeX * dx + slopeY * dy, d relative to vertex a. */
    private static final class Plane {
        private double base;
        double slopeX;
        private double slopeY;

        void set(double va, double vb, double vc, double e1x, double e1y, double e2x, double e2y, double area) {
            double d1 = vb - va;
            double d2 = vc - va;
            base = va;
            slopeX = (d1 * e2y - d2 * e1y) / area;
            slopeY = (d2 * e1x - d1 * e2x) / area;
        }

        double valueAt(double dx, double dy) {
            return base + slopeX * dx + slopeY * dy;
        }
    }
}
