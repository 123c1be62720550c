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
    int current = BACKGROUND;

    public Provenance(int width, int height) {
        this.width = width;
        this.height = height;
        this.owner = new int[width * height];
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
        current = BACKGROUND;
    }

    /** The writes from now on are primitive {@code primitive}'s (0, 1, 2, ... in drawing order). */
    public void begin(int primitive) {
        current = primitive;
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
