package simpview.inspect;

import java.util.ArrayList;
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

    /**
     * A line that wrote one or more of the eight pixels around a pixel no line reached: where it went instead.
     * Its ends are given as the page gives them; {@link #minorAt} is where the line through its rounded ends
     * is at the pixel's major coordinate, the value a DDA rounds there.
     */
    public static final class Beside {
        private final int number;
        int of;
        private final double[] ends;
        private final List<int[]> pixels = new ArrayList<>();

        Beside(int number, Vertex p, Vertex q) {
            this.number = number;
            this.ends = new double[] {p.x(), p.y(), q.x(), q.y()};
        }

        void add(int x, int y) {
            for (int[] known : pixels) {
                if (known[0] == x && known[1] == y) {
                    return;
                }
            }
            pixels.add(new int[] {x, y});
        }

        /** 1, 2, ... in the panel's drawing order. */
        public int number() {
            return number;
        }

        /** How many lines the panel draws. */
        public int of() {
            return of;
        }

        /** The line's x0, y0, x1, y1 as given, panel coordinates. */
        public double[] ends() {
            return ends.clone();
        }

        /** The pixels next to the inspected one it wrote, each {x, y} in panel coordinates, in drawing order. */
        public List<int[]> pixels() {
            return pixels.stream().map(int[]::clone).toList();
        }

        /** Whether its rounded ends make it x-major (|dx| at least |dy|), as every drawer walks it. */
        public boolean xMajor() {
            return Math.abs(round(ends[2]) - round(ends[0])) >= Math.abs(round(ends[3]) - round(ends[1]));
        }

        /**
         * The minor coordinate (y of an x-major line, x of a y-major one) of the line through its rounded ends at
         * the major coordinate {@code major}; NaN for a line of one pixel.
         */
        public double minorAt(double major) {
            double ax = round(ends[0]);
            double ay = round(ends[1]);
            double bx = round(ends[2]);
            double by = round(ends[3]);
            if (xMajor()) {
                return ax == bx ? Double.NaN : ay + (major - ax) * (by - ay) / (bx - ax);
            }
            return ax + (major - ay) * (bx - ax) / (by - ay);
        }
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
    private final List<Beside> beside;

    A1Report(int page, String title, boolean lines, Long seed, A1Rule rule, int x, int y, int column, int row, int argb,
            int panel, String drawer, int panelX, int panelY, List<Write> writes, List<CentreCase> centre,
            List<Beside> beside) {
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
        this.beside = List.copyOf(beside);
    }

    /**
     * On a page of lines, for a pixel no line reached: the lines that wrote a pixel next to it, in drawing
     * order; empty otherwise.
     */
    public List<Beside> beside() {
        return beside;
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
            } else if (writes.isEmpty()) {
                besideText(sb);
            }
        }
        return sb.toString();
    }

    /**
     * The lines that went past this pixel: which of its neighbours each wrote, and where the line through its
     * rounded ends is at this pixel's column (an x-major line) or row (a y-major one).
     */
    private void besideText(StringBuilder sb) {
        if (beside.isEmpty()) {
            sb.append("beside: no line wrote any of the eight pixels around it either\n");
            return;
        }
        sb.append("beside: the lines that wrote a pixel next to it, and where each is at this pixel's column (x-major)"
                + " or row (y-major), on the line through its rounded ends:\n");
        for (Beside b : beside) {
            sb.append("  line ").append(b.number()).append(" of ").append(b.of()).append(", ")
                    .append(point(b.ends[0], b.ends[1])).append(" to ").append(point(b.ends[2], b.ends[3]));
            if (!(isWhole(b.ends[0]) && isWhole(b.ends[1]) && isWhole(b.ends[2]) && isWhole(b.ends[3]))) {
                sb.append(", rounded ").append(point(round(b.ends[0]), round(b.ends[1]))).append(" to ")
                        .append(point(round(b.ends[2]), round(b.ends[3])));
            }
            sb.append(": wrote ");
            List<int[]> pixels = b.pixels();
            for (int k = 0; k < pixels.size(); k++) {
                int[] p = pixels.get(k);
                sb.append(k == 0 ? "" : ", ").append(point(p[0], p[1])).append(' ').append(direction(p[0], p[1]));
            }
            char major = b.xMajor() ? 'x' : 'y';
            char minor = b.xMajor() ? 'y' : 'x';
            int here = b.xMajor() ? panelX : panelY;
            int mine = b.xMajor() ? panelY : panelX;
            double at = b.minorAt(here);
            double first = b.xMajor() ? round(b.ends[0]) : round(b.ends[1]);
            double last = b.xMajor() ? round(b.ends[2]) : round(b.ends[3]);
            if (pastEnd(b)) {
                // beyond the line's last pixel along its major axis: it stops there, wherever the line through
                // its ends would be
                boolean pastSecond = here > Math.max(first, last) == last > first;
                double endX = round(pastSecond ? b.ends[2] : b.ends[0]);
                double endY = round(pastSecond ? b.ends[3] : b.ends[1]);
                sb.append(String.format(Locale.ROOT, "; %c %d is past its end %s, where it stops: a line is drawn"
                        + " between its rounded ends, both included, and no further", major, here,
                        point(endX, endY)));
            } else if (!Double.isNaN(at)) {
                sb.append(String.format(Locale.ROOT, "; at %c %d it is at %c %s, which rounds to %d, %s from this"
                        + " pixel's %d", major, here, minor, decimal(at), (long) round(at), decimal(Math.abs(at - mine)),
                        mine));
            }
            sb.append('\n');
        }
    }


    /**
     * Whether this pixel's column (of an x-major line; its row of a y-major one) is beyond the line's rounded
     * ends, where no drawer writes it: the line through the ends goes on there, the line drawn does not.
     */
    private boolean pastEnd(Beside b) {
        int here = b.xMajor() ? panelX : panelY;
        double first = b.xMajor() ? round(b.ends[0]) : round(b.ends[1]);
        double last = b.xMajor() ? round(b.ends[2]) : round(b.ends[3]);
        return here < Math.min(first, last) || here > Math.max(first, last);
    }

    /** Where panel pixel (px, py) is from the inspected one: "above", "below left", ... */
    private String direction(int px, int py) {
        String vertical = py > panelY ? "above" : py < panelY ? "below" : "";
        String horizontal = px > panelX ? "right" : px < panelX ? "left" : "";
        return vertical.isEmpty() ? horizontal : horizontal.isEmpty() ? vertical : vertical + " " + horizontal;
    }

    /** At most three decimals, no trailing zeros: 152.333, 0.5, 3. */
    private static String decimal(double v) {
        String s = String.format(Locale.ROOT, "%.3f", v);
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
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
            if (lines && panel != 0 && writes.isEmpty()) {
                besideJson(sb.append(", \"beside\": ["));
                sb.append(']');
            }
            sb.append('}');
        }
        return sb.append('}').toString();
    }

    /**
     * The lines beside a pixel no line reached, as JSON objects, comma-separated: each line's number, its ends as
     * given, the neighbours it wrote, its major axis and where it is on the minor one at this pixel's major
     * coordinate (null for a line of one pixel).
     */
    private void besideJson(StringBuilder sb) {
        for (int k = 0; k < beside.size(); k++) {
            Beside b = beside.get(k);
            sb.append(k == 0 ? "" : ", ").append("{\"primitive\": ").append(b.number()).append(", \"vertices\": [[");
            Json.number(sb, b.ends[0]);
            sb.append(", ");
            Json.number(sb, b.ends[1]);
            sb.append("], [");
            Json.number(sb, b.ends[2]);
            sb.append(", ");
            Json.number(sb, b.ends[3]);
            sb.append("]], \"pixels\": [");
            List<int[]> pixels = b.pixels();
            for (int i = 0; i < pixels.size(); i++) {
                sb.append(i == 0 ? "[" : ", [").append(pixels.get(i)[0]).append(", ").append(pixels.get(i)[1]).append(']');
            }
            double at = b.minorAt(b.xMajor() ? panelX : panelY);
            sb.append("], \"major\": \"").append(b.xMajor() ? 'x' : 'y').append("\", \"minor_here\": ");
            if (Double.isNaN(at)) {
                sb.append("null");
            } else {
                Json.number(sb, at);
            }
            sb.append(", \"past_end\": ").append(pastEnd(b)).append('}');
        }
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
