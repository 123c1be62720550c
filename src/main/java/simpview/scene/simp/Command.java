package simpview.scene.simp;

import simpview.geometry.Axis;

/**
 * One SIMP command as read from a line. The reader refills the same instance
 * for every line, so nothing is allocated per command; whoever acts on it
 * reads it before asking for the next line.
 */
public final class Command {

    /** What a line can say. */
    public enum Kind { PUSH, POP, SCALE, TRANSLATE, ROTATE, LINE, POLYGON, FILE, WIRE, FILLED }

    /** Most vertices a command has (a polygon's three). */
    public static final int MAX_VERTICES = 3;

    Kind kind;
    /** Vertex k is (xyz[3k], xyz[3k+1], xyz[3k+2]); scale and translate keep their three numbers in xyz[0..2]. */
    final double[] xyz = new double[3 * MAX_VERTICES];
    /** Vertex k's colour, when {@link #colored}. */
    final double[] rgb = new double[3 * MAX_VERTICES];
    boolean colored;
    Axis axis;
    double angle;
    String fileName;
    /** Where the command word starts in the line, as a byte index for error columns. */
    int commandIndex;
    /** Where the first argument starts, as a byte index (the file name for {@code file}). */
    int argumentIndex;

    public Kind kind() {
        return kind;
    }

    /** Number of vertices: 2 for a line, 3 for a polygon, else 0. */
    public int vertexCount() {
        return kind == Kind.LINE ? 2 : kind == Kind.POLYGON ? 3 : 0;
    }

    /** Coordinate c (0 = x, 1 = y, 2 = z) of vertex k, or of the scale/translate triple for k = 0. */
    public double coordinate(int k, int c) {
        return xyz[3 * k + c];
    }

    public boolean colored() {
        return colored;
    }

    /** Channel c (0 = r, 1 = g, 2 = b) of vertex k's colour; white when the command has no colours. */
    public double color(int k, int c) {
        return colored ? rgb[3 * k + c] : 1;
    }

    public Axis axis() {
        return axis;
    }

    public double angle() {
        return angle;
    }

    /** The name after {@code file}, without quotes and without ".simp". */
    public String fileName() {
        return fileName;
    }
}
