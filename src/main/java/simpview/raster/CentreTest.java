package simpview.raster;

/**
 * Part 1's fill rule asked of one point and one triangle, edge by edge, by
 * the rasterizer's own exact edge functions ({@link TriangleCoverage}): for
 * the inspector, which says why a pixel centre was or was not covered, and
 * on a shared edge which of the two triangles the top-left rule gave it to.
 * The answers are the rows' answers to the bit, not a formula written again.
 */
public final class CentreTest {

    /** Strictly inside the edge's half-plane. */
    public static final int INSIDE = 0;
    /** Exactly on a top or left edge: covered, as far as this edge goes. */
    public static final int ON_TOP_OR_LEFT = 1;
    /** Exactly on a right or bottom edge: not covered; the triangle on the edge's other side has it. */
    public static final int ON_RIGHT_OR_BOTTOM = 2;
    /** Strictly outside. */
    public static final int OUTSIDE = 3;

    private CentreTest() {
    }

    /**
     * For the triangle (x1, y1), (x2, y2), (x3, y3) in panel coordinates and
     * the point (px, py): where the point lies against edge 1-2, 2-3 and 3-1
     * (one of the constants above each), or null when the triangle is
     * degenerate (zero or non-finite area), which draws nothing.
     */
    public static int[] sides(double x1, double y1, double x2, double y2, double x3, double y3, double px, double py) {
        TriangleCoverage t = new TriangleCoverage();
        if (!t.set(x1, y1, x2, y2, x3, y3)) {
            return null;
        }
        return new int[] {t.side(0, px, py), t.side(1, px, py), t.side(2, px, py)};
    }

    /** Whether a point with these sides is covered: inside or on a top or left edge of every edge. */
    public static boolean covered(int[] sides) {
        if (sides == null) {
            return false;
        }
        for (int s : sides) {
            if (s != INSIDE && s != ON_TOP_OR_LEFT) {
                return false;
            }
        }
        return true;
    }
}
