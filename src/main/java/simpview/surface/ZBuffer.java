package simpview.surface;

import java.util.Arrays;

/**
 * One depth per pixel (world space for depth-cued scenes, camera space for lit
 * ones); larger z is nearer. Reset to the farthest depth of the picture: the
 * far plane, z = -200, for depth-cued scenes; -infinity for lit ones.
 *
 * <p>Only a {@link ZBufferDrawable} writes the depths, and it says so
 * ({@link #written}) before it returns from a write. So the buffer knows when
 * every entry is still at the far plane, and a reset then costs nothing: the
 * pages that draw without depth (1 and 2) do not pay for filling 3.4 MB.
 *
 * <p>A reset may also be owed ({@link #resetWhenNeeded}, the canvas's clear):
 * the entries are filled by the first that reads or tests them
 * ({@link #settle}: every reader here, and the {@link ZBufferDrawable}'s
 * writes), on whichever thread that is, once, before any of them goes on. A
 * lit scene resets the buffer to -infinity itself before it tests a depth
 * ({@link #reset}, {@link #resetByRows}), and that reset replaces the owed one:
 * so a lit page fills the buffer once, not twice (-200, then -infinity). A
 * depth-cued scene drawn in bands has its drawers make the owed reset row by
 * row instead ({@link #resetOwedByRows}).
 */
public final class ZBuffer {

    private final int width;
    private final int height;
    final double[] depth;
    /** True only while every entry is {@link #resetTo}. */
    private boolean atFarPlane;
    private double resetTo = Double.NaN;
    /**
     * True while every entry is to be {@link #resetTo} but is not yet: set on
     * the thread that clears, before any drawing thread starts; read by every
     * write of several threads at once, and cleared by the first, which fills.
     */
    private volatile boolean owed;

    public ZBuffer(int width, int height) {
        this.width = width;
        this.height = height;
        this.depth = new double[width * height];
        reset(-200);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Every entry back to {@code farthest}: -200 for depth-cued pictures, -infinity for lit ones. */
    public void reset(double farthest) {
        if (!atFarPlane || Double.doubleToLongBits(farthest) != Double.doubleToLongBits(resetTo)) {
            Arrays.fill(depth, farthest);
            resetTo = farthest;
            atFarPlane = true;
        }
        owed = false;
    }

    /**
     * Every entry back to {@code farthest} by the time anyone reads or tests
     * one ({@link #settle}), unless a {@link #reset} or {@link #resetByRows}
     * comes first and replaces it. Nothing to do when every entry already is.
     */
    public void resetWhenNeeded(double farthest) {
        if (atFarPlane && Double.doubleToLongBits(farthest) == Double.doubleToLongBits(resetTo)) {
            return;
        }
        resetTo = farthest;
        atFarPlane = false;
        owed = true;
    }

    /**
     * Makes the reset owed, if one is ({@link #resetWhenNeeded}): called
     * before the depths are read or tested. Safe from several threads at
     * once: the first fills, the others wait for it.
     */
    public void settle() {
        if (owed) {
            fillOwed();
        }
    }

    private synchronized void fillOwed() {
        if (owed) {
            Arrays.fill(depth, resetTo);
            atFarPlane = true;
            owed = false;
        }
    }

    /**
     * Every entry is to be {@code farthest}, set row by row by whoever draws
     * each row ({@link #resetRows}) before it tests any: the drawer of a band
     * of rows resets its own, on its own thread, where its drawing will find
     * them in cache.
     */
    public void resetByRows(double farthest) {
        resetTo = farthest;
        atFarPlane = false;
        owed = false;
    }

    /**
     * The reset owed, if one is ({@link #resetWhenNeeded}), to be made row by
     * row by whoever draws each row ({@link #resetRows}) before it tests any,
     * as {@link #resetByRows} has it: true when one was owed, false when every
     * entry already is at the far plane (nothing to reset). Called before any
     * drawing thread starts.
     */
    public boolean resetOwedByRows() {
        if (!owed) {
            return false;
        }
        owed = false;
        return true;
    }

    /** Rows from &lt;= y &lt; to back to the depth {@link #resetByRows} or {@link #resetWhenNeeded} gave. */
    public void resetRows(int from, int to) {
        Arrays.fill(depth, from * width, to * width, resetTo);
    }

    /** The depth every entry had after the last reset. */
    public double farthest() {
        return resetTo;
    }

    /** Some entry may now differ from the far plane. */
    public void written() {
        // Read before written: threads drawing bands call this for every span, and a
        // store each time would pull the line holding it from core to core.
        if (atFarPlane) {
            atFarPlane = false;
        }
    }

    /**
     * The raw depths, row by row from the bottom, for a stage that tests and
     * writes them itself, an owed reset made first ({@link #settle}).
     */
    public double[] depths() {
        settle();
        return depth;
    }

    /**
     * The raw depths for a stage whose user resets them ({@link #reset} or
     * {@link #resetByRows}) before it tests any, which replaces a reset
     * still owed: the lit fragment stage. Nothing owed is made here.
     */
    public double[] depthsToReset() {
        return depth;
    }

    /** True when no depth has been written since the last reset (and none is owed). */
    boolean atFarPlane() {
        return atFarPlane;
    }

    /** A copy of every depth, row by row (row y at y * width). */
    public double[] copyDepths() {
        settle();
        return depth.clone();
    }

    public double depthAt(int x, int y) {
        settle();
        return depth[y * width + x];
    }
}
