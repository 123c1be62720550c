package simpview.raster;

/**
 * Fills a convex polygon, clipped and projected, as a fan of triangles from
 * its first vertex: (0, 1, 2), (0, 2, 3), ... Each triangle is covered by
 * Part 1's rule ({@link TriangleCoverage}: centres, top-left), so the fan's
 * triangles share their diagonals without gaps or double writes.
 *
 * <p>A vertex is laid out as {@link FragmentLayout} says: panel x, panel y,
 * q, then the channels (attributes multiplied by q). The triangles are set
 * up as the depth-cued renderer's are ({@link TriangleSetup}). q and every channel are planes over
 * each triangle, evaluated at the first pixel centre of each span with their
 * x slopes, and handed to the {@link FragmentSink}: perspective-correct
 * interpolation, once the sink divides by q.
 *
 * <p>One instance reuses its scratch state; not for two threads at once.
 */
public final class LitPolygonRasterizer {

    /** Most channels a vertex may carry. */
    public static final int MAX_CHANNELS = 16;

    private final TriangleSetup triangle = new TriangleSetup();
    private final Plane q = new Plane();
    private final Plane[] channel = new Plane[MAX_CHANNELS];
    private final double[] v0 = new double[MAX_CHANNELS];
    private final double[] dv = new double[MAX_CHANNELS];
    // The rows drawn: all of them, or one band's.
    private int rowFrom;
    private int rowTo = Integer.MAX_VALUE;

    public LitPolygonRasterizer() {
        for (int c = 0; c < MAX_CHANNELS; c++) {
            channel[c] = new Plane();
        }
    }

    /** From now on fills only the rows {@code from <= y < to} of each polygon (one band of a picture). */
    public void rows(int from, int to) {
        rowFrom = from;
        rowTo = to;
    }

    /**
     * Fills the n-vertex polygon in v (from index 0) on a width x height panel.
     *
     * @param channels channels per vertex, at most {@link #MAX_CHANNELS}
     */
    public void fill(double[] v, int n, int channels, int width, int height, FragmentSink sink) {
        fill(v, 0, n, channels, width, height, sink);
    }

    /**
     * The same for the polygon whose first vertex starts at v[at]; only the
     * channels the sink reads ({@link FragmentSink#channelsRead}) are
     * interpolated.
     */
    public void fill(double[] v, int at, int n, int channels, int width, int height, FragmentSink sink) {
        int stride = FragmentLayout.stride(channels);
        int read = Math.min(channels, sink.channelsRead(channels));
        for (int k = 1; k + 1 < n; k++) {
            triangle(v, at, at + k * stride, at + (k + 1) * stride, read, width, height, sink);
        }
        sink.primitiveDone();
    }

    private void triangle(double[] v, int i1, int i2, int i3, int channels, int width, int height,
            FragmentSink sink) {
        TriangleSetup t = triangle;
        if (!t.set(v, i1, i2, i3, FragmentLayout.X, FragmentLayout.Y)) {
            return;
        }
        t.plane(q, v, FragmentLayout.Q);
        for (int ch = 0; ch < channels; ch++) {
            t.plane(channel[ch], v, FragmentLayout.CHANNEL + ch);
            dv[ch] = channel[ch].slopeX;
        }
        int lastRow = t.lastRow(height, rowTo);
        for (int row = t.firstRow(height, rowFrom); row <= lastRow; row++) {
            if (t.row(row, width)) {
                double dx = t.dx();
                double dy = t.dy(row);
                for (int ch = 0; ch < channels; ch++) {
                    v0[ch] = channel[ch].valueAt(dx, dy);
                }
                sink.span(row, t.from(), t.to(), q.valueAt(dx, dy), q.slopeX, v0, dv);
            }
        }
    }
}
