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
    /**
     * The plain scales screens and screenshot tools draw at (a HiDPI screen's 2x, a desktop at 125 % or 150 %, a
     * capture saved at half size), at which a picture without a panel at 1:1 is searched for the panel drawn larger
     * or smaller, by the same evidence measured at that scale.
     */
    private static final double[] SCALES = {2, 1.5, 1.25, 1.75, 2.5, 3, 4, 0.5, 0.75, 0.8, 2.0 / 3};

    private final int[] rgb;
    private final int width;
    private final int height;
    /** rowWhite[y * (width + 1) + x]: white pixels in row y left of column x; null until a search needs it. */
    private int[] rowWhite;
    /** colWhite[y * width + x]: white pixels in column x above row y (row-major, so it fills in order). */
    private int[] colWhite;
    /** The picture's pixels that are not white, counted with {@link #rowWhite}. */
    private long notWhite;

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
            notWhite += width - rowWhite[y * (width + 1) + width];
        }
    }

    /** The panel's place in a picture of {@code rgb} pixels (row by row), or a clear refusal. */
    static PanelPlace find(int[] rgb, int width, int height, String name) throws CompareException {
        int size = PanelPlace.SIZE;
        if (width < size || height < size) {
            throw new CompareException(name + " is " + width + "x" + height
                    + ": too small to hold the 650x650 panel (a page is 750x750)"
                    + new PanelFinder(rgb, width, height).atAnotherScale());
        }
        if (width == size && height == size) {
            return new PanelPlace(0, 0, "the whole 650x650 picture is the panel");
        }
        PanelFinder finder = new PanelFinder(rgb, width, height);
        if (width == PAGE && height == PAGE) {
            if (finder.score(PAGE_MARGIN, PAGE_MARGIN, PanelPlace.SIZE, PanelPlace.SIZE) >= 0) {
                return new PanelPlace(PAGE_MARGIN, PAGE_MARGIN, "a 750x750 page");
            }
            PanelPlace found = finder.search();
            return found != null ? new PanelPlace(found.left(), found.top(),
                    "a 750x750 page, but its panel's white frame is here, not at x 50, y 50")
                    : new PanelPlace(PAGE_MARGIN, PAGE_MARGIN, "a 750x750 page; no white frame around its panel");
        }
        PanelPlace found = finder.search();
        if (found == null) {
            String atAnotherScale = finder.atAnotherScale();
            throw new CompareException("no 650x650 panel found in " + name + " (" + width + "x" + height
                    + "): looked for a square with white margins around it and a dark edge inside"
                    + (atAnotherScale.isEmpty() ? scaled(width, height) : atAnotherScale));
        }
        return new PanelPlace(found.left(), found.top(), "found in a " + width + "x" + height + " picture");
    }

    /**
     * Whether the picture holds a 650x650 panel framed by white margins (found where {@link #find} would find it,
     * not taken on trust from a 750x750 picture's size) that is one panel: not split down its middle by a white
     * gutter, as the first assignment's page of four panels is.
     */
    static boolean holdsOnePanel(int[] rgb, int width, int height) {
        PanelPlace found = framedPanel(rgb, width, height);
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

    /** The best place for a 650x650 panel framed by white margins in the picture, at 1:1, or null. */
    static PanelPlace framedPanel(int[] rgb, int width, int height) {
        if (width < PanelPlace.SIZE || height < PanelPlace.SIZE) {
            return null;
        }
        return new PanelFinder(rgb, width, height).search();
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

    /**
     * For a picture that holds the panel drawn at one of the {@link #SCALES} (a square of that many times 650
     * pixels framed as at 1:1, each side give or take the pixel a smooth scaling blends its edges by), a sentence
     * that says where and at what scale; else "".
     */
    private String atAnotherScale() {
        for (double scale : SCALES) {
            int least = (int) Math.floor(PanelPlace.SIZE * scale) - 1;
            int most = (int) Math.ceil(PanelPlace.SIZE * scale) + 1;
            for (int across = least; across <= most; across++) {
                for (int down = Math.max(least, across - 1); down <= Math.min(most, across + 1); down++) {
                    PanelPlace found = across + 2 <= width && down + 2 <= height ? search(across, down) : null;
                    if (found != null) {
                        return String.format(Locale.ROOT, "; it holds the panel scaled by %.3g: a %dx%d square at x "
                                + "%d, y %d with white margins around it and a dark edge inside (%s); a scaled "
                                + "picture cannot be compared pixel for pixel: save the page itself (750x750), or "
                                + "capture the window with the display at 100 %% (1:1, no scaling)", scale, across,
                                down, found.left(), found.top(), scale > 1
                                        ? "a HiDPI screen, or a desktop at 125 % or 150 %, captures so"
                                        : "a screenshot tool saving a smaller copy makes one so");
                    }
                }
            }
        }
        return "";
    }

    /** The best place that qualifies for the 650x650 panel, or null. */
    private PanelPlace search() {
        return search(PanelPlace.SIZE, PanelPlace.SIZE);
    }

    /** The best place that qualifies for a square {@code across} pixels wide and {@code down} high, or null. */
    private PanelPlace search(int across, int down) {
        if (rowWhite == null) {
            countWhite();
        }
        // Two shortcuts, each taken only where score would refuse every place it skips: a border needs
        // BORDER_DARK of its pixels not white, and the picture may not have so many at all (a white picture);
        // the rows above and below a square need FRAME_WHITE of it white, and a row may not have so many.
        int border = 2 * across + 2 * down - 4;
        if (notWhite < BORDER_DARK * border) {
            return null;
        }
        int needAcross = (int) Math.ceil(FRAME_WHITE * across);
        int bestScore = -1;
        PanelPlace best = null;
        for (int top = 1; top + down < height; top++) {
            if (row(top - 1, 0, width) < needAcross || row(top + down, 0, width) < needAcross) {
                continue;
            }
            for (int left = 1; left + across < width; left++) {
                int score = score(left, top, across, down);
                if (score > bestScore) {
                    bestScore = score;
                    best = new PanelPlace(left, top, "");
                }
            }
        }
        return best;
    }

    /**
     * White pixels of the frame outside plus dark pixels of the border inside
     * of the square {@code across} by {@code down} pixels at (left, top) (650
     * by 650 at 1:1), or -1 when some side of the frame is not white enough
     * or the border is not dark enough (or the frame does not fit in the
     * picture).
     */
    private int score(int left, int top, int across, int down) {
        int right = left + across;
        int bottom = top + down;
        if (left < 1 || top < 1 || right >= width || bottom >= height) {
            return -1;
        }
        int needAcross = (int) Math.ceil(FRAME_WHITE * across);
        int needDown = (int) Math.ceil(FRAME_WHITE * down);
        int above = row(top - 1, left, right);
        int below = row(bottom, left, right);
        int before = column(left - 1, top, bottom);
        int after = column(right, top, bottom);
        if (above < needAcross || below < needAcross || before < needDown || after < needDown) {
            return -1;
        }
        int topWhite = row(top, left, right);
        int bottomWhite = row(bottom - 1, left, right);
        int leftWhite = column(left, top + 1, bottom - 1);
        int rightWhite = column(right - 1, top + 1, bottom - 1);
        if (topWhite == across || bottomWhite == across || leftWhite == down - 2 || rightWhite == down - 2) {
            // A side of the square white throughout is margin, not panel: a scaled page's smaller panel
            // framed with margin on two sides, say; a panel's drawing does not fill a whole edge in white.
            return -1;
        }
        int borderWhite = topWhite + bottomWhite + leftWhite + rightWhite;
        int border = 2 * across + 2 * down - 4;
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
