package simpview.surface;

/**
 * A drawable that passes everything to the one it wraps unless told otherwise.
 *
 * <p>Except {@link #setRun}: it is not passed on but keeps the interface's
 * default, setPixel pixel by pixel through this decorator, so a decorator
 * that changes what setPixel does (tests depth, replaces colour, drops writes)
 * changes what a run does with it. A decorator passes runs on itself, where
 * it means the same (see {@link PanelDrawable}, {@link ProvenanceDrawable}).
 */
public abstract class DrawableDecorator implements Drawable {

    protected final Drawable delegate;

    protected DrawableDecorator(Drawable delegate) {
        this.delegate = delegate;
    }

    @Override
    public int width() {
        return delegate.width();
    }

    @Override
    public int height() {
        return delegate.height();
    }

    @Override
    public boolean usesColour() {
        return delegate.usesColour();
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        delegate.setPixel(x, y, z, argb);
    }

    @Override
    public int getPixel(int x, int y) {
        return delegate.getPixel(x, y);
    }

    @Override
    public void settle() {
        delegate.settle();
    }

    @Override
    public void fillSpan(Span span) {
        delegate.fillSpan(span);
    }
}
