package simpview.stage;

import java.nio.file.Path;
import simpview.geometry.Matrix4;

/**
 * Follows a scene's primitives one by one, for the window's instruments
 * (who drew each pixel, stepping through the drawing). Where nobody follows
 * there is no trace at all (null), and drawing costs nothing more.
 *
 * <p>Primitives are numbered 0, 1, 2, ... in drawing order, counting only
 * those that reach the rasterizers (not culled, and for a lit scene not
 * clipped away). {@link #read} is called on the thread that reads the scene,
 * {@link #drawing} on the one that draws; for a large depth-cued scene these
 * are two threads, and primitive n's read comes before its drawing.
 */
public interface PrimitiveTrace {

    /**
     * Primitive {@code index} comes from this command.
     *
     * @param file the file holding the command
     * @param line its 1-based line
     * @param kind {@link Painter#LINE}, {@link Painter#FILLED} or {@link Painter#WIRE}
     * @param p its vertices, panel x and panel y first in each: read, never kept
     * @param at where the first vertex starts in p
     * @param stride the numbers per vertex in p
     * @param vertices how many (2 for a line; 3 or more for a polygon, a lit one clipped)
     */
    void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices);

    /** Primitive {@code index} is about to be drawn; false leaves it out (the picture stops before it). */
    boolean drawing(int index);

    /**
     * A primitive that reaches no rasterizer: culled whole ({@code culled}),
     * or clipped away entirely. It takes no number. Its vertices are given in
     * camera space (x, y, z first in each; world space for a depth-cued
     * scene), before clipping. The default ignores it.
     *
     * @param file the file holding its command, or null when the stage does not know it (depth-cued scenes)
     * @param line its 1-based line, or 0 with a null file
     */
    default void skipped(Path file, int line, int kind, boolean culled, double[] p, int at, int stride,
            int vertices) {
    }

    /** True for a trace that wants each primitive's {@link #source}; the default does not, and costs nothing. */
    default boolean wantsSource() {
        return false;
    }

    /**
     * The next primitive as its command wrote it: its vertices in object
     * space (x, y, z each; read, never kept) and the CTM at its command.
     * Told before the primitive is culled, skipped or read, and only to a
     * trace that {@link #wantsSource}.
     */
    default void source(Matrix4 ctm, double[] xyz, int vertices) {
    }

    /**
     * The next primitive of a lit scene in camera space, after culling and
     * lighting and before clipping: {@code vertices} of {@code stride}
     * numbers each, x, y, z, then r, g, b (the lit colour under flat and
     * gouraud shading, kd otherwise), then the unit normal; read, never kept.
     * Told only to a trace that {@link #wantsSource}, and only for a
     * primitive that is not culled; {@link #read} (or {@link #skipped}, when
     * clipped away) follows.
     */
    default void unclipped(double[] p, int at, int stride, int vertices) {
    }

    /**
     * The lit primitive {@link #read} next carries one colour (a phong
     * polygon: one kd), the same at every vertex, and its colour channels
     * hold it as it is, not times q as its other channels are
     * (FragmentStage.oneColour, FragmentStage.phong). Told only then, just
     * before that read.
     */
    default void oneColour() {
    }

    /**
     * The polygon just told by {@link #unclipped} has no normal of its own at
     * any vertex: the normal each vertex carries is its face normal,
     * (p2 - p1) x (p3 - p1) made unit (a simp polygon, or an obj face without
     * vn references). Told only then, just after that.
     */
    default void faceNormalOnly() {
    }

    /**
     * The filled polygon just told by {@link #unclipped} is flat shaded: it
     * was lit once, at {@code once}[0..2] (its vertices' centroid, camera
     * space), with the normal {@code once}[3..5] (the sum of its vertices'
     * own unit normals, or its face normal; not made unit) and kd
     * {@code once}[6..8] (its vertices' mean); read, never kept.
     */
    default void litOnce(double[] once) {
    }

    /**
     * The filled polygon just told by {@link #unclipped} is gouraud shaded:
     * each of its {@code vertices} was lit at its own position with its own
     * unit normal (both as told there) and kd {@code kd}[3k..3k+2] for vertex
     * k, the kd that its lit colour replaced; read, never kept.
     */
    default void litEach(double[] kd, int vertices) {
    }

    /**
     * The scene is drawn again from the start (it turned out lit after it
     * had drawn depth-cued): forget every primitive told so far; numbering
     * starts at 0 again.
     */
    default void restart() {
    }
}
