package simpview.surface;

import java.util.Arrays;

/**
 * One depth per pixel (world space for depth-cued scenes, camera space for lit
 * ones); larger z is nearer. Reset to the farthest depth of the picture: the
 * far plane, z = -200, for depth-cued scenes; -infinity for lit ones.
 *
 * <p>Whoever writes depths (a {@link ZBufferDrawable}, the lit fragment stage)
 * says which ({@link #written(int, int, int)}: a row and a run of it) before it
 * returns from a write. So the buffer knows when every entry is still at the
 * far plane, and a reset then costs nothing: the pages that draw without depth
 * (1 and 2) do not pay for filling 3.4 MB. And it knows, row by row, the run
 * outside which every entry still holds the depth that row was last reset to
 * ({@link #rowReset}): a reset to the same depth fills that run alone, so a
 * picture pays for the rows and columns the one before it wrote, not for the
 * whole panel (a model in the middle of the panel leaves most of it alone).
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
    /**
     * Row y's entries outside x from writtenFrom[y] to writtenTo[y] (excluded)
     * all hold rowReset[y], the depth the row was last reset to: the run is
     * empty (from = width, to = 0) after a reset, widened by every write. Each
     * row's three are read and written only by the thread drawing that row, or
     * the one resetting it.
     */
    private final int[] writtenFrom;
    private final int[] writtenTo;
    private final double[] rowReset;

    public ZBuffer(int width, int height) {
        this.width = width;
        this.height = height;
        this.depth = new double[width * height];
        this.writtenFrom = new int[height];
        this.writtenTo = new int[height];
        this.rowReset = new double[height];
        Arrays.fill(rowReset, Double.NaN); // no row holds a known depth yet: the first reset fills every entry
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
            resetTo = farthest;
            resetRows(0, height);
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
            resetRows(0, height);
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

    /**
     * Rows from &lt;= y &lt; to back to the depth {@link #resetByRows} or {@link #resetWhenNeeded} gave: of a
     * row last reset to that same depth, the run written since; of any other, every entry, the first such
     * row by a fill and the others as copies of it (as {@link ImageDrawable#fillRect}, for the interpreter and C1).
     */
    public void resetRows(int from, int to) {
        double farthest = resetTo;
        long bits = Double.doubleToLongBits(farthest);
        int filled = -1; // a row of this call filled whole with farthest, once there is one
        for (int y = from; y < to; y++) {
            int row = y * width;
            if (Double.doubleToLongBits(rowReset[y]) == bits) {
                if (writtenFrom[y] < writtenTo[y]) {
                    Arrays.fill(depth, row + writtenFrom[y], row + writtenTo[y], farthest);
                }
            } else {
                if (filled < 0) {
                    Arrays.fill(depth, row, row + width, farthest);
                    filled = row;
                } else {
                    System.arraycopy(depth, filled, depth, row, width);
                }
                rowReset[y] = farthest;
            }
            writtenFrom[y] = width;
            writtenTo[y] = 0;
        }
    }

    /** The depth every entry had after the last reset. */
    public double farthest() {
        return resetTo;
    }

    /**
     * Entries x from &lt;= x &lt; to of row y (inside the buffer) may now differ from the depth the row was
     * reset to: said by every write, before it returns.
     */
    public void written(int y, int from, int to) {
        // Read before written: threads drawing bands call this for every span, and a
        // store each time would pull the line holding it from core to core.
        if (atFarPlane) {
            atFarPlane = false;
        }
        if (from < writtenFrom[y]) {
            writtenFrom[y] = from;
        }
        if (to > writtenTo[y]) {
            writtenTo[y] = to;
        }
    }

    /**
     * The raw depths, row by row from the bottom, for a stage that tests and
     * writes them itself (and says which it wrote, {@link #written(int, int, int)}),
     * an owed reset made first ({@link #settle}).
     */
    public double[] depths() {
        settle();
        return depth;
    }

    /**
     * The raw depths for a stage whose user resets them ({@link #reset} or
     * {@link #resetByRows}) before it tests any, which replaces a reset
     * still owed: the lit fragment stage, which says which it wrote
     * ({@link #written(int, int, int)}). Nothing owed is made here.
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
