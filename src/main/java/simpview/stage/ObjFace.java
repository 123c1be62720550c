package simpview.stage;

/**
 * One face of an .obj model, as a view over the model's vertex arrays: a
 * single instance is reused for every face, so reading a model allocates
 * nothing per face. Valid only during the call that hands it over.
 *
 * <p>Vertex k, for k in [0, {@link #size()}), in the face's counter-clockwise
 * order:
 * <ul>
 * <li>its position ({@link #x}, {@link #y}, {@link #z}), in the model's own
 *     coordinates, already divided by the w of its {@code v} line;</li>
 * <li>its colour ({@link #r}, {@link #g}, {@link #b}) when its {@code v} line
 *     gave one ({@link #hasColor}), as written: not clamped;</li>
 * <li>its normal ({@link #nx}, {@link #ny}, {@link #nz}) when the face's
 *     reference gave one ({@code v//vn} or {@code v/vt/vn}, see
 *     {@link #hasNormal}), as written: not made unit length;</li>
 * <li>{@link #vertex} and {@link #normal}: the 0-based indices of that
 *     vertex and normal among the file's {@code v} and {@code vn} lines, the
 *     same for every face that shares them, so a caller can do per-vertex
 *     work once per vertex.</li>
 * </ul>
 * Values for k outside [0, size()) are undefined (not checked: this is a hot
 * path).
 */
public final class ObjFace {

    private double[] positions;
    private double[] colours;
    private double[] normals;
    private int[] vertexRefs;
    private int[] normalRefs;
    private int offset;
    private int size;
    private int line;
    /** The face's index in its kept model, -1 for a face streamed as it is read. */
    private int index = -1;
    /** For each corner reference, the earlier face with that corner's edge ({@link #edgeFirstFace}), or null. */
    private int[] edgeFirstFaces;

    public ObjFace() {
    }

    /** Points the view at a set of arrays (three doubles per vertex or normal; colours and normalRefs may be null). */
    public void bind(double[] positions, double[] colours, double[] normals, int[] vertexRefs, int[] normalRefs) {
        this.positions = positions;
        this.colours = colours;
        this.normals = normals;
        this.vertexRefs = vertexRefs;
        this.normalRefs = normalRefs;
        this.edgeFirstFaces = null;
        this.index = -1;
    }

    /**
     * After {@link #bind}: for each corner reference r of the bound arrays,
     * the index of the first face of the model with the edge from that
     * corner to the next of its face (the last corner's: to the first),
     * either way round, when that face comes before the corner's own; -1 for
     * none.
     */
    public void bindEdges(int[] edgeFirstFaces) {
        this.edgeFirstFaces = edgeFirstFaces;
    }

    /** The face is refs[offset, offset + size), from line {@code line} of its file. */
    public void select(int offset, int size, int line) {
        this.offset = offset;
        this.size = size;
        this.line = line;
    }

    /** The same, for face {@code index} of a kept model. */
    public void select(int offset, int size, int line, int index) {
        select(offset, size, line);
        this.index = index;
    }

    /** The face's index in its kept model, in file order; -1 for a face streamed as it is read. */
    public int index() {
        return index;
    }

    /**
     * The index of the earlier face of the model that has the edge from
     * corner k to corner k + 1 (the last corner's: to the first), either way
     * round; -1 when none has, or when it is not known ({@link #bindEdges}).
     */
    public int edgeFirstFace(int k) {
        return edgeFirstFaces == null ? -1 : edgeFirstFaces[offset + k];
    }

    /** The number of vertices, at least 3. */
    public int size() {
        return size;
    }

    /** The 1-based line of the face's {@code f} line in its file. */
    public int line() {
        return line;
    }

    /** The 0-based index of vertex k among the file's {@code v} lines. */
    public int vertex(int k) {
        return vertexRefs[offset + k];
    }

    public double x(int k) {
        return positions[3 * vertexRefs[offset + k]];
    }

    public double y(int k) {
        return positions[3 * vertexRefs[offset + k] + 1];
    }

    public double z(int k) {
        return positions[3 * vertexRefs[offset + k] + 2];
    }

    /** Whether vertex k's {@code v} line gave a colour. */
    public boolean hasColor(int k) {
        return colours != null && !Double.isNaN(colours[3 * vertexRefs[offset + k]]);
    }

    /** Vertex k's red as written; NaN when it has no colour. */
    public double r(int k) {
        return colours == null ? Double.NaN : colours[3 * vertexRefs[offset + k]];
    }

    public double g(int k) {
        return colours == null ? Double.NaN : colours[3 * vertexRefs[offset + k] + 1];
    }

    public double b(int k) {
        return colours == null ? Double.NaN : colours[3 * vertexRefs[offset + k] + 2];
    }

    /** Whether the face's reference to vertex k named a normal. */
    public boolean hasNormal(int k) {
        return normalRefs != null && normalRefs[offset + k] >= 0;
    }

    /** The 0-based index of vertex k's normal among the file's {@code vn} lines; -1 when it has none. */
    public int normal(int k) {
        return normalRefs == null ? -1 : normalRefs[offset + k];
    }

    /** Vertex k's normal, x; only when {@link #hasNormal}(k) (else an index error). */
    public double nx(int k) {
        return normals[3 * normalRefs[offset + k]];
    }

    public double ny(int k) {
        return normals[3 * normalRefs[offset + k] + 1];
    }

    public double nz(int k) {
        return normals[3 * normalRefs[offset + k] + 2];
    }
}
