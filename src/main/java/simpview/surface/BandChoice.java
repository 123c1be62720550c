package simpview.surface;

/**
 * Whether a recorded batch of primitives is drawn split into bands, by all
 * the threads, or as one band, by one of them: the rule for a picture whose
 * thread count the user did not give ({@link DrawingThreads#upTo}, the
 * default of the window, {@code render}, {@code compare} and {@code check}).
 * A count the user gave ({@code --threads N}, {@link DrawingThreads#of}) is
 * always used as it is.
 *
 * <p>Batches are drawn while the next ones are recorded ({@link BandQueue}):
 * one kept whole is drawn by one thread alone, beside the reading; one split
 * is drawn band by band by the workers, and by the reading thread whenever
 * it waits for a batch to fill. Splitting costs each band the row test
 * of every primitive and the set-up of every triangle that crosses into it,
 * which pays unless the batch is little work in all: a batch of fewer than
 * {@link #LEAST_PIXELS} pixels ({@link #pixels}: each filled polygon's
 * area, each line's length) is kept whole. Measured on the course's pages,
 * turned as the orbit turns them: even the dummy model's pages (A3 pageI,
 * A4 page-d, 11 to 29 pixels a face) draw faster split, once the geometry
 * stage runs beside the drawing (docs/performance.md, session 4).
 *
 * <p>The choice is about speed alone: a picture is the same to the bit drawn
 * in any number of bands, or as it is read ({@link RowBands}).
 */
public final class BandChoice {

    /** Batches covering fewer pixels than this in all are drawn as one band. */
    public static final double LEAST_PIXELS = 50_000;

    private BandChoice() {
    }

    /**
     * True when a batch covering about {@code pixels} pixels is best split
     * into bands drawn by {@code threads}: always when the user gave the
     * count and it is more than one; by the rule above when the count is
     * chosen per picture; never on one thread.
     */
    public static boolean splits(DrawingThreads threads, double pixels) {
        if (threads.isOne()) {
            return false;
        }
        if (!threads.choosesPerPicture()) {
            return true;
        }
        return pixels >= LEAST_PIXELS;
    }

    /**
     * About how many pixels a primitive covers, for {@link #splits}: a filled
     * polygon's area (the shoelace formula over its n corners, corner k's x
     * at {@code v[at + k * stride]} and its y next to it), and for lines
     * ({@code filled} false) the length in pixels of its n - 1 edges, or of
     * all n when {@code closed} (an outline).
     */
    public static double pixels(double[] v, int at, int n, int stride, boolean filled, boolean closed) {
        double sum = 0;
        int edges = closed || filled ? n : n - 1;
        for (int k = 0; k < edges; k++) {
            int i = at + k * stride;
            int j = k + 1 < n ? i + stride : at;
            double x0 = v[i];
            double y0 = v[i + 1];
            double x1 = v[j];
            double y1 = v[j + 1];
            sum += filled ? x0 * y1 - x1 * y0 : Math.max(Math.abs(x1 - x0), Math.abs(y1 - y0)) + 1;
        }
        return filled ? Math.abs(sum) / 2 : sum;
    }
}
