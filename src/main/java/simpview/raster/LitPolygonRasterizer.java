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
    /** True when the last triangle had a span that could pass: then the next one's box is not asked. */
    private boolean lastPassed;

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
        if (channels < 1) {
            throw new IllegalArgumentException("a lit polygon carries z: " + channels + " channels");
        }
        int stride = FragmentLayout.stride(channels);
        int read = Math.max(1, Math.min(channels, sink.channelsRead(channels)));
        sink.polygon(v, at, n, stride);
        for (int k = 1; k + 1 < n; k++) {
            triangle(v, at, at + k * stride, at + (k + 1) * stride, read, width, height, sink);
        }
        sink.primitiveDone();
    }

    /*
     * Hidden triangles. Most of a mesh's triangles are behind what is drawn
     * already when their turn comes: 47 % of A4 page-d's 28,716 lie wholly
     * behind the depths over their box, and only 10 % have a pixel that
     * passes. Only q's and z's planes are set up first. When the triangle
     * before passed nothing, the box of the vertices is asked whether it
     * hides the triangle (FragmentSink.hides, with the bound of
     * TriangleSetup.highestDepth); if so the triangle is done. Otherwise
     * its rows are walked, each asked whether a pixel passes
     * (FragmentSink.anyNearer, the sink's own test on the z the span would
     * give), and the other channels' planes are set up at the first row
     * that has one: from there on every row is a span, as before. Neither
     * question writes, and a span's values do not depend on when its planes
     * were set up, so the sink is given exactly the spans that can change
     * something, with the same numbers. After a triangle that passed a pixel
     * the box is not asked (a mesh's neighbours are alike): on A4 page-g,
     * 96 % of whose triangles pass, asking of every one cost 7 %.
     */
    private void triangle(double[] v, int i1, int i2, int i3, int channels, int width, int height,
            FragmentSink sink) {
        TriangleSetup t = triangle;
        if (!t.set(v, i1, i2, i3, FragmentLayout.X, FragmentLayout.Y)) {
            return;
        }
        t.plane(q, v, FragmentLayout.Q);
        Plane z = channel[FragmentLayout.Z];
        t.plane(z, v, FragmentLayout.CHANNEL + FragmentLayout.Z);
        dv[FragmentLayout.Z] = z.slopeX;
        int firstRow = t.firstRow(height, rowFrom);
        int lastRow = t.lastRow(height, rowTo);
        int firstColumn = t.firstColumn(width);
        int lastColumn = t.lastColumn(width);
        if (firstRow > lastRow || firstColumn > lastColumn) {
            return; // no pixel centre in its box
        }
        if (!lastPassed && sink.hides(firstRow, lastRow, firstColumn, lastColumn, t.highestDepth(q, z))) {
            return;
        }
        boolean planesSet = false;
        for (int row = firstRow; row <= lastRow; row++) {
            if (t.row(row, width)) {
                double dx = t.dx();
                double dy = t.dy(row);
                double q0 = q.valueAt(dx, dy);
                double z0 = z.valueAt(dx, dy);
                if (!planesSet) {
                    if (!sink.anyNearer(row, t.from(), t.to(), q0, q.slopeX, z0, z.slopeX)) {
                        continue;
                    }
                    for (int ch = 1; ch < channels; ch++) {
                        t.plane(channel[ch], v, FragmentLayout.CHANNEL + ch);
                        dv[ch] = channel[ch].slopeX;
                    }
                    planesSet = true;
                }
                v0[FragmentLayout.Z] = z0;
                for (int ch = 1; ch < channels; ch++) {
                    v0[ch] = channel[ch].valueAt(dx, dy);
                }
                sink.span(row, t.from(), t.to(), q0, q.slopeX, v0, dv);
            }
        }
        lastPassed = planesSet;
    }
}
