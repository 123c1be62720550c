package simpview.pages;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntConsumer;
import simpview.geometry.Vertex;
import simpview.raster.FilledPolygonRenderer;
import simpview.surface.Drawable;
import simpview.surface.GhostWritingDrawable;
import simpview.surface.PageCanvas;

/**
 * The first assignment's pages 4 and 5 (SPEC Part 3): the four scenes of
 * {@link A1Polygons}, filled by Part 1's rule (under {@link A1Rule#COURSE}
 * with rows sampled at integer y), each triangle its random
 * colour (page 4), or every triangle white at opacity 0.14 through a
 * {@link GhostWritingDrawable} (page 5, the same geometry and seed).
 */
public final class PolygonTestPage implements A1Page {

    private final boolean ghost;

    private PolygonTestPage(boolean ghost) {
        this.ghost = ghost;
    }

    public static PolygonTestPage filled() {
        return new PolygonTestPage(false);
    }

    public static PolygonTestPage ghosts() {
        return new PolygonTestPage(true);
    }

    public boolean ghost() {
        return ghost;
    }

    @Override
    public String title() {
        return ghost ? "Ghost polygons (white, opacity 0.14)" : "Filled polygons";
    }

    @Override
    public boolean usesSeed() {
        return true;
    }

    /**
     * Panel k's scene k, as SPEC gives it: under {@link A1Rule#COURSE} too, whose half-pixel move is how
     * simpview samples the course's way, not the geometry.
     */
    @Override
    public List<ListedPrimitive> primitives(PageContext context) {
        A1Polygons scenes = new A1Polygons(context.seed(), A1Rule.SPEC);
        List<ListedPrimitive> out = new ArrayList<>();
        for (int k = 1; k <= A1Polygons.SCENES; k++) {
            double[] n = scenes.scene(k);
            for (int i = 0; i < scenes.count(k); i++) {
                int at = A1Polygons.at(i);
                out.add(new ListedPrimitive(k, List.of(Vertex.readFrom(n, at),
                        Vertex.readFrom(n, at + Vertex.NUMBERS), Vertex.readFrom(n, at + 2 * Vertex.NUMBERS))));
            }
        }
        return out;
    }

    @Override
    public List<String> panelNames() {
        return A1Polygons.NAMES;
    }

    @Override
    public void draw(PageCanvas canvas, PageContext context) {
        drawSteps(canvas, context, Integer.MAX_VALUE);
    }

    @Override
    public int steps(PageContext context) {
        A1Polygons scenes = new A1Polygons(context.seed(), context.a1Rule());
        int most = 0;
        for (int k = 1; k <= A1Polygons.SCENES; k++) {
            most = Math.max(most, scenes.count(k));
        }
        return most;
    }

    @Override
    public void drawSteps(PageCanvas canvas, PageContext context, int steps) {
        Drawable[] panels = A1Layout.paint(canvas);
        A1Polygons scenes = new A1Polygons(context.seed(), context.a1Rule());
        FilledPolygonRenderer fill = new FilledPolygonRenderer();
        for (int k = 1; k <= A1Polygons.SCENES; k++) {
            drawPanel(k, scenes, Math.min(Math.max(steps, 0), scenes.count(k)), panels[k - 1], fill, null);
        }
    }

    /**
     * Draws scene k's triangles (k = 1..4) onto its panel, in order, filled
     * (through a {@link GhostWritingDrawable} on the ghost page);
     * {@code beforeTriangle}, unless null, is told each triangle's index
     * (0, 1, ...) before it is drawn (the inspector's replay of one pixel).
     */
    public void drawPanel(int k, A1Polygons scenes, Drawable panel, FilledPolygonRenderer fill,
            IntConsumer beforeTriangle) {
        drawPanel(k, scenes, scenes.count(k), panel, fill, beforeTriangle);
    }

    /** The same, the first {@code count} triangles only. */
    private void drawPanel(int k, A1Polygons scenes, int count, Drawable panel, FilledPolygonRenderer fill,
            IntConsumer beforeTriangle) {
        Drawable target = ghost ? new GhostWritingDrawable(panel) : panel;
        double[] n = scenes.scene(k);
        for (int i = 0; i < count; i++) {
            if (beforeTriangle != null) {
                beforeTriangle.accept(i);
            }
            fill.drawPolygon(n, A1Polygons.at(i), target);
        }
    }

    /** E.g. "triangle 30: panel 1, 30 of 90; panel 2, 30 of 162; panel 3, 30 of 162; panel 4 whole (20)". */
    @Override
    public String describeStep(PageContext context, int step) {
        A1Polygons scenes = new A1Polygons(context.seed(), context.a1Rule());
        StringBuilder sb = new StringBuilder("triangle " + step + ":");
        for (int k = 1; k <= A1Polygons.SCENES; k++) {
            int count = scenes.count(k);
            sb.append(k == 1 ? " " : "; ").append("panel ").append(k)
                    .append(step <= count ? ", " + step + " of " + count : " whole (" + count + ")");
        }
        return sb.toString();
    }

    @Override
    public A1Marks stepMarks(PageContext context, int step) {
        int[] pairs = new int[2 * A1Polygons.SCENES];
        for (int k = 1; k <= A1Polygons.SCENES; k++) {
            pairs[2 * (k - 1)] = k;
            pairs[2 * (k - 1) + 1] = step - 1;
        }
        return A1Marks.triangles(new A1Polygons(context.seed(), context.a1Rule()), pairs);
    }
}
