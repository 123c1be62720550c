package simpview.compare;

/**
 * A depth cue run the wrong way: near and far swapped, or z's share taken
 * from the wrong end ({@code -z / 200} for {@code (z + 200) / 200}). SPEC's
 * cue writes {@code c = far + (near - far) * s}; the other way round writes
 * {@code near + (far - near) * s}, which is {@code near + far - c}, so wherever both
 * pictures draw, simpview's colour and yours add up to one sum in each
 * channel, near + far (white on a page of white lines: 255). Every shape is
 * in place, near things dark and far ones bright, and the patches cover the
 * whole drawing; this names it. Pixels black in either picture (the
 * background, or a colour cued to black) say nothing and are left out.
 */
final class ReversedCue {

    /** Below this share of the panel differing beyond the tolerance, nothing is said. */
    static final double MIN_DIFFERING = 0.01;
    /** The least share of the differing pixels drawn (not black) in both pictures. */
    static final double MIN_DRAWN = 0.5;
    /** The least share of those whose sum is the most common one, each channel within the tolerance. */
    static final double MIN_EXPLAINED = 0.9;

    private ReversedCue() {
    }

    /**
     * The note (after "note: ") on the comparison's picture against simpview's, or null when too few pixels
     * differ, too few of them are drawn in both, or no one sum explains {@link #MIN_EXPLAINED} of those.
     */
    static String note(Comparison comparison, int tolerance) {
        if (1 - comparison.share(tolerance, false) < MIN_DIFFERING) {
            return null; // counted already: no pass over the pixels
        }
        int[] ours = comparison.ours();
        int[] theirs = comparison.theirs();
        long differing = 0;
        long drawn = 0;
        int[][] sums = new int[3][511];
        for (int i = 0; i < ours.length; i++) {
            int a = ours[i] & 0xFFFFFF;
            int b = theirs[i] & 0xFFFFFF;
            if (comparison.distance(i) <= tolerance) {
                continue;
            }
            differing++;
            if (a == 0 || b == 0) {
                continue;
            }
            drawn++;
            for (int c = 0; c < 3; c++) {
                sums[c][(a >> 8 * c & 0xFF) + (b >> 8 * c & 0xFF)]++;
            }
        }
        if (drawn < MIN_DRAWN * differing) {
            return null;
        }
        int[] sum = new int[3];
        for (int c = 0; c < 3; c++) {
            for (int s = 1; s < 511; s++) {
                sum[c] = sums[c][s] > sums[c][sum[c]] ? s : sum[c];
            }
        }
        long explained = 0;
        for (int i = 0; i < ours.length; i++) {
            int a = ours[i] & 0xFFFFFF;
            int b = theirs[i] & 0xFFFFFF;
            if (a == 0 || b == 0 || comparison.distance(i) <= tolerance) {
                continue;
            }
            boolean fits = true;
            for (int c = 0; c < 3 && fits; c++) {
                fits = Math.abs((a >> 8 * c & 0xFF) + (b >> 8 * c & 0xFF) - sum[c]) <= tolerance;
            }
            explained += fits ? 1 : 0;
        }
        if (explained < MIN_EXPLAINED * drawn) {
            return null;
        }
        return "your colours look simpview's turned end for end: of the " + Count.of(drawn, "pixel") + " that differ"
                + " by more than " + tolerance + "/255 and are drawn in both, " + Percent.of((double) explained / drawn)
                + " have yours + simpview's = (" + sum[2] + "," + sum[1] + "," + sum[0] + ") within " + tolerance
                + "/255, as a depth cue run the wrong way gives (near + far - c: near and far swapped). SPEC's cue"
                + " is far + (near - far) * (z + 200) / 200: the near colour at z = 0, the far colour at z = -200";
    }
}
