package simpview.raster;

/**
 * One attribute over a triangle: {@code value = base + slopeX * dx + slopeY * dy},
 * (dx, dy) measured from the triangle's first counter-clockwise vertex a.
 */
final class Plane {

    /**
     * The bounds below are this much of the sum of their terms' sizes wider
     * than the plane's values over their box. A value computed in a span,
     * {@code valueAt} at its first pixel then {@code k * slopeX} added,
     * rounds five times, each time by at most 2^-53 of the terms so far, so
     * that it is within 6e-16 of that sum of the exact plane over the box:
     * the margin is more than a thousand times that.
     */
    static final double MARGIN = 1e-12;

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

    /**
     * Above every value a span computes from this plane at a pixel centre
     * in the box centred at (cx, cy) (from vertex a), hw and hh half its
     * sides: the plane's highest value over the box, at a corner, and the
     * {@link #MARGIN}.
     */
    double highest(double cx, double cy, double hw, double hh) {
        return centre(cx, cy) + reach(hw, hh) + roundings(cx, cy, hw, hh);
    }

    /** Below every such value. */
    double lowest(double cx, double cy, double hw, double hh) {
        return centre(cx, cy) - reach(hw, hh) - roundings(cx, cy, hw, hh);
    }

    private double centre(double cx, double cy) {
        return base + slopeX * cx + slopeY * cy;
    }

    /** How far the plane rises from the box's centre to its highest corner. */
    private double reach(double hw, double hh) {
        return Math.abs(slopeX) * hw + Math.abs(slopeY) * hh;
    }

    /**
     * The margin on the sizes of a span's terms: the base, slopeX times the
     * first pixel's dx and again times the steps k (each at most the box's
     * farthest dx), slopeY times dy.
     */
    private double roundings(double cx, double cy, double hw, double hh) {
        return MARGIN * (Math.abs(base) + 2 * Math.abs(slopeX) * (Math.abs(cx) + hw)
                + Math.abs(slopeY) * (Math.abs(cy) + hh));
    }
}
