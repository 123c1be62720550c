package simpview.raster;

/**
 * The DDA line of SPEC Part 1: endpoints rounded to the nearest pixel, drawn
 * from the smaller-x (x-major) or smaller-y (y-major) end, the minor
 * coordinate adding the slope once per step and rounded half up
 * ({@link DdaWalk}); colour and z lerped per step.
 */
public final class DdaLineRenderer extends WalkingLineRenderer {

    public DdaLineRenderer() {
        super(new DdaWalk());
    }
}
