package simpview.window.instruments;

import java.awt.geom.Path2D;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;
import simpview.window.render.Primitives;

/**
 * Primitives' outlines for the overlays drawn over the page (wire over fill,
 * the culled and clipped-away outlines): each outline its x y pairs in image
 * coordinates, and all of them as one path in screen coordinates, which is
 * what the view draws (Java2D, over the finished picture).
 */
public final class Outlines {

    private Outlines() {
    }

    /** The outline of every primitive the drawing recorded (none recorded: empty), in image coordinates. */
    public static List<double[]> wire(Primitives primitives) {
        List<double[]> outlines = new ArrayList<>();
        for (int k = 0; primitives != null && k < primitives.size(); k++) {
            double[] outline = primitives.outline(k);
            if (outline != null) {
                outlines.add(Inspector.toImage(outline));
            }
        }
        return outlines;
    }

    /** The closed outlines as one path, each point taken to the screen by {@code screenX} and {@code screenY}. */
    public static Path2D.Double path(List<double[]> shapes, DoubleUnaryOperator screenX, DoubleUnaryOperator screenY) {
        Path2D.Double path = new Path2D.Double();
        for (double[] points : shapes) {
            path.moveTo(screenX.applyAsDouble(points[0]), screenY.applyAsDouble(points[1]));
            for (int k = 2; k + 1 < points.length; k += 2) {
                path.lineTo(screenX.applyAsDouble(points[k]), screenY.applyAsDouble(points[k + 1]));
            }
            path.closePath();
        }
        return path;
    }
}
