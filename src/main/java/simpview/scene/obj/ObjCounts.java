package simpview.scene.obj;

/**
 * How much one .obj file held: its {@code v} lines, its {@code vn} lines and
 * its {@code f} lines.
 */
public record ObjCounts(int vertices, int normals, int faces) {
}
