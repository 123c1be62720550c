package simpview.scene.obj;

import java.util.Arrays;

/**
 * The vertices and normals of an .obj file read so far, in growable
 * primitive arrays (three doubles each). Faces refer only to vertices defined
 * before them, so these are kept for the whole file even when its faces are
 * not. Colours are allocated at the first coloured vertex; a vertex without
 * a colour has NaN there (a colour read from the file is never NaN).
 */
final class ObjVertices {

    private static final int FIRST_CAPACITY = 3 * 256;

    double[] positions = new double[FIRST_CAPACITY];
    double[] colours;
    double[] normals = new double[FIRST_CAPACITY];
    int vertexCount;
    int normalCount;
    /** The line of the first vertex with a colour channel outside [0, 1], or 0. */
    int firstClampedColour;
    /** The largest channel of that vertex's colour as written, or NaN. */
    double firstClampedChannel = Double.NaN;

    void addVertex(double x, double y, double z) {
        if (3 * vertexCount == positions.length) {
            grow();
        }
        int i = 3 * vertexCount++;
        positions[i] = x;
        positions[i + 1] = y;
        positions[i + 2] = z;
        if (colours != null) {
            colours[i] = Double.NaN;
        }
    }

    /** A coloured vertex, from line {@code line}. */
    void addVertex(double x, double y, double z, double r, double g, double b, int line) {
        addVertex(x, y, z);
        if (firstClampedColour == 0 && !(within(r) && within(g) && within(b))) {
            firstClampedColour = line;
            firstClampedChannel = Math.max(r, Math.max(g, b));
        }
        if (colours == null) {
            colours = new double[positions.length];
            Arrays.fill(colours, Double.NaN);
        }
        int i = 3 * (vertexCount - 1);
        colours[i] = r;
        colours[i + 1] = g;
        colours[i + 2] = b;
    }

    private static boolean within(double c) {
        return c >= 0 && c <= 1;
    }

    void addNormal(double x, double y, double z) {
        if (3 * normalCount == normals.length) {
            normals = Arrays.copyOf(normals, grown(normals.length));
        }
        int i = 3 * normalCount++;
        normals[i] = x;
        normals[i + 1] = y;
        normals[i + 2] = z;
    }

    private void grow() {
        int capacity = grown(positions.length);
        positions = Arrays.copyOf(positions, capacity);
        if (colours != null) {
            colours = Arrays.copyOf(colours, capacity);
        }
    }

    /** Doubles a capacity, staying a multiple of 3 and within what an array can hold. */
    static int grown(int length) {
        long wanted = 2L * length;
        int most = Integer.MAX_VALUE - 8 - (Integer.MAX_VALUE - 8) % 3;
        if (length >= most) {
            throw new OutOfMemoryError("an .obj file with more vertices than an array can hold");
        }
        return (int) Math.min(most, wanted);
    }

    /** The bytes these vertices and normals take in a model (arrays cut to length). */
    long modelBytes() {
        long doubles = 3L * (vertexCount * (colours == null ? 1L : 2L) + normalCount);
        return 8 * doubles;
    }
}
