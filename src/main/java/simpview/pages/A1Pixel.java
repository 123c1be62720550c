package simpview.pages;

import java.util.Locale;
import simpview.geometry.Vertex;
import simpview.raster.AntialiasedLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.LineRenderer;
import simpview.surface.OnePixelSurface;
import simpview.surface.PageCanvas;

/**
 * What drew one pixel of a first-assignment page, for the inspector: its
 * panel and the panel's drawer, and the last line (or triangle) that wrote
 * it, with its rounded endpoints; for an antialiased pixel, its distance
 * from that line and the coverage the handout's disc gives it. Worked out by
 * drawing the panel again onto a probe that watches the one pixel.
 */
public final class A1Pixel {

    private A1Pixel() {
    }

    /** The inspector's words for image pixel (ix, iy) of the first assignment's page, or null outside its panels. */
    public static String describe(int page, long seed, A1Rule rule, int ix, int iy) {
        int panel = A1Layout.panelAt(ix, iy);
        if (panel == 0) {
            return null;
        }
        int x = ix - A1Layout.left(panel);
        int y = A1Layout.top(panel) + A1Layout.PANEL - 1 - iy;
        String where = String.format(Locale.ROOT, "panel %d, x %d, y %d", panel, x, y);
        Page shown = Assignment1.page(page);
        if (shown instanceof LineTestPage lines) {
            return where + " · " + LineTestPage.drawerName(panel, rule) + " · " + line(lines.lines(seed), panel, rule, x, y);
        }
        return where + " · " + triangle(new A1Polygons(seed, rule), panel, x, y,
                (((PolygonTestPage) shown).ghost() ? "ghost (white, opacity 0.14)" : "filled") + rule.drawerNote());
    }

    /**
     * The line or triangle (0-based, in drawing order) that last wrote image
     * pixel (ix, iy) of the page, with the panel it is in: {panel, index};
     * null outside the panels or where nothing wrote.
     */
    public static int[] lastAt(int page, long seed, A1Rule rule, int ix, int iy) {
        int panel = A1Layout.panelAt(ix, iy);
        if (panel == 0) {
            return null;
        }
        int x = ix - A1Layout.left(panel);
        int y = A1Layout.top(panel) + A1Layout.PANEL - 1 - iy;
        Page shown = Assignment1.page(page);
        int[] hits = shown instanceof LineTestPage lines ? lastLine(lines.lines(seed), panel, rule, x, y)
                : lastTriangle(new A1Polygons(seed, rule), panel, x, y);
        return hits[0] < 0 ? null : new int[] {panel, hits[0]};
    }

    /**
     * The magnifier's marks at image pixel (ix, iy): the line that last wrote
     * it as given and between its rounded ends, or the triangle as given;
     * {@link A1Marks#NONE} where nothing did.
     */
    public static A1Marks marksAt(int page, long seed, A1Rule rule, int ix, int iy) {
        int[] last = lastAt(page, seed, rule, ix, iy);
        if (last == null) {
            return A1Marks.NONE;
        }
        if (Assignment1.page(page) instanceof LineTestPage lines) {
            return A1Marks.line(lines.lines(seed), last[1], last[0]);
        }
        return A1Marks.triangles(new A1Polygons(seed, rule), last);
    }

    /** {the last line to write panel pixel (x, y), how many did}; -1 for none. */
    private static int[] lastLine(A1Lines set, int panel, A1Rule rule, int x, int y) {
        OnePixelSurface probe = new OnePixelSurface(A1Layout.PANEL, A1Layout.PANEL, x, y, PageCanvas.BACKGROUND);
        LineRenderer drawer = LineTestPage.drawer(panel, rule);
        int last = -1;
        int count = 0;
        for (int i = 0; i < set.count(); i++) {
            probe.watchAgain();
            drawer.drawLine(set.numbers(), A1Lines.from(i), A1Lines.to(i), probe);
            if (probe.written()) {
                last = i;
                count++;
            }
        }
        return new int[] {last, count};
    }

    /** {the last triangle to write panel pixel (x, y), how many did}; -1 for none. */
    private static int[] lastTriangle(A1Polygons scenes, int panel, int x, int y) {
        OnePixelSurface probe = new OnePixelSurface(A1Layout.PANEL, A1Layout.PANEL, x, y, PageCanvas.BACKGROUND);
        FilledPolygonRenderer fill = new FilledPolygonRenderer();
        double[] n = scenes.scene(panel);
        int last = -1;
        int count = 0;
        for (int i = 0; i < scenes.count(panel); i++) {
            probe.watchAgain();
            fill.drawPolygon(n, A1Polygons.at(i), probe);
            if (probe.written()) {
                last = i;
                count++;
            }
        }
        return new int[] {last, count};
    }

    private static String line(A1Lines set, int panel, A1Rule rule, int x, int y) {
        int[] hits = lastLine(set, panel, rule, x, y);
        int last = hits[0];
        int count = hits[1];
        if (last < 0) {
            return "no line drew it (background)";
        }
        Vertex p = set.start(last);
        Vertex q = set.end(last);
        double px = Math.floor(p.x() + 0.5);
        double py = Math.floor(p.y() + 0.5);
        double qx = Math.floor(q.x() + 0.5);
        double qy = Math.floor(q.y() + 0.5);
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT,
                "line %d of %d, (%.0f, %.0f) to (%.0f, %.0f)", last + 1, set.count(), px, py, qx, qy));
        if (count > 1) {
            sb.append(String.format(Locale.ROOT, ", the last of %d lines here", count));
        }
        if (panel == 4) {
            double distance = AntialiasedLineRenderer.distance(x, y, px, py, qx, qy);
            sb.append(String.format(Locale.ROOT, " · distance %.3f, coverage %.3f", distance,
                    AntialiasedLineRenderer.coverage(distance)));
        }
        return sb.toString();
    }

    private static String triangle(A1Polygons scenes, int panel, int x, int y, String how) {
        int[] hits = lastTriangle(scenes, panel, x, y);
        int last = hits[0];
        int count = hits[1];
        if (last < 0) {
            return how + " · no triangle drew it (background)";
        }
        return String.format(Locale.ROOT, "%s · triangle %d of %d%s", how, last + 1, scenes.count(panel),
                count > 1 ? ", the last of " + count + " here" : "");
    }
}
