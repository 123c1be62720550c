package simpview.scene.obj;

import simpview.stage.ObjFace;

import java.nio.file.Path;
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
        int faces = faceCount();
        for (int f = 0; f < faces; f++) {
            face.select(faceStarts[f], faceStarts[f + 1] - faceStarts[f], faceLines[f]);
            sink.face(face);
            if ((f + 1) % ObjReader.PROGRESS_LINES == 0) {
                sink.progress(faceLines[f]);
            }
        }
    }

    public int faceCount() {
        return faceLines.length;
    }

    public ObjCounts counts() {
        return new ObjCounts(positions.length / 3, normals.length / 3, faceCount(), firstClampedColour,
                firstClampedChannel, warnings);
    }

    /** The bytes of its arrays, what a cache of models counts. */
    public long bytes() {
        long doubles = positions.length + normals.length + (colours == null ? 0 : colours.length);
        long ints = faceStarts.length + vertexRefs.length + faceLines.length
                + (normalRefs == null ? 0 : normalRefs.length);
        return 8 * doubles + 4 * ints;
    }
}
