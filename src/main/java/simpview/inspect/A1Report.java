package simpview.inspect;

import java.util.List;
import java.util.Locale;
import simpview.geometry.Vertex;
import simpview.pages.A1Layout;
import simpview.pages.A1Rule;
import simpview.raster.AntialiasedLineRenderer;

/**
 * What the replay of one pixel of a first-assignment page found: the pixel's
 * colour on the page, its panel and the panel's drawer, and every write at
 * it in drawing order, each with the line (its endpoints as written and
 * rounded, as every drawer rounds them) or triangle that made it, the colour
 * it came with, its outcome ({@code written}, or {@code blended} with a
 * coverage) and the pixel's colour before and after it. Text or JSON.
 */
public final class A1Report {

    /** One write at the pixel. */
    public static final class Write {
        int primitive;
        int of;
        boolean line;
        double[] ends;
        double z;
        int argb;
        boolean blended;
        double coverage = Double.NaN;
        int old;
        int now;

        static Write line(int i, Vertex p, Vertex q) {
            Write w = new Write();
            w.primitive = i;
            w.line = true;
            w.ends = new double[] {p.x(), p.y(), q.x(), q.y()};
            return w;
        }

        static Write triangle(int i, double[] n, int at) {
            Write w = new Write();
            w.primitive = i;
            w.ends = new double[6];
            for (int k = 0; k < 3; k++) {
                w.ends[2 * k] = n[at + k * Vertex.NUMBERS + Vertex.X];
                w.ends[2 * k + 1] = n[at + k * Vertex.NUMBERS + Vertex.Y];
            }
            return w;
        }

        /** 1, 2, ... in the panel's drawing order. */
        public int number() {
            return primitive + 1;
        }

        /** How many lines or triangles the panel draws. */
        public int of() {
            return of;
        }

        public boolean isLine() {
            return line;
        }

        /** A line's x0, y0, x1, y1 or a triangle's x0, y0, x1, y1, x2, y2 as given, panel coordinates. */
        public double[] ends() {
            return ends.clone();
        }

        public double z() {
            return z;
        }

        /** The colour the write came with (a ghost write: white), 0xAARRGGBB. */
        public int argb() {
            return argb;
        }

        public Outcome outcome() {
            return blended ? Outcome.BLENDED : Outcome.WRITTEN;
        }

        /** The write's coverage (a ghost write: its opacity); NaN for a write that was not blended. */
        public double coverage() {
            return coverage;
        }

        /**
         * For a line's write, the distance the antialiased drawer measures from the line through its rounded
         * ends to the pixel (x, y) of the panel; its coverage there is that distance's.
         */
        public double distanceFrom(int x, int y) {
            return AntialiasedLineRenderer.distance(x, y, round(ends[0]), round(ends[1]), round(ends[2]),
                    round(ends[3]));
        }

        /** The pixel's colour before the write and after it. */
        public int old() {
            return old;
        }

        public int now() {
            return now;
        }

        /** "line 12 of 90, (150, 150) to (285, 150) rounded" or "triangle 3 of 20, (x, y) (x, y) (x, y)". */
        public String describe() {
            StringBuilder sb = new StringBuilder(line ? "line " : "triangle ").append(number()).append(" of ").append(of)
                    .append(", ");
            if (line) {
                sb.append(point(ends[0], ends[1])).append(" to ").append(point(ends[2], ends[3]));
                if (!(isWhole(ends[0]) && isWhole(ends[1]) && isWhole(ends[2]) && isWhole(ends[3]))) {
                    sb.append(", rounded ").append(point(round(ends[0]), round(ends[1]))).append(" to ")
                            .append(point(round(ends[2]), round(ends[3])));
                }
            } else {
                sb.append(point(ends[0], ends[1])).append(' ').append(point(ends[2], ends[3])).append(' ')
                        .append(point(ends[4], ends[5]));
            }
            return sb.toString();
        }
    }

    /**
     * One triangle of a polygon panel whose box holds the pixel's centre, and what Part 1's fill rule says of
     * that centre and it, by the rasterizer's own edge tests ({@link VertexTable#centre}).
     *
     * @param number the triangle, 1, 2, ... in the panel's drawing order
     * @param covered whether it covers the centre
     * @param why in words, naming the top-left rule where the centre is on an edge
     */
    public record CentreCase(int number, boolean covered, String why) {
    }

    private final int page;
    private final String title;
    private final Long seed;
    private final A1Rule rule;
    private final int x;
    private final int y;
    private final int column;
    private final int row;
    private final int argb;
    private final int panel;
    private final String drawer;
    private final int panelX;
    private final int panelY;
    private final List<Write> writes;
    private final boolean lines;
    private final List<CentreCase> centre;

    A1Report(int page, String title, boolean lines, Long seed, A1Rule rule, int x, int y, int column, int row, int argb,
            int panel, String drawer, int panelX, int panelY, List<Write> writes, List<CentreCase> centre) {
        this.page = page;
        this.lines = lines;
        this.title = title;
        this.seed = seed;
        this.rule = rule;
        this.x = x;
        this.y = y;
        this.column = column;
        this.row = row;
        this.argb = argb;
        this.panel = panel;
        this.drawer = drawer;
        this.panelX = panelX;
        this.panelY = panelY;
        this.writes = List.copyOf(writes);
        this.centre = List.copyOf(centre);
    }

    /**
     * On a polygon panel, the triangles whose box holds the pixel's centre and why each covers it or not, in
     * drawing order; empty on a page of lines and in the margins.
     */
    public List<CentreCase> centre() {
        return centre;
    }

    /** The pixel's colour on the page, 0xAARRGGBB. */
    public int argb() {
        return argb;
    }

    /** The panel (1 to 4) holding the pixel, or 0 in the margins. */
    public int panel() {
        return panel;
    }

    /** The panel's drawer ("DDA", "antialiased", "filled", ...), or null in the margins. */
    public String drawer() {
        return drawer;
    }

    /** The pixel in its panel's coordinates (x right, y up from the panel's bottom-left pixel); -1 in the margins. */
    public int panelX() {
        return panelX;
    }

    public int panelY() {
        return panelY;
    }

    public List<Write> writes() {
        return writes;
    }

    public String text() {
        return text(true, true);
    }

    /** The report as text: the pixel and its panel, then the history and the explanation as asked. */
    public String text(boolean withHistory, boolean withExplanation) {
        StringBuilder sb = new StringBuilder();
        sb.append("pixel (").append(x).append(", ").append(y).append(") of the first assignment's page ").append(page)
                .append(" (").append(title).append(seed == null ? "" : ", seed " + seed)
                .append(rule == A1Rule.SPEC ? "" : ", by " + rule.label()).append("; image pixel ")
                .append(column).append(", row ").append(row).append("): rgb ").append(rgb(argb)).append('\n');
        if (panel == 0) {
            sb.append("in ").append(A1Layout.whiteAround(column, row)).append(": nothing is drawn here\n");
            return sb.toString();
        }
        sb.append("panel ").append(panel).append(" (").append(drawer).append("), panel pixel (").append(panelX)
                .append(", ").append(panelY).append(")\n");
        if (withHistory) {
            history(sb);
        }
        if (withExplanation) {
            sb.append("explain: final_rgb ").append(rgb(argb)).append(writes.isEmpty() ? ", the panel's black: no "
                    + (lines ? "line" : "triangle") + " reached this pixel" : ", the last write's new colour")
                    .append('\n');
            if (!lines) {
                centreText(sb);
            }
        }
        return sb.toString();
    }

    /** The pixel's centre and the triangles whose box holds it, each covering it or not and why. */
    private void centreText(StringBuilder sb) {
        sb.append("centre: (").append(Json.number(panelX + 0.5)).append(", ").append(Json.number(panelY + 0.5))
                .append("), by Part 1's fill rule").append(rule == A1Rule.SPEC ? ""
                        : " on the triangles moved up " + Json.number(rule.rowShift()) + " px (" + rule.label() + ")")
                .append(centre.isEmpty() ? ": no triangle's box holds it" : ":").append('\n');
        for (CentreCase c : centre) {
            sb.append("  triangle ").append(c.number()).append(c.covered() ? ": covers it: " : ": does not: ")
                    .append(c.why()).append('\n');
        }
    }

    private void history(StringBuilder sb) {
        sb.append("history: ").append(writes.size()).append(writes.size() == 1 ? " write" : " writes")
                .append(", in drawing order\n");
        for (Write w : writes) {
            sb.append("  ").append(w.describe()).append('\n').append("      ").append(w.outcome().word());
            if (w.blended) {
                sb.append(String.format(Locale.ROOT, " with coverage %.6f", w.coverage));
                if (w.line) {
                    sb.append(String.format(Locale.ROOT, " (the pixel at distance %.6f from the line)",
                            w.distanceFrom(panelX, panelY)));
                }
            }
            sb.append(", rgb ").append(rgb(w.argb)).append(": ").append(rgb(w.old)).append(" -> ").append(rgb(w.now))
                    .append('\n');
        }
    }

    public String json() {
        return json(true, true);
    }

    /** The report as one JSON object: "pixel", "panel", then "history" and "explain" as asked. */
    public String json(boolean withHistory, boolean withExplanation) {
        StringBuilder sb = new StringBuilder("{\"pixel\": {\"x\": ").append(x).append(", \"y\": ").append(y)
                .append(", \"image_x\": ").append(column).append(", \"image_row\": ").append(row).append(", \"rgb\": ")
                .append(array(argb)).append(", \"depth\": null}, \"assignment\": 1, \"page\": ").append(page)
                .append(", \"title\": ");
        Json.string(sb, title);
        sb.append(", \"seed\": ").append(seed == null ? "null" : seed.toString()).append(", \"rule\": ");
        Json.string(sb, rule.key());
        sb.append(", \"panel\": ");
        if (panel == 0) {
            sb.append("null");
        } else {
            sb.append("{\"number\": ").append(panel).append(", \"drawer\": ");
            Json.string(sb, drawer);
            sb.append(", \"x\": ").append(panelX).append(", \"y\": ").append(panelY).append('}');
        }
        if (withHistory) {
            historyJson(sb.append(", \"history\": ["));
            sb.append(']');
        }
        if (withExplanation) {
            sb.append(", \"explain\": {\"final_rgb\": ").append(array(argb)).append(", \"writes\": ")
                    .append(writes.size()).append(", \"background\": ").append(writes.isEmpty());
            if (!lines && panel != 0) {
                sb.append(", \"centre\": {\"x\": ");
                Json.number(sb, panelX + 0.5);
                sb.append(", \"y\": ");
                Json.number(sb, panelY + 0.5);
                sb.append(", \"triangles\": [");
                for (int k = 0; k < centre.size(); k++) {
                    CentreCase c = centre.get(k);
                    sb.append(k == 0 ? "{" : ", {").append("\"triangle\": ").append(c.number())
                            .append(", \"covered\": ").append(c.covered()).append(", \"why\": ");
                    Json.string(sb, c.why());
                    sb.append('}');
                }
                sb.append("]}");
            }
            sb.append('}');
        }
        return sb.append('}').toString();
    }

    /** The history's entries as JSON objects, comma-separated. */
    private void historyJson(StringBuilder sb) {
        for (int k = 0; k < writes.size(); k++) {
            Write w = writes.get(k);
            sb.append(k == 0 ? "" : ", ").append("{\"primitive\": ").append(w.number()).append(", \"kind\": ")
                    .append(w.line ? "\"line\"" : "\"triangle\"").append(", \"chain\": [");
            Json.string(sb, "page " + page);
            sb.append(", ");
            Json.string(sb, "panel " + panel + " (" + drawer + ")");
            sb.append(", ");
            Json.string(sb, (w.line ? "line " : "triangle ") + w.number() + " of " + w.of);
            sb.append("], \"vertices\": [");
            for (int v = 0; v < w.ends.length; v += 2) {
                sb.append(v == 0 ? "[" : ", [");
                Json.number(sb, w.ends[v]);
                sb.append(", ");
                Json.number(sb, w.ends[v + 1]);
                sb.append(']');
            }
            sb.append(']');
            if (w.line) {
                sb.append(", \"pixels\": [[").append((long) round(w.ends[0])).append(", ").append((long) round(w.ends[1]))
                        .append("], [").append((long) round(w.ends[2])).append(", ").append((long) round(w.ends[3]))
                        .append("]]");
            }
            sb.append(", \"z\": ");
            Json.number(sb, w.z);
            sb.append(", \"rgb\": ").append(array(w.argb)).append(", \"outcome\": \"").append(w.outcome().word())
                    .append('"');
            if (w.blended) {
                sb.append(", \"coverage\": ");
                Json.number(sb, w.coverage);
                if (w.line) {
                    sb.append(", \"distance\": ");
                    Json.number(sb, w.distanceFrom(panelX, panelY));
                }
            }
            sb.append(", \"old\": ").append(array(w.old)).append(", \"new\": ").append(array(w.now)).append('}');
        }
    }

    private static String rgb(int c) {
        return "(" + (c >>> 16 & 0xFF) + ", " + (c >>> 8 & 0xFF) + ", " + (c & 0xFF) + ")";
    }

    private static String array(int c) {
        return "[" + (c >>> 16 & 0xFF) + ", " + (c >>> 8 & 0xFF) + ", " + (c & 0xFF) + "]";
    }

    private static double round(double v) {
        return Math.floor(v + 0.5);
    }

    private static boolean isWhole(double v) {
        return v == Math.rint(v);
    }

    private static String point(double px, double py) {
        return "(" + Json.number(px) + ", " + Json.number(py) + ")";
    }
}
