package simpview.compare;

/**
 * A panel without colour where simpview's has some: every pixel of the picture's panel is a shade of grey (its
 * red, green and blue at most {@link #GREY_SPREAD} levels apart) while at least {@link #MIN_SHARE} of simpview's
 * pixels are coloured (their channels further apart than the tolerance). A page saved in greyscale, or a renderer
 * that writes one channel into all three, fails with nothing else to say why: its shapes are where simpview's are,
 * its colours all wrong. Said of a picture that fails, by {@code compare} of one picture, a batch and {@code check}
 * in the same words. A panel of one colour throughout (black: nothing drawn in it) is not said to have no colour:
 * saving it in colour would change nothing.
 */
public final class Colourless {

    /** Below this share of simpview's panel coloured (a page of white lines on black), nothing is said. */
    static final double MIN_SHARE = 0.01;
    /** The most a grey pixel's channels may differ: a JPEG's rounding leaves a grey a level or two apart. */
    static final int GREY_SPREAD = 2;

    /** The note, after "note: ", whole. */
    public static final String NOTE = "your picture has no colour: every pixel of its panel is a shade of grey, where "
            + "simpview's panel is coloured; was it saved in greyscale, or does your renderer write one channel into "
            + "all three? Save it in colour (RGB) and compare again";
    /** The same briefly, for a table's note column and a progress line. */
    public static final String BRIEF = "no colour: every pixel is grey where simpview's are coloured; save it in "
            + "colour (RGB)";

    private Colourless() {
    }

    /**
     * {@link #NOTE} of theirs against ours, two panels of 0xRRGGBB pixels, when theirs is grey throughout and ours is
     * coloured beyond {@code tolerance} on at least {@link #MIN_SHARE} of its pixels, and theirs holds more than
     * one colour; null otherwise.
     */
    public static String note(int[] ours, int[] theirs, int tolerance) {
        long coloured = 0;
        boolean flat = true;
        for (int i = 0; i < ours.length; i++) {
            if (spread(theirs[i]) > GREY_SPREAD) {
                return null;
            }
            if (spread(ours[i]) > tolerance) {
                coloured++;
            }
            flat &= theirs[i] == theirs[0];
        }
        return ours.length > 0 && !flat && coloured >= MIN_SHARE * ours.length ? NOTE : null;
    }

    /** How far apart a pixel's channels are: 0 for a grey. */
    private static int spread(int rgb) {
        int r = rgb >> 16 & 0xFF;
        int g = rgb >> 8 & 0xFF;
        int b = rgb & 0xFF;
        return Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b));
    }
}
