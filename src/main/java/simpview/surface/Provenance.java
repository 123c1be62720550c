package simpview.surface;

import java.util.Arrays;

/**
 * Who drew each panel pixel: the number of the primitive whose write a pixel
 * shows now, or {@link #BACKGROUND}. Filled by a {@link ProvenanceDrawable}
 * placed after the z-buffer, so it sees only the writes that won; whoever
 * draws says which primitive is being drawn with {@link #begin}.
 */
public final class Provenance {

    /** No primitive wrote the pixel. */
    public static final int BACKGROUND = -1;

    private final int width;
    private final int height;
    final int[] owner;
    /** The primitive being read: the owner of what is drawn for it, as {@link #begin(int)} said. */
    private int reading = BACKGROUND;
    /**
     * False while the scene is drawn as it is read: then {@link #begin(int)}
     * says what is being drawn, on every row. True once its primitives are
     * recorded and drawn later ({@link #drawnFromRecords}): then only the
     * drawers say it, band by band ({@link #begin(int, int)}), while the
     * reading thread goes on with later primitives.
     */
    private boolean recorded;
    /**
     * The primitive being drawn, one per band of rows: each band's thread
     * says which of its primitives it draws (see {@link #begin(int, int)}).
     * One band, all rows, until {@link #useBands} splits them.
     */
    private int[] current = {BACKGROUND};
    /** The index in current of each row's band. */
    private int[] bandOfRow;

    public Provenance(int width, int height) {
        this.width = width;
        this.height = height;
        this.owner = new int[width * height];
        this.bandOfRow = new int[height];
        reset();
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Every pixel back to the background; no primitive being read or drawn; drawn as read again. */
    public void reset() {
        Arrays.fill(owner, BACKGROUND);
        reading = BACKGROUND;
        recorded = false;
        current = new int[] {BACKGROUND};
        Arrays.fill(bandOfRow, 0);
    }

    /**
     * Primitive {@code primitive} (0, 1, 2, ... in drawing order) is being
     * read: what is drawn for it from now on is its, on every row, unless the
     * scene is drawn from records (then the drawers say so).
     */
    public void begin(int primitive) {
        reading = primitive;
        if (!recorded) {
            Arrays.fill(current, primitive);
        }
    }

    /**
     * From now on, until {@link #reset}, the scene's primitives are recorded
     * as they are read and drawn later, by drawers that say which one they
     * draw ({@link #begin(int, int)}); {@link #begin(int)} then only says
     * which is being read. Call while nothing is being drawn.
     */
    public void drawnFromRecords() {
        recorded = true;
    }

    /**
     * From now on each band of {@code bands} has its own primitive being
     * drawn, so that threads drawing different bands may say so at once.
     * Call while nothing is being drawn; each band starts at the background.
     */
    public void useBands(RowBands bands) {
        if (bands.rows() != height) {
            throw new IllegalArgumentException(bands.rows() + " rows of bands for a record of " + height);
        }
        current = new int[bands.count()];
        Arrays.fill(current, BACKGROUND);
        for (int y = 0; y < height; y++) {
            bandOfRow[y] = bands.bandOf(y);
        }
    }

    /**
     * The writes from now on to the rows of band {@code band} (of those
     * given to {@link #useBands}) are primitive {@code primitive}'s. Only the
     * thread drawing those rows calls it, while no other draws.
     */
    public void begin(int band, int primitive) {
        current[band] = primitive;
    }

    /**
     * The primitive a write to row y would be recorded as now: what a stage
     * that writes the pixel later ({@code FragmentStage.shadeLater}) keeps.
     */
    public int drawingAt(int y) {
        return currentAt(y);
    }

    /**
     * The writes from now on to the rows of row y's band are primitive
     * {@code primitive}'s: as {@link #begin(int, int)} for that band, by the
     * thread drawing it (a stage writing late what it kept from earlier).
     */
    public void beginAt(int y, int primitive) {
        current[bandOfRow[y]] = primitive;
    }

    /** The primitive being read, as the last {@link #begin(int)} said: the owner a record gives what it records. */
    public int current() {
        return reading;
    }

    /** The primitive being drawn on row y, 0 &lt;= y &lt; height. */
    int currentAt(int y) {
        return current[bandOfRow[y]];
    }

    /** The primitive that drew (x, y) in the drawable's coordinates, or {@link #BACKGROUND}. */
    public int ownerAt(int x, int y) {
        return owner[y * width + x];
    }

    /** A copy of every pixel's owner, row by row (row y at y * width). */
    public int[] copyOwners() {
        return owner.clone();
    }
}
