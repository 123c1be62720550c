package simpview.surface;

/**
 * The end of a chain whose writes matter only to the decorators before it
 * (a count, a probe, the geometry an outline needs): a surface of the
 * panel's size (or another) that keeps nothing, wants no colour and reads as 0.
 */
public final class DiscardingDrawable implements Drawable {

    private final int width;
    private final int height;

    /** Of the panel's size. */
    public DiscardingDrawable() {
        this(PageCanvas.PANEL, PageCanvas.PANEL);
    }

    public DiscardingDrawable(int width, int height) {
        this.width = width;
        this.height = height;
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public boolean usesColour() {
        return false;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        // kept nowhere
    }

    @Override
    public void fillSpan(Span span) {
        // kept nowhere
    }

    @Override
    public int getPixel(int x, int y) {
        return 0;
    }
}
