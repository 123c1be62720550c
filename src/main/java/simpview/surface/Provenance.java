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

    /** Every pixel back to the background; no primitive being drawn. */
    public void reset() {
        Arrays.fill(owner, BACKGROUND);
        Arrays.fill(current, BACKGROUND);
    }

    /** The writes from now on, on every row, are primitive {@code primitive}'s (0, 1, 2, ... in drawing order). */
    public void begin(int primitive) {
        Arrays.fill(current, primitive);
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
     * thread drawing that band calls it.
     */
    public void begin(int band, int primitive) {
        current[band] = primitive;
    }

    /** The primitive being drawn, as the last {@link #begin(int)} said (band 0's, when split into bands). */
    public int current() {
        return current[0];
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
