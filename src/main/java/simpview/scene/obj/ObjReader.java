package simpview.scene.obj;

import java.nio.file.Path;
import simpview.scene.SceneException;

/**
 * Streams an .obj file: reads it line by line in chunks and hands each face
 * to a sink as soon as its {@code f} line is read, so a file of any number of
 * faces is drawn in bounded memory. Only the vertices and normals are kept
 * (faces may refer to any defined before them); faces are not.
 *
 * <p>The subset read (SPEC Part 2, ".obj files"), keywords in any case:
 * <ul>
 * <li>{@code v x y z}, {@code v x y z w}, {@code v x y z r g b},
 *     {@code v x y z w r g b}: the point (x/w, y/w, z/w), w not 0, with a
 *     colour when given;</li>
 * <li>{@code vn x y z}: a normal, of any length;</li>
 * <li>{@code f} and three or more references {@code v}, {@code v/vt},
 *     {@code v//vn} or {@code v/vt/vn}: 1-based indices, or negative ones
 *     counting back from the last defined (-1 the most recent);</li>
 * <li>every other line ({@code vt}, {@code g}, {@code o}, {@code s},
 *     {@code usemtl}, {@code mtllib}, {@code #...}, blank) is ignored.</li>
 * </ul>
 * Blanks, commas and parentheses all separate numbers, as in SIMP files.
 * Any error is a {@link SceneException} naming the obj file, the line and
 * column, the line and what was expected: a wrong count of numbers, a number
 * that does not parse or is out of range, w = 0, a vertex or normal index
 * that is 0 or names nothing defined so far (a texture index must be an
 * integer, nothing more: vt lines are ignored), a face of fewer than three
 * vertices; a file that is not UTF-8 text (UTF-16, or no text at all),
 * found when a line fails or the file gave no face. Faces read before an
 * error have already gone to the sink; an index naming what the file
 * defines only further down says at which line. What is worth a warning (a
 * file without faces, l and p lines, which are not drawn, decimal commas,
 * faces filled otherwise than their outline, a model inside out:
 * {@link Orientation}) is in {@link ObjCounts#warnings},
 * one warning per kind, naming the first line and counting the rest.
 */
public final class ObjReader {

    /** {@link ObjSink#progress} is called once every this many lines (or replayed faces). */
    public static final int PROGRESS_LINES = 1 << 16;

    private ObjReader() {
    }

    /** Streams the file's faces to the sink, in file order. */
    public static ObjCounts stream(Path file, ObjSink sink) throws SceneException {
        return ObjParser.open(file).run(sink);
    }

    /** Streams an .obj text held in memory, named {@code file} in messages. */
    public static ObjCounts stream(Path file, byte[] content, ObjSink sink) throws SceneException {
        return ObjParser.of(file, content).run(sink);
    }
}
