package simpview.raster;

/**
 * Bresenham's line ({@link BresenhamWalk}): endpoints rounded as for the DDA,
 * the same start endpoint, integer midpoint decisions. At an exact tie it
 * TIE_RULE.
 */
public final class BresenhamLineRenderer extends WalkingLineRenderer {

    /** What the course's page 1, panel 2 shows at a tie. */
    public static final boolean STEP_AT_TIE = true;

    public BresenhamLineRenderer() {
        super(new BresenhamWalk(STEP_AT_TIE));
    }
}
