package simpview.compare;

/**
 * Colours one level off, all the same way: every pixel that differs is one
 * level darker than simpview's in each channel that differs, never
 * brighter (or the other way round). That is what a colour made a byte by
 * truncation, {@code (int) (c * 255)}, gives where SPEC rounds,
 * {@code round(c * 255) = floor(c * 255 + 0.5)}: about half of all pixels a
 * level darker, none brighter, the drawing itself right. Such a picture
 * passes within 1/255 and its patches are everywhere and nowhere, so the
 * shares alone do not say why it is not identical; this does.
 */
final class LevelBias {

    /** Below this share of the panel differing, a few ties rounded otherwise, nothing is said. */
    static final double MIN_SHARE = 0.01;

    private LevelBias() {
    }

    /**
     * The note (after "note: ") on theirs against ours, two panels of
     * 0xRRGGBB pixels, or null when the pixels that differ are not all one
     * level off the same way, or too few of them do.
     */
    static String note(int[] ours, int[] theirs) {
        long differing = 0;
        boolean darker = false;
        boolean brighter = false;
        for (int i = 0; i < ours.length; i++) {
            int a = ours[i];
            int b = theirs[i];
            if ((a & 0xFFFFFF) == (b & 0xFFFFFF)) {
                continue;
            }
            differing++;
            for (int shift = 0; shift <= 16; shift += 8) {
                int d = (b >> shift & 0xFF) - (a >> shift & 0xFF);
                if (d == -1) {
                    darker = true;
                } else if (d == 1) {
                    brighter = true;
                } else if (d != 0) {
                    return null;
                }
            }
            if (darker && brighter) {
                return null;
            }
        }
        if (differing == 0 || differing < MIN_SHARE * ours.length) {
            return null;
        }
        String share = Percent.of((double) differing / ours.length);
        return darker
                ? "every pixel that differs (" + share + " of the panel) is one level darker than simpview's, in each"
                        + " channel that differs, never brighter: a colour made a byte by truncation, (int) (c * 255),"
                        + " where SPEC rounds, round(c * 255) = floor(c * 255 + 0.5), does this"
                : "every pixel that differs (" + share + " of the panel) is one level brighter than simpview's, in"
                        + " each channel that differs, never darker: a colour made a byte by rounding up, ceil(c * 255),"
                        + " where SPEC rounds, round(c * 255) = floor(c * 255 + 0.5), does this";
    }
}
