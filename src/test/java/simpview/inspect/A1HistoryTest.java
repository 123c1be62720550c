package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.pages.A1Layout;
import simpview.pages.A1Lines;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.LineTestPage;
import simpview.pages.PageContext;
import simpview.raster.AntialiasedLineRenderer;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.CoverageDrawable;
import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.PageCanvas;

/**
 * The first assignment's pages, pixel by pixel: the replayed history ends in
 * the page's own bytes, each write starts from the colour the one before
 * left, and every blend is the handout's c * colour + (1 - c) * old,
 * computed here per channel.
 */
class A1HistoryTest {

    private static final long SEED = 7;
    private static final int LAST = 749;

    private static BufferedImage page(int n) {
        return Assignment1.render(n, new PageContext(SEED, null, null, SceneMonitor.NONE));
    }

    @Test
    void everyHistoryEndsInThePagesBytes() {
        int blends = 0;
        for (int n = 1; n <= Assignment1.COUNT; n++) {
            BufferedImage image = page(n);
            Random random = new Random(n);
            List<int[]> lit = new ArrayList<>();
            int[] all = image.getRGB(0, 0, LAST + 1, LAST + 1, null, 0, LAST + 1);
            for (int row = 0; row <= LAST; row++) {
                for (int column = 0; column <= LAST; column++) {
                    int rgb = all[row * (LAST + 1) + column] & 0xFFFFFF;
                    if (rgb != 0 && A1Layout.panelAt(column, row) != 0) {
                        lit.add(new int[] {column, LAST - row});
                    }
                }
            }
            int drawn = 0;
            for (int k = 0; k < 30; k++) {
                // Mostly pixels the page drew, some anywhere.
                int[] xy = k % 6 == 0 ? new int[] {random.nextInt(LAST + 1), random.nextInt(LAST + 1)}
                        : lit.get(random.nextInt(lit.size()));
                int x = xy[0];
                int y = xy[1];
                int rgb = image.getRGB(x, LAST - y) & 0xFFFFFF;
                A1Report report = A1Inspector.inspect(n, SEED, A1Rule.SPEC, x, y);
                List<A1Report.Write> writes = report.writes();
                assertEquals(rgb, report.argb() & 0xFFFFFF, "page " + n + " (" + x + ", " + y + ")");
                if (writes.isEmpty()) {
                    assertEquals(report.panel() == 0 ? 0xFFFFFF : 0, rgb, "page " + n + " (" + x + ", " + y + ")");
                    continue;
                }
                drawn++;
                assertEquals(0, writes.get(0).old() & 0xFFFFFF, "a panel starts black");
                for (int i = 1; i < writes.size(); i++) {
                    assertEquals(writes.get(i - 1).now(), writes.get(i).old(), "each write starts where the last left");
                }
                assertEquals(rgb, writes.get(writes.size() - 1).now() & 0xFFFFFF, "the last write's new colour");
                for (A1Report.Write w : writes) {
                    boolean blending = n == 5 || report.panel() == 4 && n <= 3;
                    assertEquals(blending ? Outcome.BLENDED : Outcome.WRITTEN, w.outcome(), report.text());
                    if (blending) {
                        blends++;
                        double c = w.coverage();
                        assertTrue(c > 0 && c <= 1, "coverage " + c);
                        if (n == 5) {
                            assertEquals(0.14, c);
                            assertEquals(0xFFFFFF, w.argb() & 0xFFFFFF, "a ghost write is white");
                        } else {
                            // The distance shown is the one the coverage was drawn for: worked out here from
                            // the rounded ends, the pixel's centre at its integer coordinates.
                            double[] e = w.ends();
                            double ax = Math.floor(e[0] + 0.5);
                            double ay = Math.floor(e[1] + 0.5);
                            double dx = Math.floor(e[2] + 0.5) - ax;
                            double dy = Math.floor(e[3] + 0.5) - ay;
                            double across = dx == 0 && dy == 0 ? Math.abs(report.panelY() - ay)
                                    : Math.abs((report.panelX() - ax) * dy - (report.panelY() - ay) * dx)
                                            / Math.sqrt(dx * dx + dy * dy);
                            assertEquals(across, w.distanceFrom(report.panelX(), report.panelY()), 1e-12);
                            assertEquals(AntialiasedLineRenderer.coverage(across), c, 1e-12, report.text());
                            assertTrue(report.text().contains(String.format(Locale.ROOT,
                                    "(the pixel at distance %.6f from the line)", across)), report.text());
                        }
                        assertEquals(blend(w.argb(), w.old(), c), w.now() & 0xFFFFFF, report.text());
                    } else {
                        assertEquals(w.argb(), w.now(), "a plain write is its colour");
                    }
                }
            }
            assertTrue(drawn >= 20, "page " + n + ": only " + drawn + " drawn pixels sampled");
        }
        assertTrue(blends > 50, "blends checked: " + blends);
    }

    /**
     * A student given page 3's lines as render --primitives prints them blends each line's colour, a double, by
     * SPEC's formula; simpview's antialiased panel must be what they get, at every blended write. The colours
     * are whole levels (k / 255), so blending the double and the byte agree: with the raw random doubles a third
     * of the writes or so came out a level off, 3 % of the panel. Panel 4 is drawn once through the page's own
     * chain with every write recorded (the colour before, the line's colour and coverage, the colour after), and
     * the panel so drawn is the page's: asking the inspector pixel by pixel, which redraws the page each time,
     * took 17 s for every other row.
     */
    @Test
    void theRandomLinesBlendTheColourThePrimitivesPrint() {
        for (long seed : new long[] {SEED, 361}) {
            A1Lines lines = A1Lines.random(seed);
            PageCanvas canvas = new PageCanvas();
            Drawable panel = A1Layout.paint(canvas)[3];
            record Blend(int line, int old, int now, double coverage) {
            }
            List<Blend> writes = new ArrayList<>();
            int[] line = {-1};
            double[] coverage = {Double.NaN};
            Drawable written = new DrawableDecorator(panel) {
                @Override
                public void setPixel(int x, int y, double z, int argb) {
                    int old = delegate.getPixel(x, y);
                    delegate.setPixel(x, y, z, argb);
                    writes.add(new Blend(line[0], old, delegate.getPixel(x, y), coverage[0]));
                }
            };
            CoverageDrawable blend = new CoverageDrawable(written) {
                @Override
                public void setPixel(int x, int y, double z, int argb) {
                    coverage[0] = coverage();
                    super.setPixel(x, y, z, argb);
                }
            };
            LineTestPage.drawPanel(4, A1Rule.SPEC, lines, blend, i -> line[0] = i);
            BufferedImage image = Assignment1.render(3, new PageContext(seed, null, null, SceneMonitor.NONE));
            int left = A1Layout.left(4);
            int top = A1Layout.top(4);
            for (int row = top; row < top + 300; row++) {
                for (int column = left; column < left + 300; column++) {
                    assertEquals(image.getRGB(column, row), canvas.image().getRGB(column, row),
                            "seed " + seed + ": the panel drawn here is not the page's at (" + column + ", " + row + ")");
                }
            }
            int checked = 0;
            for (Blend w : writes) {
                Vertex given = lines.start(w.line());
                double c = w.coverage();
                double[] colour = {given.r(), given.g(), given.b()};
                int now = 0;
                for (int k = 0; k < 3; k++) {
                    double old = (w.old() >>> (16 - 8 * k) & 0xFF) / 255.0;
                    double v = c * colour[k] + (1 - c) * old;
                    now |= (int) Math.floor(v * 255 + 0.5) << (16 - 8 * k);
                }
                assertEquals(now, w.now() & 0xFFFFFF, "seed " + seed + ": line " + (w.line() + 1) + ", coverage " + c);
                checked++;
            }
            assertTrue(checked > 1000, "blends checked: " + checked);
        }
    }

    /** SPEC Part 3's blend, per channel in [0, 1], rounded to the nearest level. */
    private static int blend(int colour, int old, double c) {
        int out = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            double v = c * (colour >>> shift & 0xFF) / 255.0 + (1 - c) * (old >>> shift & 0xFF) / 255.0;
            out |= (int) Math.min(255, Math.floor(v * 255 + 0.5)) << shift;
        }
        return out;
    }

    /**
     * On the polygon pages, the centre section agrees with the drawing pixel for pixel: the triangles it says
     * cover the centre are exactly those that wrote the pixel, in drawing order, under both rules; on the mesh
     * (panel 2), where triangles share every inner edge, at most one does, and a centre on a shared edge names
     * the top-left rule.
     */
    @Test
    void thePolygonPagesCentreSectionIsTheDrawingsOwnAnswer() {
        int ties = 0;
        for (A1Rule rule : A1Rule.values()) {
            Random random = new Random(28);
            for (int k = 0; k < 400; k++) {
                int panel = 1 + k / 2 % 4;
                // on the mesh's diagonals (x = y: its cells are split from (min x, min y) to (max x, max y)) half
                // the time, where centres lie on shared edges; anywhere the rest
                int px = random.nextInt(300);
                int py = k % 2 == 0 ? px : random.nextInt(300);
                int x = 50 + (panel - 1) % 2 * 350 + px;
                int y = LAST - (50 + (panel - 1) / 2 * 350 + 299 - py);
                A1Report report = A1Inspector.inspect(4, SEED, rule, x, y);
                assertEquals(panel, report.panel());
                assertEquals(px, report.panelX());
                assertEquals(py, report.panelY());
                List<Integer> wrote = report.writes().stream().map(A1Report.Write::number).toList();
                List<Integer> cover = report.centre().stream().filter(A1Report.CentreCase::covered)
                        .map(A1Report.CentreCase::number).toList();
                assertEquals(wrote, cover, report.text());
                if (panel == 2) {
                    assertTrue(cover.size() <= 1, "one mesh triangle at most: " + report.text());
                }
                if (report.centre().stream().anyMatch(c -> c.why().contains("top-left rule"))) {
                    ties++;
                    assertTrue(report.text().contains("the top-left rule gives the pixel to"), report.text());
                }
            }
        }
        assertTrue(ties > 20, "centres on a shared edge met: " + ties);
    }

    @Test
    void theStarburstsCentreIsEveryLine() {
        // Panel 1's pixel (150, 150): image column 50 + 150, row 50 + 299 - 150; page y = 749 - row.
        A1Report dda = A1Inspector.inspect(1, SEED, A1Rule.SPEC, 200, LAST - 199);
        assertEquals(1, dda.panel());
        assertEquals("DDA", dda.drawer());
        assertEquals(150, dda.panelX());
        assertEquals(150, dda.panelY());
        assertEquals(90, dda.writes().size());
        A1Report.Write first = dda.writes().get(0);
        assertEquals(1, first.number());
        assertEquals(90, first.of());
        assertTrue(first.isLine());
        assertEquals(150, first.ends()[0]);
        assertEquals(285, first.ends()[2]);
        assertTrue(dda.text().contains("line 1 of 90, (150, 150) to (285, 150)"), dda.text());
        // Panel 4 (antialiased): (150, 150) is at image column 400 + 150, row 400 + 299 - 150.
        A1Report smooth = A1Inspector.inspect(1, SEED, A1Rule.SPEC, 550, LAST - 549);
        assertEquals("antialiased", smooth.drawer());
        assertEquals(90, smooth.writes().size());
        for (A1Report.Write w : smooth.writes()) {
            assertEquals(Outcome.BLENDED, w.outcome());
        }
        assertTrue(smooth.json().contains("\"outcome\": \"blended\", \"coverage\": "), smooth.json());
    }

    /**
     * A black pixel of a line panel names the lines that lit a pixel next to it. Page 2 (the handout's
     * parallelogram, integer ends, so every drawer's pixels are SPEC's DDA's): panel 1's pixel (85, 133) is
     * just below the band of the first 51 lines. Which lines light which neighbour is worked out here by
     * SPEC's DDA rule on the handout's lines; line 51, (20, 169) to (150, 99), is at y = 169 - 65 * 70 / 130
     * = 134 in column 85.
     */
    @Test
    void aBlackLinePixelNamesTheLinesBesideIt() {
        int px = 85;
        int py = 133;
        List<String> expected = new ArrayList<>();
        for (int i = 0; i < 102; i++) {
            int p = i % 51;
            int[] line = i < 51 ? new int[] {20, 299 - 80 - p, 150, 299 - 150 - p}
                    : new int[] {160 + p, 299 - 270, 240 + p, 299 - 40};
            List<int[]> pixels = ddaPixels(line[0], line[1], line[2], line[3]);
            StringBuilder near = new StringBuilder();
            for (int[] q : pixels) {
                assertTrue(q[0] != px || q[1] != py, "line " + (i + 1) + " lights the pixel itself");
                if (Math.abs(q[0] - px) <= 1 && Math.abs(q[1] - py) <= 1) {
                    near.append(near.length() == 0 ? "" : " ").append(q[0]).append(',').append(q[1]);
                }
            }
            if (near.length() > 0) {
                expected.add((i + 1) + ": " + near);
            }
        }
        assertTrue(expected.stream().anyMatch(e -> e.startsWith("51: ")), expected.toString());
        for (int panel : new int[] {1, 2, 3}) {
            int left = panel == 2 ? 400 : 50;
            int bottom = panel == 3 ? 50 : 400;
            A1Report report = A1Inspector.inspect(2, SEED, A1Rule.SPEC, left + px, bottom + py);
            assertEquals(0, report.writes().size());
            List<String> found = new ArrayList<>();
            for (A1Report.Beside b : report.beside()) {
                StringBuilder near = new StringBuilder();
                for (int[] q : b.pixels()) {
                    near.append(near.length() == 0 ? "" : " ").append(q[0]).append(',').append(q[1]);
                }
                found.add(b.number() + ": " + near);
            }
            // the test's DDA lists a line's pixels from its smaller-x end, as the drawers walk them
            assertEquals(expected, found, "panel " + panel);
            String text = report.text();
            assertTrue(text.contains("line 51 of 102, (20, 169) to (150, 99): wrote ")
                    && text.contains("; at x 85 it is at y 134, which rounds to 134, 1 from this pixel's 133"), text);
            assertTrue(report.json().contains("\"beside\": [{\"primitive\": "), report.json());
            assertFalse(report.json().contains("\"past_end\": true"), report.json());
        }
        // a lit pixel names no lines beside it
        assertTrue(A1Inspector.inspect(2, SEED, A1Rule.SPEC, 50 + px, 400 + 134).beside().isEmpty());
    }

    /**
     * A black pixel one step past a line's end is said to be past it, not to lie on the line through its ends.
     * Page 1's line 1 (t = 0) runs from (150, 150) to (150 + 135, 150) = (285, 150), line 46 (t = 180 degrees) to
     * (150 - 135, 150) = (15, 150) (SPEC Part 3); the lines beside them (t = 4 and 176, 356 and 184 degrees) end
     * nine rows away, at y 150 +- 135 sin 4 = 159.4 or 140.6. So panel 1's pixels (286, 150) and (14, 150), page
     * (336, 550) and (64, 550), have only those lines beside them, and are past their second ends.
     */
    @Test
    void aBlackPixelPastALinesEndIsSaidToBePastIt() {
        A1Report after = A1Inspector.inspect(1, SEED, A1Rule.SPEC, 50 + 286, 400 + 150);
        assertEquals(0, after.writes().size());
        assertEquals(1, after.beside().size(), after.text());
        assertTrue(after.text().contains("line 1 of 90, (150, 150) to (285, 150): wrote (285, 150) left; x 286 is past"
                + " its end (285, 150), where it stops"), after.text());
        assertFalse(after.text().contains("which rounds to"), after.text());
        assertTrue(after.json().contains("\"past_end\": true"), after.json());
        A1Report before = A1Inspector.inspect(1, SEED, A1Rule.SPEC, 50 + 14, 400 + 150);
        assertEquals(1, before.beside().size(), before.text());
        assertTrue(before.text().contains("  line 46 of 90, "), before.text());
        assertTrue(before.text().contains(": wrote (15, 150) right; x 14 is past its end (15, 150), where it stops"),
                before.text());
    }

    /** SPEC Part 1's DDA on integer ends: from the smaller major end, the minor coordinate summed and rounded half up. */
    private static List<int[]> ddaPixels(int x0, int y0, int x1, int y1) {
        List<int[]> pixels = new ArrayList<>();
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        if (xMajor ? x1 < x0 : y1 < y0) {
            int t = x0;
            x0 = x1;
            x1 = t;
            t = y0;
            y0 = y1;
            y1 = t;
        }
        if (xMajor) {
            double slope = x1 == x0 ? 0 : (double) (y1 - y0) / (x1 - x0);
            double y = y0;
            for (int x = x0; x <= x1; x++, y += slope) {
                pixels.add(new int[] {x, (int) Math.floor(y + 0.5)});
            }
        } else {
            double slope = (double) (x1 - x0) / (y1 - y0);
            double x = x0;
            for (int y = y0; y <= y1; y++, x += slope) {
                pixels.add(new int[] {(int) Math.floor(x + 0.5), y});
            }
        }
        return pixels;
    }

    @Test
    void marginsAndPixelsOffThePage() {
        A1Report margin = A1Inspector.inspect(4, SEED, A1Rule.SPEC, 10, 10);
        assertEquals(0, margin.panel());
        assertTrue(margin.writes().isEmpty());
        assertTrue(margin.json().contains("\"panel\": null"), margin.json());
        assertThrows(IllegalArgumentException.class, () -> A1Inspector.inspect(1, SEED, A1Rule.SPEC, 750, 3));
        assertThrows(IllegalArgumentException.class, () -> A1Inspector.inspect(6, SEED, A1Rule.SPEC, 3, 3));
    }

    /**
     * Hovering a first-assignment page inspects a pixel at every move of the pointer: an inspection draws the
     * pixel's panel again through a one-pixel probe and no page around it. A 750x750 canvas made for each was
     * 5.6 MB of garbage an inspection (most of its time, and a pause now and then as the pointer swept);
     * without it the largest page, the polygons, makes about 150 KB.
     */
    @Test
    void anInspectionDrawsNoPage() {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        for (int n = 1; n <= Assignment1.COUNT; n++) {
            A1Inspector.inspect(n, SEED, A1Rule.SPEC, 200, 600); // loads and links everything first
            long before = threads.getThreadAllocatedBytes(thread);
            for (int k = 0; k < 5; k++) {
                A1Inspector.inspect(n, SEED, A1Rule.SPEC, 100 + 120 * k, 100 + 130 * k);
            }
            long each = (threads.getThreadAllocatedBytes(thread) - before) / 5;
            assertTrue(each < 1_000_000, "page " + n + ": " + each + " bytes allocated an inspection");
        }
    }
}
