package simpview.pages;

import java.awt.image.BufferedImage;
import java.util.List;
import simpview.surface.PageCanvas;

/** The first assignment's five pages (SPEC Part 3). Page n is {@code all().get(n - 1)}. */
public final class Assignment1 {

    private static final List<A1Page> ALL = List.of(
            LineTestPage.starburst(),
            LineTestPage.parallelogram(),
            LineTestPage.random(),
            PolygonTestPage.filled(),
            PolygonTestPage.ghosts());

    /** How many pages: five. */
    public static final int COUNT = ALL.size();

    private Assignment1() {
    }

    public static List<A1Page> all() {
        return ALL;
    }

    /** Page n, 1-based. */
    public static A1Page page(int number) {
        if (number < 1 || number > COUNT) {
            throw new IllegalArgumentException("the first assignment has no page " + number + "; its pages are 1 to " + COUNT);
        }
        return ALL.get(number - 1);
    }

    /** Page n drawn on a fresh canvas: its pictures read no files, so it cannot fail. */
    public static BufferedImage render(int number, PageContext context) {
        PageCanvas canvas = new PageCanvas();
        page(number).drawSteps(canvas, context, Integer.MAX_VALUE);
        return canvas.image();
    }
}
