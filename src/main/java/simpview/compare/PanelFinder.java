package simpview.compare;

import java.util.Locale;

/**
 * Finds the 650x650 panel in a picture: a square whose one-pixel frame just
 * outside it is white (the margins) while its own outermost pixels are mostly
 * not (the black panel, whatever is drawn on it). The panel's content is
 * never looked at, so a page that is mostly white inside still is found by
 * its frame. A 750x750 picture is a page: its panel is at (50, 50) unless its
 * frame says clearly otherwise.
 */
final class PanelFinder {

    static final int PAGE = 750;
    static final int PAGE_MARGIN = 50;
    /** A channel at least this bright counts as white (JPEG captures are not exactly 255). */
    private static final int WHITE_LEVEL = 200;
    /**
     * How far from white a JPEG's margin pixel may be and still count as white: the same slack that finds its panel
     * ({@link #WHITE_LEVEL}), for a JPEG's noise leaves near-white pixels in white margins, even at high quality.
     */
    static final int JPEG_SLACK = 255 - WHITE_LEVEL;
    /** Each side of the frame outside the panel must be at least this white. */
    private static final double FRAME_WHITE = 0.9;
    /** The panel's own outermost pixels must be at least this much not white. */
    private static final double BORDER_DARK = 0.25;
    /** The sizes a page comes in, and what each is; a picture of one of their shapes at another size was scaled. */
    private static final int[][] SIZES = {{PAGE, PAGE}, {872, 782}};
    private static final String[] SIZE_NAMES = {"a 750x750 page", "a 872x782 window capture of a page"};

    private final int[] rgb;
    private final int width;
    private final int height;
    /** rowWhite[y * (width + 1) + x]: white pixels in row y left of column x; null until a search needs it. */
    private int[] rowWhite;
    /** colWhite[y * width + x]: white pixels in column x above row y (row-major, so it fills in order). */
    private int[] colWhite;

    private PanelFinder(int[] rgb, int width, int height) {
        this.rgb = rgb;
        this.width = width;
        this.height = height;
    }

    /** Counts of white pixels along every row and column, so that a search tries each place in constant time. */
    private void countWhite() {
        rowWhite = new int[height * (width + 1)];
        colWhite = new int[(height + 1) * width];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int white = isWhite(rgb[y * width + x]) ? 1 : 0;
                rowWhite[y * (width + 1) + x + 1] = rowWhite[y * (width + 1) + x] + white;
                colWhite[(y + 1) * width + x] = colWhite[y * width + x] + white;
            }
        }
    }

    /** The panel's place in a picture of {@code rgb} pixels (row by row), or a clear refusal. */
    static PanelPlace find(int[] rgb, int width, int height, String name) throws CompareException {
        int size = PanelPlace.SIZE;
        if (width < size || height < size) {
            throw new CompareException(name + " is " + width + "x" + height
                    + ": too small to hold the 650x650 panel (a page is 750x750)");
        }
        if (width == size && height == size) {
            return new PanelPlace(0, 0, "the whole 650x650 picture is the panel");
        }
        PanelFinder finder = new PanelFinder(rgb, width, height);
        if (width == PAGE && height == PAGE) {
            if (finder.score(PAGE_MARGIN, PAGE_MARGIN) >= 0) {
                return new PanelPlace(PAGE_MARGIN, PAGE_MARGIN, "a 750x750 page");
            }
            PanelPlace found = finder.search();
            return found != null ? new PanelPlace(found.left(), found.top(),
                    "a 750x750 page, but its panel's white frame is here, not at x 50, y 50")
                    : new PanelPlace(PAGE_MARGIN, PAGE_MARGIN, "a 750x750 page; no white frame around its panel");
        }
        PanelPlace found = finder.search();
        if (found == null) {
            throw new CompareException("no 650x650 panel found in " + name + " (" + width + "x" + height
                    + "): looked for a square with white margins around it and a dark edge inside"
                    + scaled(width, height));
        }
        return new PanelPlace(found.left(), found.top(), "found in a " + width + "x" + height + " picture");
    }

    /**
     * Whether the picture holds a 650x650 panel framed by white margins (found where {@link #find} would find it,
     * not taken on trust from a 750x750 picture's size) that is one panel: not split down its middle by a white
     * gutter, as the first assignment's page of four panels is.
     */
    static boolean holdsOnePanel(int[] rgb, int width, int height) {
        if (width < PanelPlace.SIZE || height < PanelPlace.SIZE) {
            return false;
        }
        PanelPlace found = new PanelFinder(rgb, width, height).search();
        if (found == null) {
            return false;
        }
        int middle = found.left() + PanelPlace.SIZE / 2;
        int white = 0;
        for (int y = found.top(); y < found.top() + PanelPlace.SIZE; y++) {
            white += isWhite(rgb[y * width + middle]) ? 1 : 0;
        }
        return white < FRAME_WHITE * PanelPlace.SIZE;
    }

    /** For a picture the size of a page or capture scaled, a sentence that says so; else "". */
    static String scaled(int width, int height) {
        for (int k = 0; k < SIZES.length; k++) {
            double ratio = (double) width / SIZES[k][0];
            if (width != SIZES[k][0] && Math.abs(height - ratio * SIZES[k][1]) <= 0.01 * height) {
                return String.format(Locale.ROOT, "; it has the shape of %s, scaled by %.3g: save the "
                        + "picture at its own size (1:1, no scaling)", SIZE_NAMES[k], ratio);
            }
        }
        return "";
    }

    /** The best place that qualifies, or null. */
    private PanelPlace search() {
        countWhite();
        int size = PanelPlace.SIZE;
        int bestScore = -1;
        PanelPlace best = null;
        for (int top = 1; top + size < height; top++) {
            for (int left = 1; left + size < width; left++) {
                int score = score(left, top);
                if (score > bestScore) {
                    bestScore = score;
                    best = new PanelPlace(left, top, "");
                }
            }
        }
        return best;
    }

    /**
     * White pixels of the frame outside plus dark pixels of the border inside,
     * or -1 when some side of the frame is not white enough or the border is
     * not dark enough (or the frame does not fit in the picture).
     */
    private int score(int left, int top) {
        int size = PanelPlace.SIZE;
        int right = left + size;
        int bottom = top + size;
        if (left < 1 || top < 1 || right >= width || bottom >= height) {
            return -1;
        }
        int need = (int) Math.ceil(FRAME_WHITE * size);
        int above = row(top - 1, left, right);
        int below = row(bottom, left, right);
        int before = column(left - 1, top, bottom);
        int after = column(right, top, bottom);
        if (above < need || below < need || before < need || after < need) {
            return -1;
        }
        int topWhite = row(top, left, right);
        int bottomWhite = row(bottom - 1, left, right);
        int leftWhite = column(left, top + 1, bottom - 1);
        int rightWhite = column(right - 1, top + 1, bottom - 1);
        if (topWhite == size || bottomWhite == size || leftWhite == size - 2 || rightWhite == size - 2) {
            // A side of the square white throughout is margin, not panel: a scaled page's smaller panel
            // framed with margin on two sides, say; a panel's drawing does not fill a whole edge in white.
            return -1;
        }
        int borderWhite = topWhite + bottomWhite + leftWhite + rightWhite;
        int border = 4 * size - 4;
        int dark = border - borderWhite;
        if (dark < BORDER_DARK * border) {
            return -1;
        }
        return above + below + before + after + dark;
    }

    private int row(int y, int from, int to) {
        if (rowWhite != null) {
            return rowWhite[y * (width + 1) + to] - rowWhite[y * (width + 1) + from];
        }
        int white = 0;
        for (int x = from; x < to; x++) {
            white += isWhite(rgb[y * width + x]) ? 1 : 0;
        }
        return white;
    }

    private int column(int x, int from, int to) {
        if (colWhite != null) {
            return colWhite[to * width + x] - colWhite[from * width + x];
        }
        int white = 0;
        for (int y = from; y < to; y++) {
            white += isWhite(rgb[y * width + x]) ? 1 : 0;
        }
        return white;
    }

    static boolean isWhite(int rgb) {
        return (rgb >> 16 & 0xFF) >= WHITE_LEVEL && (rgb >> 8 & 0xFF) >= WHITE_LEVEL && (rgb & 0xFF) >= WHITE_LEVEL;
    }
}
