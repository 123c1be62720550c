package simpview.inspect;

/**
 * A line between two panel points as SPEC's DDA rule walks it, for the
 * inspector's questions about one pixel: both ends rounded half up, an
 * x-major line (|dx| &gt;= |dy|) walked from the end with the smaller x, a
 * y-major one from the end with the smaller y, the minor coordinate starting
 * at the start pixel's and adding the slope once a step. {@code reversed}:
 * the walk starts at the second point given.
 */
record DdaSteps(boolean xMajor, boolean reversed, long startX, long startY, long endX, long endY) {

    static DdaSteps of(double x0, double y0, double x1, double y1) {
        long ax = (long) Math.floor(x0 + 0.5);
        long ay = (long) Math.floor(y0 + 0.5);
        long bx = (long) Math.floor(x1 + 0.5);
        long by = (long) Math.floor(y1 + 0.5);
        boolean xMajor = Math.abs(bx - ax) >= Math.abs(by - ay);
        boolean reversed = xMajor ? ax > bx : ay > by;
        return reversed ? new DdaSteps(xMajor, true, bx, by, ax, ay) : new DdaSteps(xMajor, false, ax, ay, bx, by);
    }

    /** The major coordinate at the start (x of an x-major line, else y). */
    long majorStart() {
        return xMajor ? startX : startY;
    }

    long majorEnd() {
        return xMajor ? endX : endY;
    }

    /** The minor coordinate at the start. */
    long minorStart() {
        return xMajor ? startY : startX;
    }

    /** The number of steps: one pixel fewer than the line has. */
    long steps() {
        return majorEnd() - majorStart();
    }

    /** The minor coordinate's change per step. */
    double slope() {
        long steps = steps();
        return steps == 0 ? 0 : (double) ((xMajor ? endY - startY : endX - startX)) / steps;
    }

    /** The step whose major coordinate is pixel (x, y)'s (outside 0 to steps() when the line does not reach it). */
    long stepAt(int x, int y) {
        return (xMajor ? x : y) - majorStart();
    }

    /** The minor coordinate after {@code step} steps, the slope added once a step, as the walk adds it. */
    double minorAt(long step) {
        return Coverage.minor(minorStart(), slope(), step);
    }

    /**
     * The share of the way at {@code step}, as the drawing's walk works it
     * out (DdaWalk: halves of the coordinates, so the same bits).
     */
    double t(long step) {
        double halfStart = 0.5 * majorStart();
        double halfSteps = 0.5 * majorEnd() - halfStart;
        return halfSteps == 0 ? 0 : (0.5 * (majorStart() + step) - halfStart) / halfSteps;
    }
}
