package simpview.pages;

import simpview.surface.Colors;
import simpview.surface.Drawable;
import simpview.surface.ImageDrawable;
import simpview.surface.PageCanvas;
import simpview.surface.PanelDrawable;

/**
 * The first assignment's page (SPEC Part 3): 750x750 white, four black
 * 300x300 panels with 50 px margins and gutters; panels 1 and 2 on top, 3 and
 * 4 below. Each panel is drawn in its own coordinates (origin bottom-left,
 * y up); a write outside it is dropped.
 */
public final class A1Layout {

    public static final int PANELS = 4;
    public static final int PANEL = 300;
    public static final int MARGIN = 50;

    private A1Layout() {
    }

    /** The image column of panel k's left edge (k = 1..4). */
    public static int left(int k) {
        return MARGIN + ((k - 1) % 2) * (PANEL + MARGIN);
    }

    /** The image row of panel k's top edge (k = 1..4; image rows run down). */
    public static int top(int k) {
        return MARGIN + ((k - 1) / 2) * (PANEL + MARGIN);
    }

    /** Which panel (1..4) holds image pixel (x, y), rows running down; 0 for none. */
    public static int panelAt(int x, int y) {
        for (int k = 1; k <= PANELS; k++) {
            if (x >= left(k) && x < left(k) + PANEL && y >= top(k) && y < top(k) + PANEL) {
                return k;
            }
        }
        return 0;
    }

    /**
     * Where image pixel (x, y), rows running down, lies when no panel holds it: "the page's white margins" (the
     * 50 px around the four panels), "the white gutter between panels 1 and 2" (the 50 px between two panels),
     * or "the white gutter between the four panels" (where the two gutters cross). A pixel between two panels
     * is not in a margin, and a student looking there for the page's edge would look in the wrong place.
     */
    public static String whiteAround(int x, int y) {
        int size = 2 * PANEL + 3 * MARGIN;
        if (x < MARGIN || y < MARGIN || x >= size - MARGIN || y >= size - MARGIN) {
            return "the page's white margins";
        }
        boolean acrossGutter = x >= MARGIN + PANEL && x < 2 * MARGIN + PANEL; // between the columns of panels
        boolean downGutter = y >= MARGIN + PANEL && y < 2 * MARGIN + PANEL; // between the rows
        if (acrossGutter && downGutter) {
            return "the white gutter between the four panels";
        }
        if (acrossGutter) {
            return y < MARGIN + PANEL ? "the white gutter between panels 1 and 2" : "the white gutter between panels 3 and 4";
        }
        return x < MARGIN + PANEL ? "the white gutter between panels 1 and 3" : "the white gutter between panels 2 and 4";
    }

    /** Paints the page white with its four black panels and gives the panels, 1 to 4 at [0] to [3]. */
    public static Drawable[] paint(PageCanvas canvas) {
        ImageDrawable image = new ImageDrawable(canvas.image());
        image.fillRect(0, 0, PageCanvas.SIZE, PageCanvas.SIZE, Colors.WHITE);
        Drawable[] panels = new Drawable[PANELS];
        for (int k = 1; k <= PANELS; k++) {
            image.fillRect(left(k), top(k), left(k) + PANEL, top(k) + PANEL, PageCanvas.BACKGROUND);
            panels[k - 1] = new PanelDrawable(image, left(k), top(k), PANEL);
        }
        return panels;
    }
}
