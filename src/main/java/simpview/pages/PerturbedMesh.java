package simpview.pages;

import java.util.Random;
import simpview.geometry.Vertex;

/**
 * The mesh of pages 1 and 2: an 11x11 grid of vertices 60 px apart, inset
 * 25 px in the panel, each vertex moved by a uniform offset in [-15, 15] px in
 * x and y and given a uniform random colour. Panel coordinates; these pages
 * have no depth test, so z is 0 and plays no part.
 *
 * <p>The random numbers are drawn in a fixed order (vertex by vertex, row by
 * row from the bottom: dx, dy, r, g, b) from {@code java.util.Random}, whose
 * sequence Java specifies, so a seed gives the same mesh everywhere.
 */
public final class PerturbedMesh {

    public static final int VERTICES_PER_SIDE = 11;
    public static final double SPACING = 60;
    public static final double INSET = 25;
    public static final double MAX_OFFSET = 15;

    private final Vertex[][] vertices = new Vertex[VERTICES_PER_SIDE][VERTICES_PER_SIDE];

    public PerturbedMesh(long seed) {
        Random random = new Random(seed);
        for (int row = 0; row < VERTICES_PER_SIDE; row++) {
            for (int col = 0; col < VERTICES_PER_SIDE; col++) {
                double x = INSET + col * SPACING + offset(random);
                double y = INSET + row * SPACING + offset(random);
                vertices[row][col] = new Vertex(x, y, 0,
                        random.nextDouble(), random.nextDouble(), random.nextDouble());
            }
        }
    }

    private static double offset(Random random) {
        return (random.nextDouble() * 2 - 1) * MAX_OFFSET;
    }

    public Vertex vertex(int row, int col) {
        return vertices[row][col];
    }

    /** Calls back with both triangles of every cell, lower-left triangle first. */
    public void forEachTriangle(TriangleConsumer consumer) {
        for (int row = 0; row + 1 < VERTICES_PER_SIDE; row++) {
            for (int col = 0; col + 1 < VERTICES_PER_SIDE; col++) {
                Vertex v00 = vertices[row][col];
                Vertex v01 = vertices[row][col + 1];
                Vertex v10 = vertices[row + 1][col];
                Vertex v11 = vertices[row + 1][col + 1];
                consumer.accept(v00, v01, v11);
                consumer.accept(v00, v11, v10);
            }
        }
    }

    /** Receives one triangle. */
    @FunctionalInterface
    public interface TriangleConsumer {
        void accept(Vertex a, Vertex b, Vertex c);
    }
}
