package simpview.compare;

/**
 * Where the 650x650 panel lies in a picture: its top-left pixel, in the
 * picture's own coordinates (x right, y down), and how it was found.
 *
 * @param left column of the panel's leftmost pixels
 * @param top row of the panel's topmost pixels
 * @param how e.g. "a 750x750 page" or "found in an 872x782 picture"
 */
public record PanelPlace(int left, int top, String how) {

    public static final int SIZE = 650;

    /** E.g. "x 51-700, y 81-730 of the picture (found in an 872x782 picture)". */
    public String describe() {
        return "x " + left + "-" + (left + SIZE - 1) + ", y " + top + "-" + (top + SIZE - 1)
                + " of the picture, counted from its top-left (" + how + ")";
    }
}
