package simpview.raster;

/**
 * The DDA line of Part 1 (one pixel per step along the major axis, both end
 * pixels included, the minor coordinate the rounded lerp between the end
 * pixels) for lit scenes: q and every channel are lerped per step with the
 * same parameter t, in screen space, and handed to the {@link FragmentSink},
 * which divides by q: perspective-correct along the line.
 *
 * <p>A vertex is laid out as for {@link LitPolygonRasterizer}: panel x, panel
 * y, q, channels. Only the steps whose major coordinate lies on the panel are
 * visited. One instance reuses its scratch state; not for two threads at once.
 */
public final class LitLineRasterizer {

    private final double[] at = new double[LitPolygonRasterizer.MAX_CHANNELS];

    /** The line from the vertex at v[from] to the vertex at v[to] on a width x height panel. */
    public void draw(double[] v, int from, int to, int channels, int width, int height, FragmentSink sink) {
        double px = v[from];
        double py = v[from + 1];
        double qx = v[to];
        double qy = v[to + 1];
        if (!Double.isFinite(px) || !Double.isFinite(py) || !Double.isFinite(qx) || !Double.isFinite(qy)) {
            return;
        }
        double x0 = Math.floor(px);
        double y0 = Math.floor(py);
        double x1 = Math.floor(qx);
        double y1 = Math.floor(qy);
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        double major0 = xMajor ? x0 : y0;
        double major1 = xMajor ? x1 : y1;
        double minor0 = xMajor ? y0 : x0;
        double minor1 = xMajor ? y1 : x1;
        int majorLimit = xMajor ? width : height;
        int minorLimit = xMajor ? height : width;
        double lo = Math.max(Math.min(major0, major1), 0);
        double hi = Math.min(Math.max(major0, major1), majorLimit - 1);
        if (lo > hi) {
            return;
        }
        int step = major1 >= major0 ? 1 : -1;
        int first = (int) (step > 0 ? lo : hi);
        int count = (int) (hi - lo) + 1;
        // As in DdaLineRenderer: halves keep the spans finite, and t is the same bits as unscaled.
        double halfStart = 0.5 * major0;
        double halfSpan = 0.5 * major1 - 0.5 * major0;
        double halfMinor0 = 0.5 * minor0;
        double halfMinorSpan = 0.5 * minor1 - 0.5 * minor0;
        for (int n = 0, major = first; n < count; n++, major += step) {
            double t = halfSpan == 0 ? 0 : (0.5 * major - halfStart) / halfSpan;
            double s = 1 - t;
            double minor = Math.floor(2 * (halfMinor0 + halfMinorSpan * t) + 0.5);
            if (minor < 0 || minor >= minorLimit) {
                continue;
            }
            for (int c = 0; c < channels; c++) {
                at[c] = s * v[from + 3 + c] + t * v[to + 3 + c];
            }
            double q = s * v[from + 2] + t * v[to + 2];
            int x = xMajor ? major : (int) minor;
            int y = xMajor ? (int) minor : major;
            sink.pixel(x, y, q, at);
        }
    }
}
