package simpview.scene.obj;

/**
 * How much one .obj file held: its {@code v} lines, its {@code vn} lines and
 * its {@code f} lines; and the line of its first {@code v} whose colour has a
 * channel outside 0 to 1, which is drawn clamped (0: none has).
 */
public record ObjCounts(int vertices, int normals, int faces, int firstClampedColour) {

    /** Counts of a file whose colours are all within 0 to 1 (or that has none). */
    public ObjCounts(int vertices, int normals, int faces) {
        this(vertices, normals, faces, 0);
    }
}
