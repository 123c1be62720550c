package simpview.surface;

/**
 * A surface of pixels that a renderer writes to. Decorators wrap one and
 * change what a write does (test depth, replace colour, drop writes, move the
 * origin); the chain ends at an {@link ImageDrawable}.
 *
 * <p>Three ways to write, with the same meaning: {@link #setPixel} for one
 * pixel, {@link #fillSpan} for a run of pixels on one row whose depth and
 * colour vary linearly, and {@link #setRun} for a run of pixels on one row
 * whose depths and colours are given one by one. A decorator overrides
 * setPixel and fillSpan together, so that the fast path and the pixel path
 * draw the same picture. setRun's default is setPixel pixel by pixel, which
 * is right for every decorator; one that overrides it keeps that meaning.
 *
 * <p>A drawable's size never changes: a decorator may read its delegate's
 * width and height once, when it is made.
 */
public interface Drawable {

    int width();

    int height();

    /**
     * Writes one pixel. {@code z} is the world-space depth of the sample;
     * {@code argb} its colour, 0xAARRGGBB.
     */
    void setPixel(int x, int y, double z, int argb);

    /**
     * False when the colour a write carries can never reach the surface,
     * because a decorator on the way replaces it (depth cueing does): a
     * renderer may then leave colour out. Like the size, it never changes.
     */
    default boolean usesColour() {
        return true;
    }

    /** The colour now at (x, y), 0xAARRGGBB; 0 outside the surface. */
    int getPixel(int x, int y);

    /**
     * Makes now, on this thread, what the surface owes from a clear (an
     * image's owed rows, {@link ImageDrawable#oweRows}): called before
     * several threads write at once. Reads and writes make it too, on one
     * thread. The default owes nothing; a decorator asks its delegate.
     */
    default void settle() {
    }

    /** Writes every pixel of the span; the default goes pixel by pixel. */
    default void fillSpan(Span span) {
        for (int x = span.x0; x < span.x1; x++) {
            setPixel(x, span.y, span.zAt(x), span.argbAt(x));
        }
    }

    /**
     * Writes the {@code count} pixels (x + i, y), i = 0, 1, ..., count - 1,
     * the i-th with depth {@code depths[at + i]} and colour
     * {@code colours[at + i]}: the same as that many {@link #setPixel}
     * calls in order of x, which is what the default does. The arrays are
     * read before the call returns, never kept.
     */
    default void setRun(int x, int y, int count, double[] depths, int[] colours, int at) {
        for (int i = 0; i < count; i++) {
            setPixel(x + i, y, depths[at + i], colours[at + i]);
        }
    }
}
