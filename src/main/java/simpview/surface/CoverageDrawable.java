package simpview.surface;

/**
 * Writes with a coverage: each write becomes {@code c * colour + (1 - c) *
 * old} per channel (SPEC Part 3, "Colour and coverage"), c being the coverage
 * last set by {@link #cover}; 1 at the start, which writes the colour as it is.
 * Depth is passed on unchanged. Not final only for the inspector, whose
 * probe is a CoverageDrawable that also tells what each write at its pixel was.
 */
public class CoverageDrawable extends DrawableDecorator {

    private double coverage = 1;

    public CoverageDrawable(Drawable delegate) {
        super(delegate);
    }

    /** The coverage of the writes from now on, in [0, 1]. */
    public void cover(double c) {
        coverage = c;
    }

    /** The coverage of the writes now. */
    public final double coverage() {
        return coverage;
    }

    /** The surface this one writes to. */
    public Drawable target() {
        return delegate;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        delegate.setPixel(x, y, z, coverage >= 1 ? argb : Colors.mix(argb, delegate.getPixel(x, y), coverage));
    }

    @Override
    public void fillSpan(Span span) {
        for (int x = span.x0; x < span.x1; x++) {
            setPixel(x, span.y, span.zAt(x), span.argbAt(x));
        }
    }
}
