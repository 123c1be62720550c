package simpview.scene.simp;

import simpview.geometry.ViewVolume;

/**
 * Culling against the six planes of the view volume: a primitive whose
 * world-space vertices all lie outside one and the same plane cannot touch
 * the volume, so it is not rasterized at all. Each vertex gets an outcode,
 * one bit per plane it is outside; the primitive is culled when the codes
 * share a bit.
 */
public final class Culling {

    private static final int LEFT = 1;
    private static final int RIGHT = 2;
    private static final int BOTTOM = 4;
    private static final int TOP = 8;
    private static final int NEAR = 16;
    private static final int FAR = 32;

    private Culling() {
    }

    /** The planes (x, y, z) is outside of; NaN is outside none. */
    static int outcode(double x, double y, double z) {
        int code = 0;
        if (x < ViewVolume.MIN_X) {
            code |= LEFT;
        } else if (x > ViewVolume.MAX_X) {
            code |= RIGHT;
        }
        if (y < ViewVolume.MIN_Y) {
            code |= BOTTOM;
        } else if (y > ViewVolume.MAX_Y) {
            code |= TOP;
        }
        if (z > ViewVolume.NEAR_Z) {
            code |= NEAR;
        } else if (z < ViewVolume.FAR_Z) {
            code |= FAR;
        }
        return code;
    }

    /**
     * True when the first {@code count} points of {@code xyz} (x, y, z each,
     * world space) are all outside one plane.
     */
    public static boolean isCulled(double[] xyz, int count) {
        int common = ~0;
        for (int k = 0; k < count && common != 0; k++) {
            common &= outcode(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
        }
        return common != 0;
    }
}
