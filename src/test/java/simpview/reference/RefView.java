package simpview.reference;

/**
 * The view of a lit scene in camera space, as SPEC Part 2 words it: either
 * the perspective frustum of a `camera` (eye at the origin, window on
 * z = -1) or, without a camera, Part 1's parallel box. It knows the six
 * clip planes and the projection onto the 650x650 panel.
 */
record RefView(boolean perspective, double xlow, double ylow, double xhigh, double yhigh,
        double hither, double yon) {

    static final int PANEL = 650;

    /** Part 1's box: x, y in [-100, 100], z in [-200, 0]. */
    static RefView parallel() {
        return new RefView(false, -100, -100, 100, 100, 0, -200);
    }

    static RefView camera(double xlow, double ylow, double xhigh, double yhigh, double hither, double yon) {
        return new RefView(true, xlow, ylow, xhigh, yhigh, hither, yon);
    }

    /**
     * Signed distance-like value of camera-space point v to clip plane
     * `plane` (0 hither, 1 yon, 2 left, 3 right, 4 bottom, 5 top):
     * >= 0 inside. Linear in v, so crossings are found by its ratio.
     */
    double inside(int plane, double[] v) {
        double x = v[0];
        double y = v[1];
        double z = v[2];
        double depth = perspective ? -z : 1;
        return switch (plane) {
            case 0 -> hither - z;
            case 1 -> z - yon;
            case 2 -> x - xlow * depth;
            case 3 -> xhigh * depth - x;
            case 4 -> y - ylow * depth;
            case 5 -> yhigh * depth - y;
            default -> throw new IllegalArgumentException("plane " + plane);
        };
    }

    /** Pixels per window unit. */
    double pixelsPerUnit() {
        return PANEL / Math.max(xhigh - xlow, yhigh - ylow);
    }

    /** Panel x (y up, origin bottom-left) of camera-space v. */
    double panelX(double[] v) {
        double s = pixelsPerUnit();
        double xp = perspective ? v[0] / -v[2] : v[0];
        return (PANEL - s * (xhigh - xlow)) / 2 + (xp - xlow) * s;
    }

    double panelY(double[] v) {
        double s = pixelsPerUnit();
        double yp = perspective ? v[1] / -v[2] : v[1];
        return (PANEL - s * (yhigh - ylow)) / 2 + (yp - ylow) * s;
    }

    /**
     * The weight that makes attributes perspective-correct: 1/(-z) in
     * perspective (a/z and 1/z are linear on screen), 1 in the parallel view.
     */
    double weight(double[] v) {
        return perspective ? 1 / -v[2] : 1;
    }
}
