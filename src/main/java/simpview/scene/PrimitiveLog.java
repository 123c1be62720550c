package simpview.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import simpview.geometry.Vertex;
import simpview.surface.Provenance;

/**
 * The trace the window keeps of one picture: for every primitive its file,
 * line and projected outline, in primitive arrays (nothing allocated per
 * primitive but the arrays' growth); who drew each pixel, through the
 * canvas's {@link Provenance} record; and, when stepping, where the drawing
 * stops. Reads and drawings may come from two threads: only the reading
 * thread writes the arrays, and they are read by others once the picture is
 * done (the hand-over of the finished picture orders the two), so no lock
 * is taken per primitive.
 */
public final class PrimitiveLog implements PrimitiveTrace {

    /** Numbers of outline per primitive: panel x and y of up to three vertices. */
    public static final int OUTLINE = 6;
    /** The painter's kind for a line; its other kinds are triangles. */
    private static final int LINE = 0;

    private final Provenance provenance;
    private final int limit;
    private final List<Path> files = new ArrayList<>();
    private int size;
    private int[] fileOf = new int[256];
    private int[] lineOf = new int[256];
    private byte[] kindOf = new byte[256];
    private double[] outlines = new double[256 * OUTLINE];

    /**
     * @param provenance the record the canvas keeps (told which primitive draws), or null
     * @param limit how many primitives to draw, or -1 for all
     */
    public PrimitiveLog(Provenance provenance, int limit) {
        this.provenance = provenance;
        this.limit = limit;
    }

    @Override
    public void read(int index, Path file, int line, int kind, double[] p) {
        if (size == fileOf.length) {
            grow();
        }
        int last = files.size() - 1;
        if (last < 0 || files.get(last) != file && !files.get(last).equals(file)) {
            last = files.indexOf(file);
            if (last < 0) {
                files.add(file);
                last = files.size() - 1;
            }
        }
        fileOf[size] = last;
        lineOf[size] = line;
        kindOf[size] = (byte) kind;
        int vertices = kind == LINE ? 2 : 3;
        for (int k = 0; k < 3; k++) {
            int from = Math.min(k, vertices - 1) * Vertex.NUMBERS;
            outlines[size * OUTLINE + 2 * k] = p[from + Vertex.X];
            outlines[size * OUTLINE + 2 * k + 1] = p[from + Vertex.Y];
        }
        size++;
    }

    private void grow() {
        int capacity = 2 * fileOf.length;
        fileOf = Arrays.copyOf(fileOf, capacity);
        lineOf = Arrays.copyOf(lineOf, capacity);
        kindOf = Arrays.copyOf(kindOf, capacity);
        outlines = Arrays.copyOf(outlines, capacity * OUTLINE);
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

    /** Primitives read. */
    public int size() {
        return size;
    }

    public Path file(int primitive) {
        return files.get(fileOf[primitive]);
    }

    public int line(int primitive) {
        return lineOf[primitive];
    }

    public int kind(int primitive) {
        return kindOf[primitive];
    }

    /** The primitive's projected vertices, panel x and y in turn (2 for a line, 3 for a triangle). */
    public double[] outline(int primitive) {
        int vertices = kindOf[primitive] == LINE ? 2 : 3;
        return Arrays.copyOfRange(outlines, primitive * OUTLINE, primitive * OUTLINE + 2 * vertices);
    }
}
