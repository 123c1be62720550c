package simpview.raster;

/**
 * One attribute over a triangle: {@code value = base + slopeX * dx + slopeY * dy},
 * (dx, dy) measured from the triangle's first counter-clockwise vertex a.
 */
final class Plane {

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
