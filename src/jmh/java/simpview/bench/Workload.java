package simpview.bench;

import java.awt.Color;
import java.util.Random;
import simpview.geometry.Vertex;
import simpview.surface.PageCanvas;

/**
 * The geometry the raster benchmarks share with their Java2D baselines, made
 * once per trial from fixed seeds. Ours is in panel coordinates (origin
 * bottom-left, y up); Java2D's is the same shapes in image coordinates
 * (origin top-left of the 750x750 page, y down), with integer vertices so that
 * both draw exactly the same geometry.
 */
final class Workload {

    static final int PANEL = PageCanvas.PANEL;
    static final int MARGIN = PageCanvas.MARGIN;
    static final int PANEL_PIXELS = PANEL * PANEL;

    static final int MESH_COLUMNS = 250;
    static final int MESH_ROWS = 200;
    static final int MESH_TRIANGLES = 2 * MESH_COLUMNS * MESH_ROWS;

    static final int LINES = 100_000;

    private Workload() {
    }

    /** Image x of panel pixel edge x. */
    static int imageX(double panelX) {
        return MARGIN + (int) panelX;
    }

    /** Image y of panel pixel edge y (the panel is flipped). */
    static int imageY(double panelY) {
        return MARGIN + PANEL - (int) panelY;
    }

    /** A vertex with random colour and a random depth strictly inside the view volume. */
    static Vertex vertex(Random random, double x, double y) {
        return new Vertex(x, y, -1 - random.nextDouble() * 198,
                random.nextDouble(), random.nextDouble(), random.nextDouble());
    }

    /**
     * Triangles as plain numbers ({@link Vertex#NUMBERS} per vertex, triangle t
     * from 3t * NUMBERS), which is how scenes hand them to the renderer, and
     * as Java2D's int coordinates with one flat colour each.
     */
    static final class Triangles {
        final double[] numbers;
        final int[][] imageXs;
        final int[][] imageYs;
        final Color[] colors;

        /** @param vertices flat triples: triangle t is vertices 3t, 3t+1, 3t+2 */
        Triangles(Vertex[] vertices) {
            numbers = new double[vertices.length * Vertex.NUMBERS];
            for (int i = 0; i < vertices.length; i++) {
                vertices[i].writeTo(numbers, i * Vertex.NUMBERS);
            }
            int n = vertices.length / 3;
            imageXs = new int[n][3];
            imageYs = new int[n][3];
            colors = new Color[n];
            for (int t = 0; t < n; t++) {
                for (int k = 0; k < 3; k++) {
                    Vertex v = vertices[3 * t + k];
                    imageXs[t][k] = imageX(v.x());
                    imageYs[t][k] = imageY(v.y());
                }
                Vertex first = vertices[3 * t];
                colors[t] = new Color((float) first.r(), (float) first.g(), (float) first.b());
            }
        }

        int count() {
            return colors.length;
        }
    }

    /** Two triangles sharing the panel's diagonal: every panel pixel once. Corners at four depths. */
    static Triangles fullPanel() {
        Vertex a = new Vertex(0, 0, -190, 1, 0, 0);
        Vertex b = new Vertex(PANEL, 0, -120, 0, 1, 0);
        Vertex c = new Vertex(PANEL, PANEL, -10, 0, 0, 1);
        Vertex d = new Vertex(0, PANEL, -60, 1, 1, 1);
        return new Triangles(new Vertex[] {a, b, c, a, c, d});
    }

    /**
     * A 250x200-cell grid over the panel, two triangles per cell (100,000),
     * integer vertices (cells 2 to 4 px), random colours and depths (seed 42).
     */
    static Triangles mesh() {
        Random random = new Random(42);
        Vertex[][] grid = new Vertex[MESH_ROWS + 1][MESH_COLUMNS + 1];
        for (int j = 0; j <= MESH_ROWS; j++) {
            for (int i = 0; i <= MESH_COLUMNS; i++) {
                grid[j][i] = vertex(random, Math.round(i * (double) PANEL / MESH_COLUMNS),
                        Math.round(j * (double) PANEL / MESH_ROWS));
            }
        }
        Vertex[] vertices = new Vertex[3 * MESH_TRIANGLES];
        int n = 0;
        for (int j = 0; j < MESH_ROWS; j++) {
            for (int i = 0; i < MESH_COLUMNS; i++) {
                Vertex v00 = grid[j][i];
                Vertex v10 = grid[j][i + 1];
                Vertex v01 = grid[j + 1][i];
                Vertex v11 = grid[j + 1][i + 1];
                vertices[n++] = v00;
                vertices[n++] = v10;
                vertices[n++] = v11;
                vertices[n++] = v00;
                vertices[n++] = v11;
                vertices[n++] = v01;
            }
        }
        return new Triangles(vertices);
    }

    /** Lines as vertex pairs: line l is vertices 2l, 2l+1. */
    static final class Lines {
        final Vertex[] vertices;
        final int[] imageCoords; // x0 y0 x1 y1 per line
        final Color[] colors;

        Lines(Vertex[] vertices) {
            this.vertices = vertices;
            int n = vertices.length / 2;
            imageCoords = new int[4 * n];
            colors = new Color[n];
            for (int l = 0; l < n; l++) {
                Vertex p = vertices[2 * l];
                Vertex q = vertices[2 * l + 1];
                imageCoords[4 * l] = imageX(p.x());
                imageCoords[4 * l + 1] = imageY(p.y()) - 1; // the pixel row, not its top edge
                imageCoords[4 * l + 2] = imageX(q.x());
                imageCoords[4 * l + 3] = imageY(q.y()) - 1;
                colors[l] = new Color((float) p.r(), (float) p.g(), (float) p.b());
            }
        }

        int count() {
            return colors.length;
        }
    }

    /** 100,000 lines between random pixel centres of the panel (seed 7). */
    static Lines randomLines() {
        Random random = new Random(7);
        Vertex[] vertices = new Vertex[2 * LINES];
        for (int i = 0; i < vertices.length; i++) {
            vertices[i] = vertex(random, random.nextInt(PANEL) + 0.5, random.nextInt(PANEL) + 0.5);
        }
        return new Lines(vertices);
    }
}
