package simpview.compare;

/**
 * Two 650x650 panels compared pixel by pixel. A pixel's distance is the
 * largest difference of one channel (0 to 255). Its distance with slack is
 * the smaller one found when either picture may take its colour from one
 * pixel away: the larger of (ours against the nearest match among theirs'
 * 3x3 neighbours) and (theirs against ours' 3x3 neighbours). Both ways, so a
 * line one pixel off passes and a line missing from either side does not.
 *
 * <p>Invariant: slack[i] <= direct[i]. The pixels are read, never kept
 * changed; the arrays here are the only ones made.
 */
public final class Comparison {

    public static final int N = PanelPlace.SIZE;
    private static final int LEVELS = 256;

    private final int[] ours;
    private final int[] theirs;
    private final byte[] direct = new byte[N * N];
    private final byte[] slack = new byte[N * N];
    private final int[] directCount = new int[LEVELS];
    private final int[] slackCount = new int[LEVELS];

    private Comparison(int[] ours, int[] theirs) {
        this.ours = ours;
        this.theirs = theirs;
    }

    /** Compares two panels of 650x650 0xRRGGBB pixels, row by row from the top. */
    public static Comparison of(int[] ours, int[] theirs) {
        if (ours.length != N * N || theirs.length != N * N) {
            throw new IllegalArgumentException("panels are 650x650 pixels");
        }
        Comparison c = new Comparison(ours, theirs);
        c.measure();
        return c;
    }

    private void measure() {
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                int i = y * N + x;
                int d = Rasters.distance(ours[i], theirs[i]);
                int s = d == 0 ? 0 : Math.max(nearest(ours[i], theirs, x, y, d), nearest(theirs[i], ours, x, y, d));
                direct[i] = (byte) d;
                slack[i] = (byte) s;
                directCount[d]++;
                slackCount[s]++;
            }
        }
    }

    /** The smallest distance from {@code colour} to a pixel of {@code other} in the 3x3 around (x, y), at most {@code bound}. */
    private static int nearest(int colour, int[] other, int x, int y, int bound) {
        int best = bound;
        for (int ny = Math.max(0, y - 1); ny <= Math.min(N - 1, y + 1); ny++) {
            for (int nx = Math.max(0, x - 1); nx <= Math.min(N - 1, x + 1); nx++) {
                best = Math.min(best, Rasters.distance(colour, other[ny * N + nx]));
                if (best == 0) {
                    return 0;
                }
            }
        }
        return best;
    }

    /** The share of panel pixels within {@code tolerance} (0 to 255) in every channel, with or without slack. */
    public double share(int tolerance, boolean withSlack) {
        int[] counts = withSlack ? slackCount : directCount;
        long within = 0;
        for (int level = 0; level <= Math.min(tolerance, LEVELS - 1); level++) {
            within += counts[level];
        }
        return (double) within / (N * N);
    }

    public Shares exact() {
        return new Shares(share(0, false), share(1, false), share(8, false));
    }

    public Shares withSlack() {
        return new Shares(share(0, true), share(1, true), share(8, true));
    }

    /** Pixel i's distance, 0 to 255, without slack. i = row from the top * 650 + column. */
    public int distance(int i) {
        return direct[i] & 0xFF;
    }

    /** Pixel i's distance with one pixel of slack. */
    public int distanceWithSlack(int i) {
        return slack[i] & 0xFF;
    }

    public int[] ours() {
        return ours;
    }

    public int[] theirs() {
        return theirs;
    }
}
