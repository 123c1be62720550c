package simpview.compare;

/**
 * Edges a pixel off: pixels that differ beyond the tolerance as they stand
 * but match with slack (yellow in the heat map) on a share of the panel that
 * the course's own pictures never reach, and which neighbour of simpview's
 * each such pixel has the colour of. A renderer whose fills take the pixels
 * on the other side of an edge (the top-left rule ignored, or x's rounded up
 * where SPEC's pixel centres round otherwise) lights a pixel beside each of
 * simpview's edges: with slack it passes, and without this nothing says so.
 * Only pixels by a step of simpview's own colours count: where its colours
 * change smoothly, theirs a few levels off matches a neighbour as well.
 */
final class EdgeShift {

    /**
     * Below this share of the panel, nothing is said: the course's own pictures have at most 0.75 % (pageF of the
     * third assignment), its depth cue and its few rounding ties.
     */
    static final double MIN_SHARE = 0.01;
    /** A side is named when at least this share of the pixels has its neighbour's colour ... */
    static final double SIDE_SHARE = 0.25;
    /** ... and at least this many times as many as have the opposite neighbour's. */
    static final int SIDE_RATIO = 4;

    private EdgeShift() {
    }

    /**
     * The note (after "note: ") of the comparison within {@code tolerance}, or null when too few pixels are a pixel
     * off, or the comparison has no slack.
     */
    static String note(Comparison comparison, int tolerance) {
        if (comparison.deviation() == 0 || comparison.metric() != Comparison.Metric.EXACT) {
            return null;
        }
        int n = comparison.size();
        int[] ours = comparison.ours();
        int[] theirs = comparison.theirs();
        int off = 0;
        int left = 0;
        int right = 0;
        int above = 0;
        int below = 0;
        for (int row = 0; row < n; row++) {
            for (int x = 0; x < n; x++) {
                int i = row * n + x;
                if (comparison.distance(i) <= tolerance || comparison.distanceWithSlack(i) > tolerance) {
                    continue;
                }
                int colour = theirs[i];
                if (!besideStep(ours, n, x, row, colour, tolerance)) {
                    continue;
                }
                off++;
                // a neighbour counts only when the one opposite it does not match too: on a smooth shading both
                // would, and say nothing of a side
                boolean l = x > 0 && Rasters.distance(colour, ours[i - 1]) <= tolerance;
                boolean r = x < n - 1 && Rasters.distance(colour, ours[i + 1]) <= tolerance;
                boolean a = row > 0 && Rasters.distance(colour, ours[i - n]) <= tolerance;
                boolean b = row < n - 1 && Rasters.distance(colour, ours[i + n]) <= tolerance;
                left += l && !r ? 1 : 0;
                right += r && !l ? 1 : 0;
                above += a && !b ? 1 : 0;
                below += b && !a ? 1 : 0;
            }
        }
        if (off < MIN_SHARE * n * n) {
            return null;
        }
        String across = side(left, right, off, "to the right of", "to the left of");
        String down = side(above, below, off, "below", "above");
        String sides = across == null ? down : down == null ? across : across + " and " + down;
        return Percent.of((double) off / (n * n)) + " of the panel differs by more than " + tolerance + "/255 as it "
                + "stands but matches with slack (yellow in the heat map): edges a pixel off. Of those pixels, yours has"
                + " the colour of simpview's pixel to its left (not its right) at " + Percent.of((double) left / off) + ", to its right (not its left) at "
                + Percent.of((double) right / off) + ", above it (not below) at " + Percent.of((double) above / off)
                + ", below it (not above) at " + Percent.of((double) below / off)
                + (sides == null ? "" : ": your edges lie a pixel " + sides + " simpview's")
                + ". Check which pixels your fills take along an edge: pixel centres and the top-left rule (SPEC,"
                + " Rasterization rules)";
    }

    /**
     * Whether {@code colour}, theirs at (x, row), is that of a neighbour of simpview's pixel there whose own colour
     * steps away from it by more than the tolerance: an edge of simpview's picture, which theirs has moved. On a smooth
     * shading (a gradient of a few levels a pixel) a colour a little off, a light's term or the fog left out, is a
     * neighbour's colour too, with no edge there: a term missing, not an edge moved (page-c3 without its ambient
     * light had 3.51 % of the panel so, and was told to check the top-left rule).
     */
    private static boolean besideStep(int[] ours, int n, int x, int row, int colour, int tolerance) {
        int own = ours[row * n + x];
        for (int r = Math.max(0, row - 1); r <= Math.min(n - 1, row + 1); r++) {
            for (int c = Math.max(0, x - 1); c <= Math.min(n - 1, x + 1); c++) {
                int neighbour = ours[r * n + c];
                if (Rasters.distance(colour, neighbour) <= tolerance && Rasters.distance(own, neighbour) > tolerance) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * The side an edge lies on when the neighbour on one side ({@code one}) explains many pixels and that on the
     * other ({@code other}) few: {@code oneWords}, {@code otherWords} the other way round; or null.
     */
    private static String side(int one, int other, int off, String oneWords, String otherWords) {
        if (one >= SIDE_SHARE * off && one >= SIDE_RATIO * other) {
            return oneWords;
        }
        if (other >= SIDE_SHARE * off && other >= SIDE_RATIO * one) {
            return otherWords;
        }
        return null;
    }
}
