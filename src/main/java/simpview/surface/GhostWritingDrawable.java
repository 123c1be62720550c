package simpview.surface;

/**
 * The first assignment's ghost (SPEC Part 3, page 5): every write, whatever
 * its colour, makes the pixel full white at opacity {@value #OPACITY}, each
 * channel {@code 0.14 * 1 + 0.86 * old}, never through the alpha bits.
 * Depth is passed on unchanged.
 */
public final class GhostWritingDrawable extends DrawableDecorator {

    public static final double OPACITY = 0.14;

    /** What a ghost write makes of each old channel byte: the same arithmetic, done once per byte. */
    private static final int[] AFTER = new int[256];

    static {
        for (int level = 0; level < 256; level++) {
            AFTER[level] = Colors.red(Colors.mix(Colors.WHITE, level << 16, OPACITY));
        }
    }

    public GhostWritingDrawable(Drawable delegate) {
        super(delegate);
    }

    /** The colour written is always white at the opacity, whatever is asked: a filler may leave colour out. */
    @Override
    public boolean usesColour() {
        return false;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        int old = delegate.getPixel(x, y);
        delegate.setPixel(x, y, z, 0xFF000000 | AFTER[Colors.red(old)] << 16 | AFTER[Colors.green(old)] << 8
                | AFTER[Colors.blue(old)]);
    }

    /**
     * The same as a write per pixel, with each old colour's ghost worked out
     * once for as long as the old colour stays the same along the span (the
     * panels are flat areas of one grey between the edges).
     */
    @Override
    public void fillSpan(Span span) {
        int y = span.y;
        int lastOld = 0;
        int lastNew = 0;
        for (int x = span.x0; x < span.x1; x++) {
            int old = delegate.getPixel(x, y);
            if (old != lastOld || x == span.x0) {
                lastOld = old;
                lastNew = 0xFF000000 | AFTER[Colors.red(old)] << 16 | AFTER[Colors.green(old)] << 8
                        | AFTER[Colors.blue(old)];
            }
            delegate.setPixel(x, y, span.zAt(x), lastNew);
        }
    }
}
