package simpview.cli;

import java.util.List;
import simpview.pages.A1Polygons;
import simpview.pages.LineTestPage;
import simpview.pages.ListedPrimitive;
import simpview.pages.Page;
import simpview.pages.PageContext;
import simpview.pages.PolygonTestPage;
import simpview.surface.Colors;

/**
 * What {@code render --page N --primitives F} writes: the lines and
 * triangles the page makes itself, one a line ({@link ListedPrimitive#text}),
 * after a few lines of '#' saying what they are. A student draws them with
 * their own renderer and compares the picture with simpview's: the seeded
 * pages then hold the same random lines, triangles and colours.
 */
final class PrimitiveListing {

    /** The widest a header line is, '#' and all: a sentence longer than one is wrapped at words. */
    static final int WIDTH = 100;

    private PrimitiveListing() {
    }

    /** The listing of page {@code number} (named as {@code which}: "page 2", "the first assignment's page 3"). */
    static String of(Page page, String which, PageContext context) {
        List<ListedPrimitive> primitives = page.primitives(context);
        long lines = primitives.stream().filter(ListedPrimitive::isLine).count();
        StringBuilder out = new StringBuilder();
        out.append("# simpview: ").append(which).append(", ").append(page.title())
                .append(page.usesSeed() ? ", seed " + context.seed() : "").append(": ")
                .append(count(lines, "line")).append(", ").append(count(primitives.size() - lines, "triangle"))
                .append('\n');
        out.append("# in drawing order, panel by panel, as simpview's drawers are given them:\n");
        out.append("#   line PANEL x0 y0 z0 r0 g0 b0 x1 y1 z1 r1 g1 b1\n");
        out.append("#   triangle PANEL x0 y0 z0 r0 g0 b0 x1 y1 z1 r1 g1 b1 x2 y2 z2 r2 g2 b2\n");
        out.append("# x right, y up from the panel's bottom-left pixel, in pixels; colours 0 to 1; each number the\n");
        out.append("# shortest decimal that reads back as simpview's double\n");
        out.append(comment(panels(page)));
        if (page instanceof LineTestPage && page.usesSeed() && !primitives.isEmpty()) {
            // The random colours are whole levels (A1Lines.wholeLevels): say so, so that a student blends the
            // colour printed and gets simpview's bytes, and knows the byte a whole pixel of it gets.
            double r = primitives.get(0).vertices().get(0).r();
            out.append(comment("each colour channel is a whole number of 255ths, k / 255 (the first line's red, " + r
                    + ", is " + Colors.toByte(r) + " / 255): k is the byte a pixel the line covers whole gets; the "
                    + "antialiased panel blends this colour, c * colour + (1 - c) * old"));
        }
        for (ListedPrimitive p : primitives) {
            out.append(p.text()).append('\n');
        }
        return out.toString();
    }

    /** How each panel draws what it is given. */
    private static String panels(Page page) {
        if (page instanceof LineTestPage) {
            StringBuilder out = new StringBuilder("the same lines in each panel, drawn by panel");
            for (int k = 0; k < LineTestPage.DRAWERS.size(); k++) {
                out.append(k == 0 ? " " : ", ").append(k + 1).append(": ").append(LineTestPage.DRAWERS.get(k));
            }
            return out.append(" (ends rounded first)").toString();
        }
        if (page instanceof PolygonTestPage polygons) {
            StringBuilder out = new StringBuilder("panel k draws scene k:");
            for (int k = 0; k < A1Polygons.NAMES.size(); k++) {
                out.append(k == 0 ? " " : ", ").append(k + 1).append(": ").append(A1Polygons.NAMES.get(k));
            }
            return out.append(polygons.ghost() ? " (each white at opacity 0.14: the colours are not drawn)"
                    : " (each triangle filled with its colour)").toString();
        }
        return "one panel: " + page.title();
    }

    /**
     * A sentence as header lines of '#', each at most {@link #WIDTH} wide, broken between words (a word longer
     * than a line has one to itself), as the header's fixed lines are.
     */
    static String comment(String sentence) {
        StringBuilder out = new StringBuilder();
        StringBuilder line = new StringBuilder("#");
        for (String word : sentence.split(" ")) {
            if (line.length() > 1 && line.length() + 1 + word.length() > WIDTH) {
                out.append(line).append('\n');
                line = new StringBuilder("#");
            }
            line.append(' ').append(word);
        }
        return out.append(line).append('\n').toString();
    }

    private static String count(long n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }
}
