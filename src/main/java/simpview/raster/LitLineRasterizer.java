package simpview.raster;

/**
 * The DDA line of Part 1 ({@link DdaWalk}, the same walk as
 * {@link DdaLineRenderer}) for lit scenes: q and every channel are lerped per
 * step from the walk's start endpoint to its end, in screen space, and handed
 * to the {@link FragmentSink}, which divides by q: perspective-correct along
 * the line. A value both ends share is every step's, to the bit
 * ({@link WalkingLineRenderer#lerp}): so a line of one colour, whose colour
 * channels hold it as it is, is that colour at every pixel.
 *
 * <p>A vertex is laid out as for {@link LitPolygonRasterizer}: panel x, panel
 * y, q, channels. Only the pixels on the panel are visited. One instance
 * reuses its scratch state; not for two threads at once.
 */
public final class LitLineRasterizer {

    private final DdaWalk walk = new DdaWalk();
    private final double[] at = new double[LitPolygonRasterizer.MAX_CHANNELS];

    /** From now on only rows from &lt;= y &lt; to are drawn (a band's): the same pixels of those rows as the whole line. */
    public void rows(int from, int to) {
        walk.rows(from, to);
    }

    /**
     * The outline of the n vertices from v[at] ({@link FragmentLayout#stride}
     * numbers each), edge k from vertex k to k + 1 and the last back to the
     * first, each a {@link #draw}; but for edge k under 64 when bit k of
     * {@code leftOut} is set (0 draws every edge).
     */
    public void outline(double[] v, int at, int n, int channels, long leftOut, int width, int height,
            FragmentSink sink) {
        int stride = FragmentLayout.stride(channels);
        for (int k = 0; k < n; k++) {
            if (k >= Long.SIZE || (leftOut >>> k & 1) == 0) {
                draw(v, at + k * stride, at + ((k + 1) % n) * stride, channels, width, height, sink);
            }
        }
    }

    /** The line from the vertex at v[from] to the vertex at v[to] on a width x height panel. */
    public void draw(double[] v, int from, int to, int channels, int width, int height, FragmentSink sink) {
        if (!walk.start(v[from], v[from + 1], v[to], v[to + 1], width, height)) {
            return;
        }
        int a = walk.reversed() ? to : from;
        int b = walk.reversed() ? from : to;
        if (channels == FragmentLayout.COLOUR_CHANNELS) {
            colourLine(v, a, b, sink);
            return;
        }
        while (walk.next()) {
            double t = walk.t();
            double s = 1 - t;
            for (int c = 0; c < channels; c++) {
                at[c] = WalkingLineRenderer.lerp(v[a + 3 + c], v[b + 3 + c], s, t);
            }
            sink.pixel(walk.x(), walk.y(), WalkingLineRenderer.lerp(v[a + 2], v[b + 2], s, t), at);
        }
    }

    /**
     * The walk begun, for a line of the four colour channels (every line and
     * outline): the same lerps, with the ends' numbers read once into locals
     * (the writes to at[] could alias v, so the loop above reads them again
     * at every pixel).
     */
    private void colourLine(double[] v, int a, int b, FragmentSink sink) {
        int ca = a + FragmentLayout.CHANNEL;
        int cb = b + FragmentLayout.CHANNEL;
        double qa = v[a + FragmentLayout.Q];
        double qb = v[b + FragmentLayout.Q];
        double za = v[ca + FragmentLayout.Z];
        double zb = v[cb + FragmentLayout.Z];
        double ra = v[ca + FragmentLayout.R];
        double rb = v[cb + FragmentLayout.R];
        double ga = v[ca + FragmentLayout.G];
        double gb = v[cb + FragmentLayout.G];
        double ba = v[ca + FragmentLayout.B];
        double bb = v[cb + FragmentLayout.B];
        double[] channel = at;
        while (walk.next()) {
            double t = walk.t();
            double s = 1 - t;
            channel[FragmentLayout.Z] = WalkingLineRenderer.lerp(za, zb, s, t);
            channel[FragmentLayout.R] = WalkingLineRenderer.lerp(ra, rb, s, t);
            channel[FragmentLayout.G] = WalkingLineRenderer.lerp(ga, gb, s, t);
            channel[FragmentLayout.B] = WalkingLineRenderer.lerp(ba, bb, s, t);
            sink.pixel(walk.x(), walk.y(), WalkingLineRenderer.lerp(qa, qb, s, t), channel);
        }
    }
}
