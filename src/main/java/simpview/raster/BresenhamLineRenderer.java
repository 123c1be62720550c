package simpview.raster;

/**
 * Bresenham's line ({@link BresenhamWalk}), as the course's page 1 panel 2
 * draws it: the midpoint algorithm in the first octant and the any-octant
 * transform for the rest, from the same start endpoint as the DDA; the ends'
 * major coordinates rounded, the decisions taken on the line through their
 * minor coordinates as given; at an exact tie the minor coordinate is kept
 * (on the start's side).
 *
 * <p>On integer endpoints it is the integer midpoint algorithm, and lights
 * the DDA's pixels on every line without an exact tie; at a tie it keeps
 * where the DDA rounds half up (the other pixel on rising lines, the same on
 * falling ones), and the DDA's added-up sum may land a last bit beside the
 * half. On other endpoints the two differ wherever the line through the
 * rounded ends and the one through the given ones round apart
 * (docs/assignment1.md).
 */
public final class BresenhamLineRenderer extends WalkingLineRenderer {

    public BresenhamLineRenderer() {
        super(new BresenhamWalk());
    }
}
