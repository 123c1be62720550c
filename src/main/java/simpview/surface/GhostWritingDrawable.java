package simpview.surface;

/**
 * The first assignment's ghost (SPEC Part 3, page 5): every write, whatever
 * its colour, makes the pixel full white at opacity {@value #OPACITY}, each
 * channel {@code 0.14 * 1 + 0.86 * old}, never through the alpha bits.
 * Depth is passed on unchanged. A span is read, made ghosts of and written
 * back as one run ({@link Drawable#setRun}), in scratch rows this instance
 * keeps: one instance serves one thread.
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

    /** One row's depths and colours, for {@link #fillSpan}: grown to the longest span, never per span. */
    private double[] depths = new double[0];
    private int[] colours = new int[0];

    public GhostWritingDrawable(Drawable delegate) {
        super(delegate);
    }

    /** The colour written is always white at the opacity, whatever is asked. */
    @Override
    public boolean usesColour() {
        return false;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        delegate.setPixel(x, y, z, ghostOver(delegate.getPixel(x, y)));
    }

    private static int ghostOver(int old) {
        return 0xFF000000 | AFTER[Colors.red(old)] << 16 | AFTER[Colors.green(old)] << 8 | AFTER[Colors.blue(old)];
    }

    /** The span's pixels read, made ghosts of and written back as one run. */
    @Override
    public void fillSpan(Span span) {
        int count = span.x1 - span.x0;
        if (count <= 0) {
            return;
        }
        if (colours.length < count) {
            colours = new int[count];
            depths = new double[count];
        }
        delegate.getRun(span.x0, span.y, count, colours, 0);
        // Runs of one old colour are common (a ghost over a flat area): each is looked up once.
        int old = ~colours[0];
        int ghost = 0;
        for (int i = 0; i < count; i++) {
            if (colours[i] != old) {
                old = colours[i];
                ghost = ghostOver(old);
            }
            colours[i] = ghost;
        }
        for (int i = 0; i < count; i++) {
            depths[i] = span.zAt(span.x0 + i);
        }
        delegate.setRun(span.x0, span.y, count, depths, colours, 0);
    }
}
