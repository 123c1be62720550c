package simpview.shading;

/**
 * Lights points for phong shading, at every pixel: from a point's camera-space
 * position P, its normal N (any length; zero gives the ambient term alone) and
 * its kd, the colour clamped to [0, 1]. One point at a time into out[0..3),
 * or a batch of them, each point's colour the same to the bit either way.
 */
public interface PointShader {

    void shade(double px, double py, double pz, double nx, double ny, double nz,
            double kr, double kg, double kb, double[] out);

    /** Lights every point of the batch into its colour, each as {@link #shade} would alone. */
    void shade(LitPoints points);

    /**
     * False when the colour is the ambient term alone (no light), so that
     * both ways of shading read only kd: a batch's P and N may then be left
     * unset, and one point's given as anything (FragmentStage gives 0, and
     * its rasterizer does not interpolate them).
     */
    boolean usesPoint();

    /**
     * A guess: true when no light likely reaches point P with normal N, nor
     * the points of its face around it (see {@link Lighting#unlitAt}). A
     * fragment stage groups such points in batches of their own; nothing drawn
     * depends on the answer. The default never guesses so.
     */
    default boolean unlitAt(double px, double py, double pz, double nx, double ny, double nz) {
        return false;
    }

    /** How many lights a point adds up (0: the ambient term alone, as {@link #usesPoint} false). */
    default int lightCount() {
        return usesPoint() ? 1 : 0;
    }
}
