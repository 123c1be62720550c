package simpview.stage;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
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

    private final Provenance provenance;
    private final int limit;
    private final List<Path> files = new ArrayList<>();
    private int size;
    private int[] fileOf = new int[256];
    private int[] lineOf = new int[256];
    private byte[] kindOf = new byte[256];
    /** Primitive k's outline is outlines[outlineAt[k], outlineAt[k + 1]): panel x and y of each vertex. */
    private int[] outlineAt = new int[257];
    private double[] outlines = new double[256 * 6];

    /**
     * @param provenance the record the canvas keeps (told which primitive draws), or null
     * @param limit how many primitives to draw, or -1 for all
     */
    public PrimitiveLog(Provenance provenance, int limit) {
        this.provenance = provenance;
        this.limit = limit;
    }

    @Override
    public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
        if (size == fileOf.length) {
            grow();
        }
        fileOf[size] = fileNumber(file);
        lineOf[size] = line;
        kindOf[size] = (byte) kind;
        int start = outlineAt[size];
        if (start + 2 * vertices > outlines.length) {
            outlines = Arrays.copyOf(outlines, Math.max(2 * outlines.length, start + 2 * vertices));
        }
        for (int k = 0; k < vertices; k++) {
            outlines[start + 2 * k] = p[at + k * stride];
            outlines[start + 2 * k + 1] = p[at + k * stride + 1];
        }
        outlineAt[size + 1] = start + 2 * vertices;
        size++;
    }

    @Override
    public void restart() {
        size = 0;
        files.clear();
    }

    /** The number of {@code file} among the files met so far (most primitives come from the last one met). */
    private int fileNumber(Path file) {
        int last = files.size() - 1;
        if (last >= 0 && (files.get(last) == file || files.get(last).equals(file))) {
            return last;
        }
        int known = files.indexOf(file);
        if (known >= 0) {
            return known;
        }
        files.add(file);
        return files.size() - 1;
    }

    private void grow() {
        int capacity = 2 * fileOf.length;
        fileOf = Arrays.copyOf(fileOf, capacity);
        lineOf = Arrays.copyOf(lineOf, capacity);
        kindOf = Arrays.copyOf(kindOf, capacity);
        outlineAt = Arrays.copyOf(outlineAt, capacity + 1);
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

    /** The primitive's projected vertices, panel x and y in turn (2 for a line, 3 or more for a polygon). */
    public double[] outline(int primitive) {
        return Arrays.copyOfRange(outlines, outlineAt[primitive], outlineAt[primitive + 1]);
    }
}
