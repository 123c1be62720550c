package simpview.compare;

import java.util.Locale;
import simpview.geometry.Vertex;
import simpview.pages.A1Polygons;
import simpview.raster.CentreTest;
import simpview.surface.PageCanvas;

/**
 * A first-assignment polygon panel filled without the top-left rule: most of the pixels that differ have their
 * centres exactly on an edge of one of simpview's triangles, where SPEC's fill rule decides by the edge's side
 * (drawn only for a top or left edge). Filled by "inside or on any edge" such a pixel is drawn by both triangles
 * that share the edge (the later one's colour shows; on the ghost page it is blended twice, brighter); by "strictly
 * inside" by neither (a gap: black, or darker). Which edges a centre lies on is asked of the rasterizer's own exact
 * edge tests ({@link CentreTest}), so the pixels counted are the ones the rule decides.
 *
 * @param onEdges how many of the differing pixels have their centres on an edge
 * @param shared how many of those are on an edge of two triangles (or more)
 * @param gaps how many of those the picture leaves black or darker: drawn by neither
 * @param differing how many pixels of the panel differ beyond the tolerance
 * @param edgePixels how many pixels of the panel have their centres on an edge
 * @param example one such pixel, in words: "(45, 45), on the edges of triangles 3 and 4"
 */
public record FillRule(int onEdges, int shared, int gaps, int differing, int edgePixels, String example)
        implements PanelHint {

    /** At least this many differing pixels on edges ... */
    static final int LEAST = 3;
    /** ... and at least this share of those that differ. */
    static final double MOST = 0.8;

    /**
     * The hint for a polygon panel of n x n pixels (ours and theirs row by row from the top) filling the triangles
     * {@code scene} ({@link A1Polygons#scene}: three vertices each, moved by the rule's row shift), blended at
     * opacity on the ghost page ({@code ghost}); null when too few of its differing pixels lie on edges.
     */
    public static FillRule find(int[] ours, int[] theirs, int n, int tolerance, double[] scene, boolean ghost) {
        int differing = 0;
        for (int i = 0; i < n * n; i++) {
            differing += Rasters.distance(ours[i], theirs[i]) > tolerance ? 1 : 0;
        }
        if (differing < LEAST) {
            return null;
        }
        int[] on = new int[n * n]; // how many triangles have the pixel's centre on an edge
        int[] first = new int[n * n]; // the first two of them, from 1
        int[] second = new int[n * n];
        int triangles = scene.length / (3 * Vertex.NUMBERS);
        for (int t = 0; t < triangles; t++) {
            int at = A1Polygons.at(t);
            double[] x = {scene[at], scene[at + Vertex.NUMBERS], scene[at + 2 * Vertex.NUMBERS]};
            double[] y = {scene[at + 1], scene[at + Vertex.NUMBERS + 1], scene[at + 2 * Vertex.NUMBERS + 1]};
            markEdges(x, y, n, t + 1, on, first, second);
        }
        int edgePixels = 0;
        int onEdges = 0;
        int shared = 0;
        int gaps = 0;
        String example = null;
        for (int i = 0; i < n * n; i++) {
            if (on[i] == 0) {
                continue;
            }
            edgePixels++;
            if (Rasters.distance(ours[i], theirs[i]) <= tolerance) {
                continue;
            }
            onEdges++;
            shared += on[i] >= 2 ? 1 : 0;
            gaps += ghost ? (darker(theirs[i], ours[i]) ? 1 : 0)
                    : (theirs[i] & 0xFFFFFF) == (PageCanvas.BACKGROUND & 0xFFFFFF) ? 1 : 0;
            if (example == null) {
                example = "(" + i % n + ", " + (n - 1 - i / n) + "), on the edge"
                        + (on[i] >= 2 ? "s of triangles " + first[i] + " and " + second[i] : " of triangle " + first[i]);
            }
        }
        if (onEdges < LEAST || onEdges < MOST * differing) {
            return null;
        }
        return new FillRule(onEdges, shared, gaps, differing, edgePixels, example);
    }

    /**
     * Counts, for each pixel whose centre lies on an edge of the triangle numbered {@code number} and not outside it,
     * that it does; keeps the first two such triangles.
     */
    private static void markEdges(double[] x, double[] y, int n, int number, int[] on, int[] first, int[] second) {
        int x0 = (int) Math.max(0, Math.floor(Math.min(x[0], Math.min(x[1], x[2]))) - 1);
        int x1 = (int) Math.min(n - 1, Math.ceil(Math.max(x[0], Math.max(x[1], x[2]))));
        int y0 = (int) Math.max(0, Math.floor(Math.min(y[0], Math.min(y[1], y[2]))) - 1);
        int y1 = (int) Math.min(n - 1, Math.ceil(Math.max(y[0], Math.max(y[1], y[2]))));
        for (int e = 0; e < 3; e++) {
            int f = (e + 1) % 3;
            double dx = x[f] - x[e];
            double dy = y[f] - y[e];
            double slack = 1e-9 * (Math.abs(dx) + Math.abs(dy) + 1);
            for (int py = y0; py <= y1; py++) {
                for (int px = x0; px <= x1; px++) {
                    double cx = px + 0.5;
                    double cy = py + 0.5;
                    // near the edge's line by a quick cross product; the rasterizer's own test decides
                    if (Math.abs(dx * (cy - y[e]) - dy * (cx - x[e])) > slack * (Math.abs(cx) + Math.abs(cy) + 1)) {
                        continue;
                    }
                    int[] sides = CentreTest.sides(x[0], y[0], x[1], y[1], x[2], y[2], cx, cy);
                    if (sides == null) {
                        return; // a degenerate triangle draws nothing
                    }
                    boolean onEdge = false;
                    boolean outside = false;
                    for (int s : sides) {
                        onEdge |= s == CentreTest.ON_TOP_OR_LEFT || s == CentreTest.ON_RIGHT_OR_BOTTOM;
                        outside |= s == CentreTest.OUTSIDE;
                    }
                    int i = (n - 1 - py) * n + px;
                    if (!onEdge || outside || first[i] == number || second[i] == number) {
                        continue; // a vertex's pixel: counted once for its triangle
                    }
                    on[i]++;
                    if (first[i] == 0) {
                        first[i] = number;
                    } else if (second[i] == 0) {
                        second[i] = number;
                    }
                }
            }
        }
    }

    /** Whether {@code a} is no lighter than {@code b} in any channel, and darker in one. */
    private static boolean darker(int a, int b) {
        boolean less = false;
        for (int shift = 0; shift <= 16; shift += 8) {
            int ca = a >> shift & 0xFF;
            int cb = b >> shift & 0xFF;
            if (ca > cb) {
                return false;
            }
            less |= ca < cb;
        }
        return less;
    }

    @Override
    public String brief() {
        return "to fill without the top-left rule: pixels whose centres lie on an edge " + (gaps == 0 ? "drawn twice"
                : gaps == onEdges ? "left out" : "left out or drawn twice");
    }

    @Override
    public String hint(int n) {
        int twice = onEdges - gaps;
        String which = gaps == 0 ? "draws all of them twice, by both triangles there"
                : twice == 0 ? "leaves all of them out: a gap, drawn by neither triangle"
                : String.format(Locale.ROOT, "leaves %,d of them out (a gap, drawn by neither triangle) and draws %,d "
                        + "twice, by both", gaps, twice);
        return String.format(Locale.ROOT, "your fill does not keep the top-left rule: %,d of the %s that differ have "
                + "their centres exactly on an edge of simpview's triangles (the panel has %s such pixels), %,d of them "
                + "on an edge two triangles share; yours %s (%s). SPEC draws a centre that lies exactly on an edge only "
                + "for a top or left edge, so two triangles that share an edge draw each pixel on it once: no gaps, no "
                + "double writes (Rasterization rules).", onEdges, Count.of(differing, "pixel"),
                String.format(Locale.ROOT, "%,d", edgePixels), shared, which, example);
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}
