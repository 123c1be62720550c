package simpview.inspect;

import java.util.List;
import simpview.scene.simp.SourcePlace;

/**
 * One write attempted at the inspected pixel, in drawing order: which
 * primitive made it and where its command stands, the depth and colour it
 * came with, and what became of it. Filled in while the scene is replayed,
 * then only read.
 */
public final class HistoryEntry {

    /** Primitive numbers are those of the window's stepping; a primitive culled or clipped away has none. */
    public static final int NO_NUMBER = -1;

    int primitive;
    List<SourcePlace> chain;
    int kind;
    double z = Double.NaN;
    /** The colour it came with (depth-cued scenes: the colour the cue gives it), 0xAARRGGBB; 0 when it has none. */
    int argb;
    Outcome outcome;
    /** For a write that lost the depth test: the depth there and the primitive that put it there. */
    double storedDepth = Double.NaN;
    int storedOwner = NO_NUMBER;
    /**
     * A culled entry: the plane every vertex is outside of; a clipped one: the
     * planes the clipper cut it by (Clipper.cutPlanes); as Camera's outcode
     * bits. 0 for the other outcomes.
     */
    int planes;
    /**
     * A clipped filled polygon: where the pixel's ray meets its plane (camera
     * space), which is outside the planes {@link #herePlanes}; null when not
     * worked out (a line, a wire edge, a culled one, or a point inside them all).
     */
    double[] here;
    int herePlanes;
    /** The colour as the drawing code computed it, term by term; null where there is nothing to explain. */
    Terms explanation;

    HistoryEntry(int primitive, List<SourcePlace> chain, int kind, Outcome outcome) {
        this.primitive = primitive;
        this.chain = chain;
        this.kind = kind;
        this.outcome = outcome;
    }

    public int primitive() {
        return primitive;
    }

    /** The include chain: the top file's line first, the command's own line last (an .obj face's after its obj command). */
    public List<SourcePlace> chain() {
        return chain;
    }

    /** {@link simpview.stage.Painter#LINE}, {@code FILLED} or {@code WIRE}. */
    public int kind() {
        return kind;
    }

    public double z() {
        return z;
    }

    public int argb() {
        return argb;
    }

    public Outcome outcome() {
        return outcome;
    }

    public double storedDepth() {
        return storedDepth;
    }

    public int storedOwner() {
        return storedOwner;
    }

    /** The planes that culled or cut the primitive (Camera's outcode bits); 0 for a write. */
    public int planes() {
        return planes;
    }

    /** Their names, in the clipper's order ("hither", "left", ...). */
    public List<String> planeNames() {
        return VertexTable.planeNames(planes);
    }

    /** A clipped filled polygon's point at the pixel (camera space x, y, z), or null; see {@link #herePlanes()}. */
    public double[] here() {
        return here == null ? null : here.clone();
    }

    /** The planes that point is outside of: those that cut the polygon away at this pixel (outcode bits). */
    public int herePlanes() {
        return herePlanes;
    }

    public Terms explanation() {
        return explanation;
    }
}
