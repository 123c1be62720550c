package simpview.pages;

import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Vertex;

/**
 * What the window draws over a first-assignment page to show a line or a
 * triangle as it was given, in image coordinates (x right, y down, pixel
 * (i, j) the square [i, i + 1) x [j, j + 1)): an overlay, never page pixels.
 *
 * @param outlines closed outlines (x0, y0, x1, y1, ...): triangles as given
 * @param given segments as given (x0, y0, x1, y1 per segment): the true line, unrounded
 * @param rounded the same segments between their rounded endpoints
 */
public record A1Marks(List<double[]> outlines, double[] given, double[] rounded) {

    public static final A1Marks NONE = new A1Marks(List.of(), new double[0], new double[0]);

    public A1Marks {
        outlines = List.copyOf(outlines);
        given = given.clone();
        rounded = rounded.clone();
    }

    public boolean isEmpty() {
        return outlines.isEmpty() && given.length == 0;
    }

    /** Line i of a line test in the given panels: as given and between its rounded ends. */
    static A1Marks line(A1Lines set, int i, int... panels) {
        double[] n = set.numbers();
        double px = n[A1Lines.from(i) + Vertex.X];
        double py = n[A1Lines.from(i) + Vertex.Y];
        double qx = n[A1Lines.to(i) + Vertex.X];
        double qy = n[A1Lines.to(i) + Vertex.Y];
        double[] given = new double[4 * panels.length];
        double[] rounded = new double[4 * panels.length];
        for (int k = 0; k < panels.length; k++) {
            put(given, k, panels[k], px, py, qx, qy);
            put(rounded, k, panels[k], Math.floor(px + 0.5), Math.floor(py + 0.5), Math.floor(qx + 0.5), Math.floor(qy + 0.5));
        }
        return new A1Marks(List.of(), given, rounded);
    }

    /** Triangle i of each panel's scene where it has one, (panel, i) pairs in turn. */
    static A1Marks triangles(A1Polygons scenes, int[] panelsAndTriangles) {
        List<double[]> outlines = new ArrayList<>();
        for (int k = 0; k + 1 < panelsAndTriangles.length; k += 2) {
            int panel = panelsAndTriangles[k];
            int i = panelsAndTriangles[k + 1];
            if (i < 0 || i >= scenes.count(panel)) {
                continue;
            }
            double[] n = scenes.scene(panel);
            double[] outline = new double[6];
            for (int v = 0; v < 3; v++) {
                int at = A1Polygons.at(i) + v * Vertex.NUMBERS;
                // The fill samples pixel (i, j) at (i + 1/2, j + 1/2) of these (row-shifted) coordinates.
                outline[2 * v] = A1Layout.left(panel) + n[at + Vertex.X];
                outline[2 * v + 1] = A1Layout.top(panel) + A1Layout.PANEL - n[at + Vertex.Y];
            }
            outlines.add(outline);
        }
        return new A1Marks(outlines, new double[0], new double[0]);
    }

    /** A line's panel point (pixel centres at integer coordinates, as the line drawers round) in the image. */
    private static void put(double[] into, int k, int panel, double px, double py, double qx, double qy) {
        into[4 * k] = A1Layout.left(panel) + px + 0.5;
        into[4 * k + 1] = A1Layout.top(panel) + A1Layout.PANEL - 0.5 - py;
        into[4 * k + 2] = A1Layout.left(panel) + qx + 0.5;
        into[4 * k + 3] = A1Layout.top(panel) + A1Layout.PANEL - 0.5 - qy;
    }
}
