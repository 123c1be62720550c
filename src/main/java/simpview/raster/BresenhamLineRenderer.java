package simpview.raster;

/**
 * Bresenham's line ({@link BresenhamWalk}): the midpoint algorithm in the
 * first octant and the any-octant transform for the rest, from the same start
 * endpoint as the DDA, the ends rounded first; at an exact tie the minor
 * coordinate is kept (on the start's side).
 *
 * <p>{@code new BresenhamLineRenderer()} is SPEC Part 3's: the integer
 * algorithm on the rounded ends. It lights the DDA's pixels on every line
 * without an exact tie; at a tie it keeps where the DDA rounds half up (the
 * other pixel on rising lines, the same on falling ones), and the DDA's
 * added-up sum may land a last bit beside the half.
 * {@link #throughGivenMinor()} is the course's program's, as its picture of
 * page 1 panel 2 shows it: the decisions taken on the line through the ends'
 * minor coordinates as given, so on non-integer ends it differs from the DDA
 * wherever that line and the rounded one round apart (docs/assignment1.md).
 */
public final class BresenhamLineRenderer extends WalkingLineRenderer {

    /** SPEC Part 3's Bresenham: the integer midpoint algorithm on the rounded ends. */
    public BresenhamLineRenderer() {
        super(BresenhamWalk.integer());
    }

    private BresenhamLineRenderer(BresenhamWalk walk) {
        super(walk);
    }

    /** The course's program's Bresenham: decisions on the ends' given minor coordinates. */
    public static BresenhamLineRenderer throughGivenMinor() {
        return new BresenhamLineRenderer(BresenhamWalk.throughGivenMinor());
    }
}
