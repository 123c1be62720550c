package simpview.inspect;

import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Vertex;
import simpview.pages.A1Layout;
import simpview.pages.A1Lines;
import simpview.pages.A1Polygons;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.LineTestPage;
import simpview.pages.Page;
import simpview.pages.PolygonTestPage;
import simpview.raster.FilledPolygonRenderer;
import simpview.surface.Colors;
import simpview.surface.CoverageDrawable;
import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.OnePixelSurface;
import simpview.surface.GhostWritingDrawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.surface.Span;

/**
 * The history of one pixel of the first assignment's pages (SPEC Part 3):
 * the pixel starts as the page starts (white around the panels, black in
 * them), and the pixel's panel is drawn again by the page's own code
 * ({@link LineTestPage#drawPanel}, {@link PolygonTestPage#drawPanel}) through
 * a probe that lets only the writes at the pixel through and tells each: the
 * line or triangle that made it, its colour, and the pixel's colour before
 * and after. On the antialiased panel the probe is the
 * {@link CoverageDrawable} the antialiased drawer blends through (so it sees
 * each write's coverage and colour before the blend); on the ghost page it
 * stands behind the {@link GhostWritingDrawable} (every write white at
 * opacity {@value GhostWritingDrawable#OPACITY}). Its last write's new colour
 * is the pixel's colour on the page.
 */
public final class A1Inspector {

    private A1Inspector() {
    }

    /**
     * Page {@code page} (1 to 5) of the first assignment drawn with {@code
     * seed} under {@code rule}, at page pixel (x, y): x right, y up from the page's bottom-left
     * pixel, 0 to 749.
     *
     * @throws IllegalArgumentException for a page or pixel outside the page
     */
    public static A1Report inspect(int page, long seed, A1Rule rule, int x, int y) {
        Page shown = Assignment1.page(page);
        int last = PageCanvas.SIZE - 1;
        if (x < 0 || x > last || y < 0 || y > last) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is outside the page: x and y are 0 to "
                    + last + ", from the page's bottom-left pixel, y up");
        }
        int column = x;
        int row = last - y;
        int panel = A1Layout.panelAt(column, row);
        int argb = Colors.WHITE; // the page around the panels
        List<A1Report.Write> writes = new ArrayList<>();
        List<A1Report.CentreCase> centre = new ArrayList<>();
        List<A1Report.Beside> beside = new ArrayList<>();
        String drawer = null;
        int px = -1;
        int py = -1;
        if (panel != 0) {
            px = column - A1Layout.left(panel);
            py = A1Layout.top(panel) + A1Layout.PANEL - 1 - row;
            Watch watch = new Watch(px, py, writes, beside);
            // The panel as the replay needs it: the one pixel watched, the panel's background elsewhere (what a ghost
            // or a blend reads beside it only makes writes the probe drops). A page drawn for each pixel inspected
            // was most of an inspection's time, and its garbage, while the pointer swept a page.
            OnePixelSurface pixel = new OnePixelSurface(A1Layout.PANEL, A1Layout.PANEL, px, py, PageCanvas.BACKGROUND);
            if (shown instanceof LineTestPage lines) {
                drawer = LineTestPage.drawerName(panel, rule);
                A1Lines set = lines.lines(seed);
                watch.lines = set;
                Drawable probe = new Probe(watch, pixel);
                // The antialiased drawer blends through a CoverageDrawable it is given as it is.
                Drawable target = panel == 4 ? new CoverageProbe(watch, probe) : probe;
                LineTestPage.drawPanel(panel, rule, set, target, i -> watch.primitive = i);
            } else {
                PolygonTestPage polygons = (PolygonTestPage) shown;
                drawer = (polygons.ghost() ? "ghost (white, opacity " + GhostWritingDrawable.OPACITY + ")" : "filled")
                        + rule.drawerNote();
                A1Polygons scenes = new A1Polygons(seed, rule);
                watch.triangles = scenes.scene(panel);
                watch.ghost = polygons.ghost();
                polygons.drawPanel(panel, scenes, new Probe(watch, pixel), new FilledPolygonRenderer(),
                        i -> watch.primitive = i);
                centre.addAll(centreCases(scenes.scene(panel), px, py));
            }
            watch.count = shown instanceof LineTestPage ? watch.lines.count()
                    : watch.triangles.length / (3 * Vertex.NUMBERS);
            for (A1Report.Write w : writes) {
                w.of = watch.count;
            }
            for (A1Report.Beside b : beside) {
                b.of = watch.count;
            }
            argb = pixel.colour();
        }
        if (!writes.isEmpty()) {
            beside.clear(); // said only of a pixel no line reached
        }
        return new A1Report(page, shown.title(), shown instanceof LineTestPage, shown.usesSeed() ? seed : null, rule, x, y, column, row,
                argb, panel, drawer, px, py, writes, centre, beside);
    }

    /**
     * The triangles (three vertices each, as drawn) whose box holds the centre of panel pixel (x, y), and what
     * the fill rule says of each ({@link VertexTable#centre}: the rasterizer's own edge tests).
     */
    private static List<A1Report.CentreCase> centreCases(double[] triangles, int x, int y) {
        List<A1Report.CentreCase> cases = new ArrayList<>();
        double cx = x + 0.5;
        double cy = y + 0.5;
        int n = Vertex.NUMBERS;
        for (int i = 0; i < triangles.length / (3 * n); i++) {
            double[] drawn = new double[6];
            for (int k = 0; k < 3; k++) {
                drawn[2 * k] = triangles[(3 * i + k) * n + Vertex.X];
                drawn[2 * k + 1] = triangles[(3 * i + k) * n + Vertex.Y];
            }
            boolean inBox = cx >= Math.min(drawn[0], Math.min(drawn[2], drawn[4]))
                    && cx <= Math.max(drawn[0], Math.max(drawn[2], drawn[4]))
                    && cy >= Math.min(drawn[1], Math.min(drawn[3], drawn[5]))
                    && cy <= Math.max(drawn[1], Math.max(drawn[3], drawn[5]));
            if (inBox) {
                Terms t = VertexTable.centre(drawn, x, y);
                cases.add(new A1Report.CentreCase(i + 1, (Boolean) t.get("covered"), (String) t.get("why")));
            }
        }
        return cases;
    }

    /** What the probes tell: the write at the pixel, the primitive at hand. */
    private static final class Watch {
        final int x;
        final int y;
        final List<A1Report.Write> writes;
        final List<A1Report.Beside> beside;
        int primitive;
        int count;
        A1Lines lines;
        double[] triangles;
        boolean ghost;
        /** Set by the coverage probe for the write on its way: its colour before the blend and its coverage. */
        boolean blending;
        int incoming;
        double coverage;

        Watch(int x, int y, List<A1Report.Write> writes, List<A1Report.Beside> beside) {
            this.x = x;
            this.y = y;
            this.writes = writes;
            this.beside = beside;
        }

        /**
         * On a page of lines, a write at (wx, wy), one of the eight pixels around the watched one, is told as the
         * line's: where a line went instead of here. Polygons' neighbours are not told (their centres say it).
         */
        void besideAt(int wx, int wy) {
            if (lines == null || Math.abs(wx - x) > 1 || Math.abs(wy - y) > 1 || wx == x && wy == y) {
                return;
            }
            A1Report.Beside last = beside.isEmpty() ? null : beside.get(beside.size() - 1);
            if (last == null || last.number() != primitive + 1) {
                last = new A1Report.Beside(primitive + 1, lines.start(primitive), lines.end(primitive));
                beside.add(last);
            }
            last.add(wx, wy);
        }

        void wrote(double z, int old, int now) {
            A1Report.Write w;
            if (lines != null) {
                w = A1Report.Write.line(primitive, lines.start(primitive), lines.end(primitive));
            } else {
                w = A1Report.Write.triangle(primitive, triangles, A1Polygons.at(primitive));
            }
            w.z = z;
            w.old = old;
            w.now = now;
            if (blending) {
                w.blended = true;
                w.argb = incoming;
                w.coverage = coverage;
                blending = false;
            } else if (ghost) {
                w.blended = true;
                w.argb = Rgb.WHITE.argb();
                w.coverage = GhostWritingDrawable.OPACITY;
            } else {
                w.argb = now;
            }
            writes.add(w);
        }
    }

    /** Just before the panel: writes at the pixel are told (old and new colour) and go on; the rest go no further. */
    private static final class Probe extends DrawableDecorator {
        private final Watch watch;

        Probe(Watch watch, Drawable panel) {
            super(panel);
            this.watch = watch;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            if (x == watch.x && y == watch.y) {
                int old = delegate.getPixel(x, y);
                delegate.setPixel(x, y, z, argb);
                watch.wrote(z, old, delegate.getPixel(x, y));
            } else {
                watch.besideAt(x, y);
            }
        }

        @Override
        public void fillSpan(Span s) {
            if (s.y == watch.y && s.x0 <= watch.x && watch.x < s.x1) {
                setPixel(watch.x, s.y, s.zAt(watch.x), s.argbAt(watch.x));
            }
        }
    }

    /** The antialiased drawer's blend, telling the probe behind it each write's colour and coverage first. */
    private static final class CoverageProbe extends CoverageDrawable {
        private final Watch watch;

        CoverageProbe(Watch watch, Drawable probe) {
            super(probe);
            this.watch = watch;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            if (x == watch.x && y == watch.y) {
                watch.blending = true;
                watch.incoming = argb;
                watch.coverage = coverage();
                super.setPixel(x, y, z, argb);
            } else {
                watch.besideAt(x, y);
            }
        }
    }
}
