package simpview.raster;

/**
 * The set-up of one filled triangle, shared by the depth-cued renderer
 * ({@link FilledPolygonRenderer}) and the lit one ({@link LitPolygonRasterizer}):
 * its coverage ({@link TriangleCoverage}), its vertices in counter-clockwise
 * order a, b, c, the edges from a that every attribute {@link Plane} is
 * given over, and the rows to visit. Each row's run and each attribute at a
 * run's first pixel are computed from the triangle alone, never stepped from
 * the row before: so drawing only some rows (one band of a picture) gives
 * those rows exactly the values the whole triangle gives them.
 */
final class TriangleSetup {

    final TriangleCoverage coverage = new TriangleCoverage();
    /** Where the counter-clockwise vertices a, b, c start in the array given to {@link #set}. */
    int a;
    int b;
    int c;
    private double ax;
    private double ay;
    private double e1x;
    private double e1y;
    private double e2x;
    private double e2y;

    /**
     * The triangle whose vertices start at p[i1], p[i2], p[i3], with x at
     * offset {@code x} and y at offset {@code y} in each.
     *
     * @return false when it is degenerate: it covers no pixel
     */
    boolean set(double[] p, int i1, int i2, int i3, int x, int y) {
        TriangleCoverage t = coverage;
        if (!t.set(p[i1 + x], p[i1 + y], p[i2 + x], p[i2 + y], p[i3 + x], p[i3 + y])) {
            return false;
        }
        a = i1;
        b = t.clockwise ? i3 : i2;
        c = t.clockwise ? i2 : i3;
        ax = p[a + x];
        ay = p[a + y];
        e1x = p[b + x] - ax;
        e1y = p[b + y] - ay;
        e2x = p[c + x] - ax;
        e2y = p[c + y] - ay;
        return true;
    }

    /** The attribute at offset {@code at} of each vertex, as a plane over the triangle. */
    void plane(Plane plane, double[] p, int at) {
        plane.set(p[a + at], p[b + at], p[c + at], e1x, e1y, e2x, e2y, coverage.area);
    }

    /** The same, each vertex's value multiplied by {@code scale} first. */
    void plane(Plane plane, double[] p, int at, double scale) {
        plane.set(scale * p[a + at], scale * p[b + at], scale * p[c + at], e1x, e1y, e2x, e2y, coverage.area);
    }

    /** The first row to visit: the triangle's lowest, or {@code from} if higher, within [0, height]. */
    int firstRow(int height, int from) {
        return Math.max(coverage.firstRow(height), from);
    }

    /** The last row to visit: the triangle's highest, or {@code to - 1} if lower. */
    int lastRow(int height, int to) {
        return Math.min(coverage.lastRow(height), to - 1);
    }

    /** The covered run of the row into from() and to(); false when it is empty. */
    boolean row(int row, int width) {
        return coverage.row(row, width);
    }

    /** The first covered pixel of the last row asked for. */
    int from() {
        return coverage.from;
    }

    /** One past its last. */
    int to() {
        return coverage.to;
    }

    /** x of the run's first pixel centre, from vertex a. */
    double dx() {
        return coverage.from + 0.5 - ax;
    }

    /** y of the row's pixel centres, from vertex a. */
    double dy(int row) {
        return row + 0.5 - ay;
    }

    /**
     * Above every z a sink computes at a pixel of this triangle from the
     * planes of q and of z times q (at pixel k of a span,
     * {@code (z0 + k dz) * (1 / (q0 + k dq))}, each value a span's, as
     * {@link Plane#highest} bounds it), so that a pixel whose depth is at
     * least this already is never passed by the triangle; NaN when q is not
     * positive over the triangle's box, as the clipper leaves it. The bound
     * is over the box of the vertices, widened by {@link TriangleCoverage#boxSlack}.
     */
    double highestDepth(Plane q, Plane zq) {
        TriangleCoverage t = coverage;
        double slack = t.boxSlack();
        double cx = (t.minX() + t.maxX()) * 0.5 - ax;
        double cy = (t.minY() + t.maxY()) * 0.5 - ay;
        double hw = (t.maxX() - t.minX()) * 0.5 + slack;
        double hh = (t.maxY() - t.minY()) * 0.5 + slack;
        double qLow = q.lowest(cx, cy, hw, hh);
        if (!(qLow > 0)) {
            return Double.NaN;
        }
        double high = zq.highest(cx, cy, hw, hh);
        // z = zq / q, q positive: largest at the least q if zq may be
        // positive, else at the most q. The division, the reciprocal and the
        // product each round by 2^-53, far inside the margin added.
        double z = high >= 0 ? high / qLow : high / q.highest(cx, cy, hw, hh);
        return z + Math.abs(z) * Plane.MARGIN;
    }

    /** The first column of the widened box of the vertices, within [0, width]. */
    int firstColumn(int width) {
        return coverage.firstColumn(width);
    }

    /** Its last, within [-1, width - 1]. */
    int lastColumn(int width) {
        return coverage.lastColumn(width);
    }
}
