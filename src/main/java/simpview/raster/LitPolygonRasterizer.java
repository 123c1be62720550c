package simpview.raster;

/**
 * Fills a convex polygon, clipped and projected, as a fan of triangles from
 * its first vertex: (0, 1, 2), (0, 2, 3), ... Each triangle is covered by
 * Part 1's rule ({@link TriangleCoverage}: centres, top-left), so the fan's
 * triangles share their diagonals without gaps or double writes.
 *
 * <p>A vertex is {@code 3 + channels} numbers: panel x, panel y, q, then the
 * channels (attributes multiplied by q). q and every channel are planes over
 * each triangle, evaluated at the first pixel centre of each span with their
 * x slopes, and handed to the {@link FragmentSink}: perspective-correct
 * interpolation, once the sink divides by q.
 *
 * <p>One instance reuses its scratch state; not for two threads at once.
 */
public final class LitPolygonRasterizer {

    /** Most channels a vertex may carry. */
    public static final int MAX_CHANNELS = 16;

    private final TriangleCoverage coverage = new TriangleCoverage();
    private final Plane q = new Plane();
    private final Plane[] channel = new Plane[MAX_CHANNELS];
    private final double[] v0 = new double[MAX_CHANNELS];
    private final double[] dv = new double[MAX_CHANNELS];

    public LitPolygonRasterizer() {
        for (int c = 0; c < MAX_CHANNELS; c++) {
            channel[c] = new Plane();
        }
    }

    /**
     * Fills the n-vertex polygon in v (from index 0) on a width x height panel.
     *
     * @param channels channels per vertex, at most {@link #MAX_CHANNELS}
     */
    public void fill(double[] v, int n, int channels, int width, int height, FragmentSink sink) {
        int stride = 3 + channels;
        for (int k = 1; k + 1 < n; k++) {
            triangle(v, 0, k * stride, (k + 1) * stride, channels, width, height, sink);
        }
    }

    private void triangle(double[] v, int i1, int i2, int i3, int channels, int width, int height,
            FragmentSink sink) {
        TriangleCoverage t = coverage;
        if (!t.set(v[i1], v[i1 + 1], v[i2], v[i2 + 1], v[i3], v[i3 + 1])) {
            return;
        }
        int a = i1;
        int b = t.clockwise ? i3 : i2;
        int c = t.clockwise ? i2 : i3;
        double ax = v[a];
        double ay = v[a + 1];
        double e1x = v[b] - ax;
        double e1y = v[b + 1] - ay;
        double e2x = v[c] - ax;
        double e2y = v[c + 1] - ay;
        q.set(v[a + 2], v[b + 2], v[c + 2], e1x, e1y, e2x, e2y, t.area);
        for (int ch = 0; ch < channels; ch++) {
            channel[ch].set(v[a + 3 + ch], v[b + 3 + ch], v[c + 3 + ch], e1x, e1y, e2x, e2y, t.area);
            dv[ch] = channel[ch].slopeX;
        }
        int lastRow = t.lastRow(height);
        for (int row = t.firstRow(height); row <= lastRow; row++) {
            if (t.row(row, width)) {
                double dx = t.from + 0.5 - ax;
                double dy = row + 0.5 - ay;
                for (int ch = 0; ch < channels; ch++) {
                    v0[ch] = channel[ch].valueAt(dx, dy);
                }
                sink.span(row, t.from, t.to, q.valueAt(dx, dy), q.slopeX, v0, dv);
            }
        }
    }
}
