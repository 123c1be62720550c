package simpview.raster;

/**
 * Where the lit rasterizers hand their pixels: the fragment stage that tests
 * depth, resolves the attributes, shades, fogs and writes. Each fragment
 * carries q (1/w, see {@link simpview.geometry.Camera#q}) and a number of
 * channels, each an attribute multiplied by q; all of them are affine in
 * screen space, so a span gives their values at its first pixel and their
 * change per pixel. The sink divides by q at each pixel.
 */
public interface FragmentSink {

    /**
     * Pixels {@code from <= x < to} of row y; at pixel x, q is
     * {@code q0 + (x - from) * dq} and channel c is {@code v0[c] + (x - from) * dv[c]}.
     * The arrays are read before the call returns, never kept.
     */
    void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv);

    /** One pixel with its q and channels. */
    void pixel(int x, int y, double q, double[] v);

    /**
     * The polygon whose spans come next, until {@link #primitiveDone}: its n
     * corners, the first at v[at], each {@code stride} numbers on, as
     * {@link FragmentLayout} lays them out. The array is read before
     * primitiveDone returns, never kept after. A sink may take a guess from
     * it about the spans to come, for speed (FragmentStage groups the pixels
     * of faces no light reaches), never anything that changes what they draw.
     * The filled rasterizer calls it before each polygon's spans; the default
     * does nothing.
     */
    default void polygon(double[] v, int at, int n, int stride) {
    }

    /**
     * The primitive whose spans came since the last call is done: a sink
     * may write its pixels together then ({@code FragmentStage} does, for
     * short phong spans), and must have written them all when this returns.
     * The filled rasterizer calls it after each polygon; the default does
     * nothing.
     */
    default void primitiveDone() {
    }

    /**
     * How many of a fragment's first channels, of the {@code channels} it
     * carries, this sink reads now: a rasterizer need not interpolate the
     * rest (their entries in a span's arrays are then left as they were).
     * The default reads them all.
     */
    default int channelsRead(int channels) {
        return channels;
    }

    /**
     * Whether a span of row y with these q and z (channel {@link FragmentLayout#Z}
     * over q, as in {@link #span}) may pass the sink's tests now: false only
     * when {@link #span} with them would change nothing, whatever its other
     * channels. A rasterizer need not interpolate the other channels of a
     * triangle until a span of it may pass, nor hand the sink the spans
     * before. Asking changes nothing. The default says yes.
     */
    default boolean anyNearer(int y, int from, int to, double q0, double dq, double z0, double dz) {
        return true;
    }

    /**
     * Whether what the sink holds already hides every fragment whose z is at
     * most {@code z} in rows {@code firstRow..lastRow}, columns
     * {@code firstColumn..lastColumn} (within the panel; an empty box is
     * hidden): true only when no such fragment would change anything there.
     * A rasterizer that bounds a triangle's z over the box need not draw it
     * then. Asking changes nothing. The default says no.
     */
    default boolean hides(int firstRow, int lastRow, int firstColumn, int lastColumn, double z) {
        return false;
    }
}
