package simpview.surface;

/**
 * Whether a recorded batch of primitives is drawn split into bands, by all
 * the threads, or as one band, by the thread that draws: the rule for a
 * picture whose thread count the user did not give ({@link DrawingThreads#upTo},
 * the default of the window, {@code render}, {@code compare} and {@code check}).
 * A count the user gave ({@code --threads N}, {@link DrawingThreads#of}) is
 * always used as it is.
 *
 * <p>The rule looks at what the batch will cost, from two numbers the record
 * keeps as it is filled: how many primitives it holds, and about how many
 * pixels they cover ({@link #pixels}: each filled polygon's area, each line's
 * length in pixels). A band pays for every primitive that may touch it (the
 * row test, the triangle's set-up, the shader made for the band), and the
 * recording costs every primitive a copy, so bands win only where the pixels
 * are the work. The course's pages, turned as the orbit turns them, fall
 * into two groups: the dummy model's pages (A3 pageI, A4 page-d) cover 11 to
 * 29 pixels a face (their first 1,024 faces, or a whole batch of 16,000),
 * and there two threads were slower than one; every other page's first
 * batch covers 43 (A4 page-g) to 7,750 (A3 pageG). The
 * line is drawn at {@link #PIXELS_PER_PRIMITIVE} = 30, and a batch of fewer
 * than {@link #LEAST_PIXELS} pixels in all is not worth a second thread.
 *
 * <p>A scene's first batch is judged when {@link #FIRST_BATCH} primitives are
 * recorded (or at its end, if it has fewer). Drawn whole, the rest of the
 * scene is drawn as it is read, not recorded at all: so a page of small faces
 * costs its one-thread time and one recorded batch. (With 1,024 primitives,
 * the first batch splits only when it covers 50,000 pixels: 49 a primitive.)
 *
 * <p>The choice is about speed alone: a picture is the same to the bit drawn
 * in any number of bands, or as it is read ({@link RowBands}).
 */
public final class BandChoice {

    /**
     * Primitives in a scene's first batch: it is judged and drawn when this
     * many are recorded (or at the end of a smaller scene), and when it is
     * drawn whole the rest of the scene is drawn as it is read, by one thread,
     * not recorded at all (recording the whole of A4 page-d and drawing it as
     * one band cost 21 % more than drawing it as read, as measured).
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
