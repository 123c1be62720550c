package simpview.scene.obj;

import simpview.stage.ObjFace;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import simpview.scene.SceneException;

/**
 * A parsed .obj file kept in memory, to be drawn again without reading it:
 * its vertices (positions already divided by w, colours where given),
 * normals and faces, in compact primitive arrays.
 *
 * <p>Immutable once made: {@link #replay} only reads, so one model may be
 * replayed by several threads at once. Replaying hands a sink exactly the
 * faces, values and order that streaming the file gives.
 */
public final class ObjModel {

    /** Three doubles per vertex. */
    private final double[] positions;
    /** Three doubles per vertex, NaN for a vertex without colour; null when no vertex has one. */
    private final double[] colours;
    /** Three doubles per vn line. */
    private final double[] normals;
    /** Face f is vertexRefs[faceStarts[f], faceStarts[f + 1]). */
    private final int[] faceStarts;
    /** 0-based vertex indices. */
    private final int[] vertexRefs;
    /** 0-based normal indices beside vertexRefs, -1 for none; null when no face names a normal. */
    private final int[] normalRefs;
    /** The line of each face in its file. */
    private final int[] faceLines;
    /** The line of the first vertex with a colour channel outside [0, 1], or 0 ({@link ObjCounts}). */
    private final int firstClampedColour;
    /** The largest channel of that colour, or NaN ({@link ObjCounts}). */
    private final double firstClampedChannel;
    /** What reading the file warned of ({@link ObjCounts#warnings}). */
    private final List<String> warnings;
    /** See {@link #edgeFirstFaces()}: null until a replay asks. */
    private volatile int[] edgeFirstFaces;

    ObjModel(double[] positions, double[] colours, double[] normals, int[] faceStarts, int[] vertexRefs,
            int[] normalRefs, int[] faceLines, int firstClampedColour, double firstClampedChannel, List<String> warnings) {
        this.positions = positions;
        this.colours = colours;
        this.normals = normals;
        this.faceStarts = faceStarts;
        this.vertexRefs = vertexRefs;
        this.normalRefs = normalRefs;
        this.faceLines = faceLines;
        this.firstClampedColour = firstClampedColour;
        this.firstClampedChannel = firstClampedChannel;
        this.warnings = List.copyOf(warnings);
    }

    /** Reads a whole file into a model, however big (for a bounded cache use {@link ObjLibrary}). */
    public static ObjModel read(Path file) throws SceneException {
        return ObjParser.model(ObjParser.open(file));
    }

    /** Reads an .obj text held in memory, named {@code file} in messages. */
    public static ObjModel of(Path file, byte[] content) throws SceneException {
        return ObjParser.model(ObjParser.of(file, content));
    }

    /**
     * Hands every face to the sink, in file order, through one reused
     * {@link ObjFace}; calls {@link ObjSink#progress} every
     * {@link ObjReader#PROGRESS_LINES} faces. Only the sink can throw.
     */
    public void replay(ObjSink sink) throws SceneException {
        ObjFace face = new ObjFace();
        face.bind(positions, colours, normals, vertexRefs, normalRefs);
        if (sink.readsEdges()) {
            face.bindEdges(edgeFirstFaces());
        }
        int faces = faceCount();
        for (int f = 0; f < faces; f++) {
            face.select(faceStarts[f], faceStarts[f + 1] - faceStarts[f], faceLines[f], f);
            sink.face(face);
            if ((f + 1) % ObjReader.PROGRESS_LINES == 0) {
                sink.progress(faceLines[f]);
            }
        }
    }

    /**
     * For each corner reference, the first face with the edge from that
     * corner to the next of its face, either way round, when that face comes
     * before the corner's own, else -1 ({@link ObjFace#edgeFirstFace}):
     * worked out at the first replay that asks, and kept. Two threads that
     * ask at once may both work it out, to the same numbers.
     */
    private int[] edgeFirstFaces() {
        int[] known = edgeFirstFaces;
        if (known != null) {
            return known;
        }
        int refs = vertexRefs.length;
        int capacity = Integer.highestOneBit(Math.max(4, 2 * refs)) << 1;
        long[] keys = new long[capacity];
        int[] firstFace = new int[capacity];
        Arrays.fill(keys, -1);
        int[] first = new int[refs];
        int faces = faceCount();
        for (int f = 0; f < faces; f++) {
            int start = faceStarts[f];
            int n = faceStarts[f + 1] - start;
            for (int k = 0; k < n; k++) {
                int a = vertexRefs[start + k];
                int b = vertexRefs[start + (k + 1) % n];
                long key = (long) Math.min(a, b) << 32 | Math.max(a, b);
                long mixed = key * 0x9E3779B97F4A7C15L;
                int slot = (int) (mixed ^ mixed >>> 32) & (capacity - 1);
                while (keys[slot] != -1 && keys[slot] != key) {
                    slot = (slot + 1) & (capacity - 1);
                }
                if (keys[slot] == -1) {
                    keys[slot] = key;
                    firstFace[slot] = f;
                    first[start + k] = -1;
                } else {
                    first[start + k] = firstFace[slot] < f ? firstFace[slot] : -1;
                }
            }
        }
        edgeFirstFaces = first;
        return first;
    }

    public int faceCount() {
        return faceLines.length;
    }

    public ObjCounts counts() {
        return new ObjCounts(positions.length / 3, normals.length / 3, faceCount(), firstClampedColour,
                firstClampedChannel, warnings);
    }

    /** The bytes of its arrays, what a cache of models counts (the edges' faces counted before they are made). */
    public long bytes() {
        long doubles = positions.length + normals.length + (colours == null ? 0 : colours.length);
        long ints = faceStarts.length + 2L * vertexRefs.length + faceLines.length
                + (normalRefs == null ? 0 : normalRefs.length);
        return 8 * doubles + 4 * ints;
    }
}
