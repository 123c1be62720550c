package simpview.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Vertex;
import simpview.scene.PrimitiveTrace;
import simpview.surface.Provenance;

/**
 * The window's trace of one picture: where each primitive came from (for the
 * inspector and the stepping line), who drew each pixel (through the
 * provenance record), and, when stepping, where the drawing stops.
 */
final class DrawingTrace implements PrimitiveTrace {

    /** The painter's kind for a line (its other kinds are triangles). */
    private static final int LINE = 0;

    private final Provenance provenance;
    private final int limit;
    private final List<PrimitiveSource> sources = new ArrayList<>();

    /**
     * @param provenance the record the canvas keeps, or null
     * @param limit how many primitives to draw, or -1 for all
     */
    DrawingTrace(Provenance provenance, int limit) {
        this.provenance = provenance;
        this.limit = limit;
    }

    @Override
    public synchronized void read(int index, Path file, int line, String text, int kind, double[] p) {
        int vertices = kind == LINE ? 2 : 3;
        double[] outline = new double[2 * vertices];
        for (int k = 0; k < vertices; k++) {
            outline[2 * k] = p[k * Vertex.NUMBERS + Vertex.X];
            outline[2 * k + 1] = p[k * Vertex.NUMBERS + Vertex.Y];
        }
        sources.add(new PrimitiveSource(file, line, text.strip(), outline));
    }

    @Override
    public boolean drawing(int index) {
        if (limit >= 0 && index >= limit) {
            return false;
        }
        if (provenance != null) {
            provenance.begin(index);
        }
        return true;
    }

    /** Every primitive read, in drawing order. */
    synchronized List<PrimitiveSource> sources() {
        return List.copyOf(sources);
    }
}
