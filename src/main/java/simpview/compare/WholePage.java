package simpview.compare;

/**
 * A page of four panels, two by two, turned as a whole: upside down (its
 * image's rows taken as the course's y, as a student's program does that
 * draws row = y), mirrored, turned half round or transposed. Each of its
 * panels then holds another panel's picture turned, which no panel's own
 * hint says; so the four are put side by side, as on the page but without
 * the margins between them (a turn of the page maps that square onto
 * itself, as it maps the page), and looked at as one panel
 * ({@link SystematicError}). A page only moved, or with red and blue swapped,
 * is left to each panel's own hint, which says the same.
 *
 * @param error what the square of the four panels is
 * @param pageSide the page's side, in pixels, margins included
 */
public record WholePage(SystematicError error, int pageSide) implements PanelHint {

    /** A page of four n x n panels, {@code pageSide} pixels a side, that is simpview's turned, or null. */
    static WholePage find(int[][] ours, int[][] theirs, int n, int pageSide, int tolerance) {
        if (ours.length != 4 || theirs.length != 4) {
            return null;
        }
        SystematicError found = SystematicError.find(square(ours, n), square(theirs, n), 2 * n, tolerance);
        return found == null || found.turn() == SystematicError.Turn.NONE ? null : new WholePage(found, pageSide);
    }

    /** Panels 1 to 4 side by side, two by two, row by row from the top: a 2n x 2n panel. */
    private static int[] square(int[][] panels, int n) {
        int side = 2 * n;
        int[] out = new int[side * side];
        for (int k = 0; k < 4; k++) {
            int left = k % 2 * n;
            int top = k / 2 * n;
            for (int y = 0; y < n; y++) {
                System.arraycopy(panels[k], y * n, out, (top + y) * side + left, n);
            }
        }
        return out;
    }

    @Override
    public double shareThere() {
        return error.shareThere();
    }

    @Override
    public boolean wholePage() {
        return true;
    }

    @Override
    public String brief() {
        return "like simpview's whole page " + error.brief();
    }

    /** The hint, its advice for the page's rows (the page's y runs up from its bottom-left pixel); n is a panel's side. */
    @Override
    public String hint(int n) {
        return error.hint(pageSide, "page");
    }
}
