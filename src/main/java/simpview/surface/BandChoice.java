package simpview.surface;

/**
 * Whether a recorded batch of primitives is drawn split into bands, by all
 * the threads, or as one band, by the thread that draws: the rule for a
 * picture whose thread count the user did not give ({@link DrawingThreads#upTo}).
 * A count the user gave ({@link DrawingThreads#of}) is always used as it is.
 *
 * <p>The rule looks at what the batch will cost, from two numbers the record
 * keeps as it is filled: how many primitives it holds, and about how many
 * pixels they cover (each filled polygon's area, each line's length in
 * pixels, in panel coordinates; see {@link #pixels}). A band pays for every
 * primitive that touches it (the row test, the triangle's set-up, the shader
 * made for the band) and splitting the panel into bands wins only where the
 * pixels are the work. The course's pages fall into two groups far apart:
 * the filled pages (A3 C to H, A4's pages but d) cover 300 to 20,000 pixels
 * a primitive, where two threads draw 1.5-1.9 times as fast; the pages of
 * the dummy model's 28,716 faces (A3 pageI, A4 page-d) cover 3 to 11, where
 * two threads were slower than one. The line between them is drawn at
 * {@link #PIXELS_PER_PRIMITIVE}; a batch of fewer than {@link #LEAST_PIXELS}
 * pixels is not worth waking a second thread for.
 *
 * <p>The choice is about speed alone: a picture is the same to the bit drawn
 * in any number of bands (see {@link RowBands}).
 */
public final class BandChoice {

    /**
     * Primitives in a scene's first batch: it is judged and drawn when this
     * many are recorded (or at the end of a smaller scene), and when it is
     * drawn whole the rest of the scene is drawn as it is read, by one thread,
     * not recorded at all (the recording costs a small-face page some 20 %).
     */
    public static final int FIRST_BATCH = 1024;
    /** Batches covering fewer pixels a primitive than this are drawn as one band. */
    public static final double PIXELS_PER_PRIMITIVE = 30;
    /** Batches covering fewer pixels than this in all are drawn as one band. */
    public static final double LEAST_PIXELS = 50_000;

    private BandChoice() {
    }

    /**
     * True when a batch of {@code primitives} covering about {@code pixels}
     * pixels is best split into bands drawn by {@code threads}: always when the
     * user gave the count and it is more than one; by the rule above when the
     * count is chosen per picture; never on one thread.
     */
    public static boolean splits(DrawingThreads threads, int primitives, double pixels) {
        if (threads.isOne()) {
            return false;
        }
        if (!threads.choosesPerPicture()) {
            return true;
        }
        return pixels >= LEAST_PIXELS && pixels >= PIXELS_PER_PRIMITIVE * primitives;
    }

    /**
     * About how many pixels a primitive covers, for {@link #splits}: a filled
     * polygon's area (the shoelace formula over its n corners, x and y at
     * {@code v[at + k * stride + x]} and {@code ... + x + 1}), and for lines
     * ({@code filled} false) the length in pixels of its n - 1 edges, or of
     * all n when {@code closed} (an outline).
     */
    public static double pixels(double[] v, int at, int n, int stride, boolean filled, boolean closed) {
        double sum = 0;
        int edges = closed || filled ? n : n - 1;
        for (int k = 0; k < edges; k++) {
            int i = at + k * stride;
            int j = at + ((k + 1) % n) * stride;
            double x0 = v[i];
            double y0 = v[i + 1];
            double x1 = v[j];
            double y1 = v[j + 1];
            sum += filled ? x0 * y1 - x1 * y0 : Math.max(Math.abs(x1 - x0), Math.abs(y1 - y0)) + 1;
        }
        return filled ? Math.abs(sum) / 2 : sum;
    }
}
