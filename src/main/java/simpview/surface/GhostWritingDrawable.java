package simpview.surface;

/**
 * The first assignment's ghost (SPEC Part 3, page 5): every write, whatever
 * its colour, makes the pixel full white at opacity {@value #OPACITY}, each
 * channel {@code 0.14 * 1 + 0.86 * old}, never through the alpha bits.
 * Depth is passed on unchanged.
 */
public final class GhostWritingDrawable extends DrawableDecorator {

    public static final double OPACITY = 0.14;

    public GhostWritingDrawable(Drawable delegate) {
        super(delegate);
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        delegate.setPixel(x, y, z, Colors.mix(Colors.WHITE, delegate.getPixel(x, y), OPACITY));
    }

    @Override
    public void fillSpan(Span span) {
        for (int x = span.x0; x < span.x1; x++) {
            setPixel(x, span.y, span.zAt(x), span.argbAt(x));
        }
    }
}
