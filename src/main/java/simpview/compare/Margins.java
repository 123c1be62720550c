package simpview.compare;

/**
 * The white margins around a panel: the 50-pixel frame around it, as far as
 * the picture reaches.
 *
 * @param checked how many margin pixels the picture has (0: none, e.g. a bare 650x650 panel)
 * @param notWhite how many of them are not exactly white
 * @param offByMore how many are further than the tolerance from white in some channel
 * @param worst the largest difference from white of any channel, 0 to 255
 * @param firstX the first pixel not white, in the picture (x right, y down); -1 if none
 * @param firstY its row
 * @param jpeg whether the tolerance is a JPEG's slack (its noise leaves white margins only near white)
 */
public record Margins(int checked, int notWhite, int offByMore, int worst, int firstX, int firstY, boolean jpeg) {

    static final int WIDTH = 50;

    /** Whether every margin pixel is within the tolerance of white. */
    public boolean white() {
        return offByMore == 0;
    }

    static Margins of(int[] rgb, int width, int height, PanelPlace place, int tolerance, boolean jpeg) {
        int x0 = Math.max(0, place.left() - WIDTH);
        int y0 = Math.max(0, place.top() - WIDTH);
        int x1 = Math.min(width, place.left() + PanelPlace.SIZE + WIDTH);
        int y1 = Math.min(height, place.top() + PanelPlace.SIZE + WIDTH);
        int checked = 0;
        int notWhite = 0;
        int offByMore = 0;
        int worst = 0;
        int firstX = -1;
        int firstY = -1;
        for (int y = y0; y < y1; y++) {
            boolean panelRow = y >= place.top() && y < place.top() + PanelPlace.SIZE;
            for (int x = x0; x < x1; x++) {
                if (panelRow && x >= place.left() && x < place.left() + PanelPlace.SIZE) {
                    x = place.left() + PanelPlace.SIZE - 1; // skip the panel
                    continue;
                }
                checked++;
                int off = Rasters.distance(rgb[y * width + x], 0xFFFFFF);
                if (off > 0) {
                    if (notWhite++ == 0) {
                        firstX = x;
                        firstY = y;
                    }
                    offByMore += off > tolerance ? 1 : 0;
                    worst = Math.max(worst, off);
                }
            }
        }
        return new Margins(checked, notWhite, offByMore, worst, firstX, firstY, jpeg);
    }

    /**
     * E.g. "white (52,500 pixels)", "white within a JPEG's slack (288 of 140,000 pixels slightly off, up to 16/255;
     * ...)" or "NOT white: 1,204 of 52,500 pixels off by more than the tolerance (up to 255/255), the first at x 3,
     * y 7 of the picture".
     */
    public String describe() {
        if (checked == 0) {
            return "none in the picture";
        }
        if (notWhite == 0) {
            return String.format("white (%,d pixels)", checked);
        }
        String first = String.format("the first at x %d, y %d of the picture", firstX, firstY);
        String allowed = jpeg ? "a JPEG's slack" : "the tolerance";
        if (offByMore == 0) {
            return String.format("white within %s (%,d of %,d pixels slightly off, up to %d/255; %s)",
                    allowed, notWhite, checked, worst, first);
        }
        return String.format("NOT white: %,d of %,d pixels off by more than %s (up to %d/255), %s",
                offByMore, checked, allowed, worst, first);
    }
}
