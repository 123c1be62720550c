package simpview.pages;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.IntConsumer;
import java.util.function.LongFunction;
import simpview.geometry.Vertex;
import simpview.raster.AlternatingLineRenderer;
import simpview.raster.AntialiasedLineRenderer;
import simpview.raster.DdaLineRenderer;
import simpview.raster.LineRenderer;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/**
 * One of the first assignment's line pages (SPEC Part 3, pages 1 to 3): the
 * same lines on all four panels, each panel with its drawer: 1 DDA,
 * 2 Bresenham, 3 alternating (DDA first), 4 antialiased.
 */
public final class LineTestPage implements A1Page {

    /** What draws each panel, in panel order (1..4): its name, and whether the rule changes it. */
    private enum Drawer {
        DDA("DDA", false),
        BRESENHAM("Bresenham", true),
        ALTERNATING("alternating DDA / Bresenham", true),
        ANTIALIASED("antialiased", false);

        private final String name;
        private final boolean byRule;

        Drawer(String name, boolean byRule) {
            this.name = name;
            this.byRule = byRule;
        }

        /** A fresh one under the rule. */
        LineRenderer make(A1Rule rule) {
            return switch (this) {
                case DDA -> new DdaLineRenderer();
                case BRESENHAM -> rule.bresenham();
                case ALTERNATING -> new AlternatingLineRenderer(new DdaLineRenderer(), rule.bresenham());
                case ANTIALIASED -> new AntialiasedLineRenderer();
            };
        }

        static Drawer ofPanel(int panel) {
            if (panel < 1 || panel > values().length) {
                throw new IllegalArgumentException("panels are 1 to " + values().length + ", not " + panel);
            }
            return values()[panel - 1];
        }
    }

    /** What draws panel k (1..4) at k - 1, as the inspector and the docs name it. */
    public static final List<String> DRAWERS = Arrays.stream(Drawer.values()).map(d -> d.name).toList();

    private final String title;
    private final boolean seeded;
    private final LongFunction<A1Lines> lines;

    private LineTestPage(String title, boolean seeded, LongFunction<A1Lines> lines) {
        this.title = title;
        this.seeded = seeded;
        this.lines = lines;
    }

    public static LineTestPage starburst() {
        return new LineTestPage("Starburst", false, seed -> A1Lines.starburst());
    }

    public static LineTestPage parallelogram() {
        return new LineTestPage("Parallelogram", false, seed -> A1Lines.parallelogram());
    }

    public static LineTestPage random() {
        return new LineTestPage("Random lines", true, A1Lines::random);
    }

    @Override
    public String title() {
        return title;
    }

    @Override
    public boolean usesSeed() {
        return seeded;
    }

    /** The page's lines, the same in each of the four panels. */
    @Override
    public List<ListedPrimitive> primitives(PageContext context) {
        A1Lines set = lines(context.seed());
        List<ListedPrimitive> out = new ArrayList<>();
        for (int panel = 1; panel <= A1Layout.PANELS; panel++) {
            for (int i = 0; i < set.count(); i++) {
                out.add(new ListedPrimitive(panel, List.of(set.start(i), set.end(i))));
            }
        }
        return out;
    }

    @Override
    public List<String> panelNames() {
        return DRAWERS;
    }

    /** The page's lines for this seed. */
    public A1Lines lines(long seed) {
        return lines.apply(seed);
    }

    /** Panel k's drawer by name, with the rule where the rule changes it. */
    public static String drawerName(int panel, A1Rule rule) {
        Drawer drawer = Drawer.ofPanel(panel);
        return drawer.name + (drawer.byRule ? rule.drawerNote() : "");
    }

    /** A fresh drawer for panel k (1..4) under the rule; the alternating one counts from its first line. */
    public static LineRenderer drawer(int panel, A1Rule rule) {
        return Drawer.ofPanel(panel).make(rule);
    }

    @Override
    public void draw(PageCanvas canvas, PageContext context) {
        drawSteps(canvas, context, Integer.MAX_VALUE);
    }

    @Override
    public int steps(PageContext context) {
        return lines(context.seed()).count();
    }

    @Override
    public void drawSteps(PageCanvas canvas, PageContext context, int steps) {
        Drawable[] panels = A1Layout.paint(canvas);
        A1Lines set = lines(context.seed());
        int count = Math.min(Math.max(steps, 0), set.count());
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            drawPanel(k, context.a1Rule(), set, count, panels[k - 1], null);
        }
    }

    /**
     * Draws panel k's lines (k = 1..4) onto its panel, in order, by the
     * panel's drawer under the rule; {@code beforeLine}, unless null, is told
     * each line's index (0, 1, ...) before it is drawn (the inspector's
     * replay of one pixel).
     */
    public static void drawPanel(int k, A1Rule rule, A1Lines set, Drawable panel, IntConsumer beforeLine) {
        drawPanel(k, rule, set, set.count(), panel, beforeLine);
    }

    /** The same, the first {@code count} lines only. */
    private static void drawPanel(int k, A1Rule rule, A1Lines set, int count, Drawable panel, IntConsumer beforeLine) {
        LineRenderer drawer = drawer(k, rule);
        double[] n = set.numbers();
        for (int i = 0; i < count; i++) {
            if (beforeLine != null) {
                beforeLine.accept(i);
            }
            drawer.drawLine(n, A1Lines.from(i), A1Lines.to(i), panel);
        }
    }

    /** E.g. "line 24 of 90, (150, 150) to (145.289, 284.918), rounded (150, 150) to (145, 285), ...; panel 3 by the Bresenham". */
    @Override
    public String describeStep(PageContext context, int step) {
        A1Lines set = lines(context.seed());
        int i = Math.min(Math.max(step, 1), set.count()) - 1;
        Vertex p = set.start(i);
        Vertex q = set.end(i);
        return String.format(Locale.ROOT,
                "line %d of %d, (%s, %s) to (%s, %s), rounded (%.0f, %.0f) to (%.0f, %.0f), in every panel; panel 3 by the %s",
                i + 1, set.count(), number(p.x()), number(p.y()), number(q.x()), number(q.y()), Math.floor(p.x() + 0.5),
                Math.floor(p.y() + 0.5), Math.floor(q.x() + 0.5), Math.floor(q.y() + 0.5), i % 2 == 0 ? "DDA" : "Bresenham");
    }

    @Override
    public A1Marks stepMarks(PageContext context, int step) {
        A1Lines set = lines(context.seed());
        int i = Math.min(Math.max(step, 1), set.count()) - 1;
        return A1Marks.line(set, i, 1, 2, 3, 4);
    }

    /** A coordinate as it was given, to three decimals where it has any. */
    static String number(double v) {
        return v == Math.rint(v) ? String.format(Locale.ROOT, "%.0f", v)
                : String.format(Locale.ROOT, "%.3f", v);
    }
}
