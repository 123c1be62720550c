package simpview.window.render;

import java.awt.image.BufferedImage;
import java.util.ArrayDeque;

/**
 * Page images the window has let go of, for the render thread to draw its
 * next pictures on ({@link simpview.surface.PageCanvas#handOff}): the frames
 * of a turning drag take turns on two or three images instead of each making
 * one of 2.25 MB for the collector. The event thread gives an image back
 * once nothing shows or holds it, the render thread takes one; at most
 * {@link #KEPT} are kept. Thread safe.
 */
public final class SpareImages {

    /** The most kept: one drawn on while the window shows another, and one a frame late. */
    static final int KEPT = 2;

    private final ArrayDeque<BufferedImage> spare = new ArrayDeque<>(KEPT);

    /**
     * {@code image}, a picture this renderer drew, is no longer shown or held
     * by anyone: a later picture may be drawn on it. Given twice, it is kept
     * once.
     */
    public synchronized void giveBack(BufferedImage image) {
        if (spare.size() < KEPT && !spare.contains(image)) {
            spare.push(image);
        }
    }

    /** An image given back, or null when none is: the render thread's, to draw its next picture on. */
    public synchronized BufferedImage take() {
        return spare.poll();
    }

    /** Whether {@code image} is kept, to be drawn on next. */
    public synchronized boolean holds(BufferedImage image) {
        return spare.contains(image);
    }

    /** How many are kept now. */
    synchronized int count() {
        return spare.size();
    }
}
