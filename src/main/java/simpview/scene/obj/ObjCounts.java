package simpview.scene.obj;

import java.util.List;

/**
 * How much one .obj file held: its {@code v} lines, its {@code vn} lines and
 * its {@code f} lines; the line of its first {@code v} whose colour has a
 * channel outside 0 to 1, which is drawn clamped (0: none has), and the
 * largest channel of that colour as written (NaN: none has); and what
 * reading it noticed that is worth a warning, each naming the file (the
 * first v line whose commas look like decimal commas), kept with its model
 * so that a replay warns as the first reading did.
 */
public record ObjCounts(int vertices, int normals, int faces, int firstClampedColour, double firstClampedChannel,
        List<String> warnings) {

    public ObjCounts {
        warnings = List.copyOf(warnings);
    }

    /** Counts of a file whose colours are all within 0 to 1 (or that has none), and that warned of nothing. */
    public ObjCounts(int vertices, int normals, int faces) {
        this(vertices, normals, faces, 0, Double.NaN, List.of());
    }
}
