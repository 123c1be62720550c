package simpview.surface;

/**
 * Lets through only the writes to rows {@code from <= y < to}: one band of a
 * picture drawn by several threads, each through its own band. Every other
 * write is dropped before it reaches anything below, so a band's thread
 * touches no pixel, depth or owner of another band.
 */
public final class RowBandDrawable extends DrawableDecorator {

    private final int from;
    private final int to;

    public RowBandDrawable(int from, int to, Drawable delegate) {
        super(delegate);
        this.from = from;
        this.to = to;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        if (y >= from && y < to) {
            delegate.setPixel(x, y, z, argb);
        }
    }

    @Override
    public void fillSpan(Span span) {
        if (span.y >= from && span.y < to) {
            delegate.fillSpan(span);
        }
    }

    @Override
    public void setRun(int x, int y, int count, double[] depths, int[] colours, int at) {
        if (y >= from && y < to) {
            delegate.setRun(x, y, count, depths, colours, at);
        }
    }
}
