package simpview.raster;

import simpview.geometry.Vertex;
import simpview.surface.Drawable;

/**
 * The first assignment's panel 3: its lines drawn by two drawers in turn, the
 * first line by the first drawer, the second by the second, and so on
 * (SPEC Part 3: DDA, Bresenham, DDA, ...). It counts the lines it is given:
 * one instance per panel.
 */
public final class AlternatingLineRenderer implements LineRenderer {

    private final LineRenderer first;
    private final LineRenderer second;
    private long drawn;

    public AlternatingLineRenderer(LineRenderer first, LineRenderer second) {
        this.first = first;
        this.second = second;
    }

    /** The course's: the DDA first, then Bresenham. */
    public static AlternatingLineRenderer ddaThenBresenham() {
        return new AlternatingLineRenderer(new DdaLineRenderer(), new BresenhamLineRenderer());
    }

    /** The drawer the next line will be drawn by. */
    public LineRenderer next() {
        return drawn % 2 == 0 ? first : second;
    }

    @Override
    public void drawLine(Vertex p, Vertex q, Drawable drawable) {
        LineRenderer by = next();
        drawn++;
        by.drawLine(p, q, drawable);
    }

    @Override
    public void drawLine(double[] p, int from, int to, Drawable drawable) {
        LineRenderer by = next();
        drawn++;
        by.drawLine(p, from, to, drawable);
    }
}
