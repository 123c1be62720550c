package simpview.scene.obj;

import java.util.Arrays;
import java.util.List;

/**
 * The faces of an .obj file recorded as they are read, to be kept in an
 * {@link ObjModel}: face f is vertexRefs[starts[f], starts[f + 1]) (0-based
 * vertex indices), with the normal indices beside them (-1 for none; the
 * array is made at the first normal) and the line it came from.
 *
 * <p>Recording stops for good, and lets go of its arrays, as soon as the
 * model (its arrays cut to length, as {@link ObjModel#bytes()} counts them,
 * vertices included) would pass the budget: such a file is then only
 * streamed. While recording, the arrays as grown hold up to twice that.
 */
final class ObjFaceList {

    private final long budget;
    private int[] starts = new int[257];
    private int[] lines = new int[256];
    private int[] vertexRefs = new int[1024];
    private int[] normalRefs;
    private int faceCount;
    private int refCount;
    private boolean dropped;

    ObjFaceList(long budget) {
        this.budget = budget;
    }

    /** Records refs[0, n) of the face on {@code line}; vertexBytes are what the vertices' model would hold. */
    void add(int[] refs, int[] normals, int n, boolean anyNormal, int line, long vertexBytes) {
        if (dropped) {
            return;
        }
        boolean normalsNeeded = normalRefs != null || anyNormal;
        // each reference: its vertex, its normal if any face has one, and the face first with its edge (ObjModel)
        long ints = 2L * (faceCount + 1) + 1 + (normalsNeeded ? 3L : 2L) * (refCount + n);
        if (vertexBytes + 4 * ints > budget) {
            drop();
            return;
        }
        makeRoom(n, normalsNeeded);
        System.arraycopy(refs, 0, vertexRefs, refCount, n);
        if (normalRefs != null) {
            System.arraycopy(normals, 0, normalRefs, refCount, n);
        }
        refCount += n;
        lines[faceCount] = line;
        starts[++faceCount] = refCount;
    }

    /** Grows the arrays for one more face of n references. */
    private void makeRoom(int n, boolean normalsNeeded) {
        if (faceCount == lines.length) {
            lines = Arrays.copyOf(lines, grown(lines.length, 1));
            starts = Arrays.copyOf(starts, lines.length + 1);
        }
        if (refCount + n > vertexRefs.length) {
            vertexRefs = Arrays.copyOf(vertexRefs, grown(vertexRefs.length, refCount + n));
            if (normalRefs != null) {
                normalRefs = Arrays.copyOf(normalRefs, vertexRefs.length);
            }
        }
        if (normalsNeeded && normalRefs == null) {
            normalRefs = new int[vertexRefs.length];
            Arrays.fill(normalRefs, 0, refCount, -1);
        }
    }

    /** At least twice the length, and at least {@code needed}. */
    private static int grown(int length, int needed) {
        long wanted = Math.max(2L * length, needed);
        if (wanted > Integer.MAX_VALUE - 8) {
            throw new OutOfMemoryError("an .obj file with more face references than an array can hold");
        }
        return (int) wanted;
    }

    private void drop() {
        dropped = true;
        starts = null;
        lines = null;
        vertexRefs = null;
        normalRefs = null;
    }

    /** False once the faces passed the budget. */
    boolean kept() {
        return !dropped;
    }

    /** The model of these faces over {@code vertices}, every array cut to its length, with the file's warnings. */
    ObjModel model(ObjVertices vertices, List<String> warnings) {
        if (dropped) {
            throw new IllegalStateException("the faces were dropped");
        }
        int v = 3 * vertices.vertexCount;
        int vn = 3 * vertices.normalCount;
        return new ObjModel(
                Arrays.copyOf(vertices.positions, v),
                vertices.colours == null ? null : Arrays.copyOf(vertices.colours, v),
                Arrays.copyOf(vertices.normals, vn),
                Arrays.copyOf(starts, faceCount + 1),
                Arrays.copyOf(vertexRefs, refCount),
                normalRefs == null ? null : Arrays.copyOf(normalRefs, refCount),
                Arrays.copyOf(lines, faceCount),
                vertices.firstClampedColour,
                vertices.firstClampedChannel,
                warnings);
    }
}
