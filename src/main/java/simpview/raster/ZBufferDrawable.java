package simpview.raster;

/**
 * Hidden-surface removal: a write goes through only if it is strictly nearer
 * ({@code z > zbuffer(x, y)}) than what is there, and then its depth is kept.
 * Of two writes at equal depth the first stays.
 */
public final class ZBufferDrawable extends DrawableDecorator {

    private final ZBuffer zbuffer;
    private final double[] depth;
    private final int width;
    private final int height;

    public ZBufferDrawable(ZBuffer zbuffer, Drawable delegate) {
        super(delegate);
        if (zbuffer.width() != delegate.width() || zbuffer.height() != delegate.height()) {
            throw new IllegalArgumentException("z-buffer " + zbuffer.width() + "x" + zbuffer.height()
                    + " does not match its drawable " + delegate.width() + "x" + delegate.height());
        }
        this.zbuffer = zbuffer;
        this.depth = zbuffer.depth;
        this.width = zbuffer.width();
        this.height = zbuffer.height();
    }

    public ZBuffer zbuffer() {
        return zbuffer;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        if (x < 0 || x >= width || y < 0 || y >= height) {
            return;
        }
        int i = y * width + x;
        if (z > depth[i]) {
            depth[i] = z;
            delegate.setPixel(x, y, z, argb);
        }
    }

    /** Passes on the longest runs of pixels that win the depth test, each as one span. */
    @Override
    public void fillSpan(Span s) {
        if (s.y < 0 || s.y >= height) {
            return;
        }
        int x0 = s.x0;
        int x1 = s.x1;
        int from = Math.max(x0, 0);
        int to = Math.min(x1, width);
        int row = s.y * width;
        double z = s.z;
        double dz = s.dz;
        int xBase = s.xBase;
        int runStart = -1;
        for (int x = from; x < to; x++) {
            double zx = z + (x - xBase) * dz;
            if (zx > depth[row + x]) {
                depth[row + x] = zx;
                if (runStart < 0) {
                    runStart = x;
                }
            } else if (runStart >= 0) {
                emit(s, runStart, x);
                runStart = -1;
            }
        }
        if (runStart >= 0) {
            emit(s, runStart, to);
        }
        s.x0 = x0;
        s.x1 = x1;
    }

    private void emit(Span s, int from, int to) {
        s.x0 = from;
        s.x1 = to;
        delegate.fillSpan(s);
    }
}
