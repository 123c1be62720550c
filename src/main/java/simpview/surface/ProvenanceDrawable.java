package simpview.surface;

import java.util.Arrays;

/**
 * Records, for every write that reaches it, which primitive made it (see
 * {@link Provenance}), and passes the write on unchanged. Placed after the
 * z-buffer it keeps the owner of what each pixel shows. When it is not in a
 * chain it costs nothing.
 */
public final class ProvenanceDrawable extends DrawableDecorator {

    private final Provenance provenance;
    private final int[] owner;
    private final int width;
    private final int height;

    public ProvenanceDrawable(Provenance provenance, Drawable delegate) {
        super(delegate);
        if (provenance.width() != delegate.width() || provenance.height() != delegate.height()) {
            throw new IllegalArgumentException("provenance " + provenance.width() + "x" + provenance.height()
                    + " does not match its drawable " + delegate.width() + "x" + delegate.height());
        }
        this.provenance = provenance;
        this.owner = provenance.owner;
        this.width = provenance.width();
        this.height = provenance.height();
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        if (x >= 0 && x < width && y >= 0 && y < height) {
            owner[y * width + x] = provenance.currentAt(y);
        }
        delegate.setPixel(x, y, z, argb);
    }

    /** Records the run's pixels inside the drawable as the current primitive's, then passes the run on. */
    @Override
    public void setRun(int x, int y, int count, double[] depths, int[] colours, int at) {
        if (y >= 0 && y < height) {
            int from = Math.max(0, x);
            int to = Math.min(width, x + count);
            if (from < to) {
                Arrays.fill(owner, y * width + from, y * width + to, provenance.currentAt(y));
            }
        }
        delegate.setRun(x, y, count, depths, colours, at);
    }

    @Override
    public void fillSpan(Span s) {
        if (s.y >= 0 && s.y < height) {
            int from = Math.max(0, s.x0);
            int to = Math.min(width, s.x1);
            if (from < to) {
                Arrays.fill(owner, s.y * width + from, s.y * width + to, provenance.currentAt(s.y));
            }
        }
        delegate.fillSpan(s);
    }
}
