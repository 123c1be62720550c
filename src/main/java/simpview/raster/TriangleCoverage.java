package simpview.raster;

/**
 * Which pixels of each row a triangle covers, for every filled renderer.
 *
 * <p>Pixel (i, j) is covered iff its centre (i + 0.5, j + 0.5) is inside the
 * triangle, a centre exactly on an edge only for a top or left edge. The test
 * is the sign of each edge function, evaluated with the edge's endpoints in a
 * canonical order: two triangles sharing an edge compute bit-identical values
 * there and differ only in sign, and the top-left rule gives the tie to
 * exactly one of them. Along a row each edge function is monotone in x even
 * in floating point (every operation in it rounds monotonically), so the
 * covered pixels form one run whose ends are found from the edge crossings
 * and then settled by that same exact test.
 *
 * <p>Work is bounded by the surface: rows and runs are clipped to [0, width)
 * x [0, height) before any pixel is visited. One instance reuses its state.
 */
final class TriangleCoverage {

    private final Edge[] edges = {new Edge(), new Edge(), new Edge()};
    // Edges by role: inside to the right (dy < 0), to the left (dy > 0),
    // horizontal (at most one); null where the triangle has none.
    private Edge left0;
    private Edge left1;
    private Edge right0;
    private Edge right1;
    private Edge flat;
    private double minX;
    private double maxX;
    private double minY;
    private double maxY;
    /**
     * How much the box of the vertices is widened on every side: more than a
     * pixel centre can lie outside the triangle and still be covered, its
     * edge tests rounded (about 2^-51 of its distance from the edge's first
     * endpoint): 2^-30 of the coordinates' sizes, and 2^-30 of a pixel. Made
     * once in {@link #set}: both column ends and a lit triangle's depth bound use it.
     */
    private double boxSlack;
    /** Twice the triangle's area, positive. */
    double area;
    /** True when the vertices were given clockwise: the counter-clockwise order is 1, 3, 2. */
    boolean clockwise;
    /** The covered run of the last row asked for: {@code from <= x < to}. */
    int from;
    int to;

    /**
     * Sets up the triangle (x1, y1), (x2, y2), (x3, y3), in either orientation.
     *
     * @return false when it is degenerate (zero or non-finite area): no pixel centre lies strictly inside
     */
    boolean set(double x1, double y1, double x2, double y2, double x3, double y3) {
        double a = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1);
        if (!(a != 0) || !Double.isFinite(a)) {
            return false;
        }
        clockwise = a < 0;
        area = Math.abs(a);
        double bx = clockwise ? x3 : x2;
        double by = clockwise ? y3 : y2;
        double cx = clockwise ? x2 : x3;
        double cy = clockwise ? y2 : y3;
        left0 = left1 = right0 = right1 = flat = null;
        setUpEdge(edges[0], x1, y1, bx, by);
        setUpEdge(edges[1], bx, by, cx, cy);
        setUpEdge(edges[2], cx, cy, x1, y1);
        // A finite area means finite vertices (an infinite or NaN one makes
        // it infinite or NaN), so these orders need compares only, not
        // Math.min and max, whose NaN and signed-zero rules cost more and
        // would change nothing here: a zero's sign is lost to the rows' casts.
        minX = lower(x1, lower(x2, x3));
        maxX = higher(x1, higher(x2, x3));
        minY = lower(y1, lower(y2, y3));
        maxY = higher(y1, higher(y2, y3));
        boxSlack = 0x1p-30 * (1 + Math.abs(minX) + Math.abs(maxX) + Math.abs(minY) + Math.abs(maxY));
        return true;
    }

    private static double lower(double a, double b) {
        return a < b ? a : b;
    }

    private static double higher(double a, double b) {
        return a > b ? a : b;
    }

    /** The lowest row whose centre line the triangle may reach, within [0, height]. */
    int firstRow(int height) {
        double row = Math.ceil(minY - 0.5);
        return row <= 0 ? 0 : row < height ? (int) row : height;
    }

    /** How much the box of the vertices is widened on every side ({@link #boxSlack}). */
    double boxSlack() {
        return boxSlack;
    }

    /** The first column of the widened box of the vertices, within [0, width]. */
    int firstColumn(int width) {
        double column = Math.ceil(minX - 0.5 - boxSlack);
        return column <= 0 ? 0 : column < width ? (int) column : width;
    }

    /** Its last, within [-1, width - 1]. */
    int lastColumn(int width) {
        double column = Math.floor(maxX - 0.5 + boxSlack);
        return column <= -1 ? -1 : column < width - 1 ? (int) column : width - 1;
    }

    double minX() {
        return minX;
    }

    double maxX() {
        return maxX;
    }

    double minY() {
        return minY;
    }

    double maxY() {
        return maxY;
    }

    /** The highest such row, within [-1, height - 1]. */
    int lastRow(int height) {
        double row = Math.floor(maxY - 0.5);
        return row <= -1 ? -1 : row < height - 1 ? (int) row : height - 1;
    }

    /**
     * The covered run of a row, the intersection of one half-row per edge,
     * into from and to; false when empty.
     *
     * <p>Of two edges on one side, one binds on a row and the other's
     * half-row holds the run: so the first edge's end is found, and the
     * second is asked only whether it holds that end pixel (one exact test;
     * its half-row is an interval that reaches the panel's edge, so it then
     * holds the run). Only where not is its own end found, and it is asked
     * first from then on: a triangle's rows come in order, and past the
     * corner between them the other edge binds. A2's page 7 (590 triangles,
     * 59,422 rows): 0.95-0.97 of its time (session 23).
     */
    boolean row(int row, int width) {
        double py = row + 0.5;
        if (flat != null && !flat.inside(flat.rowTerm(py), 0.5)) {
            return false; // a horizontal edge excludes or admits the whole row
        }
        int start = left0.firstInside(py, width);
        if (left1 != null && start < width && !left1.insideLeft(left1.rowTerm(py), start + 0.5)) {
            start = left1.firstInside(py, width);
            Edge binding = left1;
            left1 = left0;
            left0 = binding;
        }
        int end = width;
        if (start < end) {
            end = right0.endOfInside(py, width);
        }
        if (right1 != null && start < end && !right1.insideRight(right1.rowTerm(py), end - 0.5)) {
            end = right1.endOfInside(py, width);
            Edge binding = right1;
            right1 = right0;
            right0 = binding;
        }
        from = start;
        to = end;
        return start < end;
    }

    /**
     * Where the point (px, py) lies against the edge from given vertex k to
     * vertex k + 1 (mod 3) of the triangle last {@link #set}, by the same
     * exact test the rows use: {@link CentreTest#INSIDE} or
     * {@link CentreTest#OUTSIDE}, or on it, where the top-left rule decides.
     */
    int side(int k, double px, double py) {
        // set() keeps the edges counter-clockwise: 1->2, 2->3, 3->1 as given, or, when clockwise, 1->3, 3->2, 2->1.
        Edge e = clockwise ? edges[2 - k] : edges[k];
        double f = e.f(e.rowTerm(py), px);
        if (f > 0) {
            return CentreTest.INSIDE;
        }
        if (f < 0) {
            return CentreTest.OUTSIDE;
        }
        return e.topLeft ? CentreTest.ON_TOP_OR_LEFT : CentreTest.ON_RIGHT_OR_BOTTOM;
    }

    private void setUpEdge(Edge e, double ax, double ay, double bx, double by) {
        e.set(ax, ay, bx, by);
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

        /**
         * A guess clamped to [0, width]; NaN becomes 0. Compares, not
         * Math.min: no NaN is left to order, and this runs for every edge of
         * every row.
         */
        private static double clampIndex(double estimate, int width) {
            return estimate >= 0 ? (estimate < width ? estimate : width) : 0;
        }
    }

}
