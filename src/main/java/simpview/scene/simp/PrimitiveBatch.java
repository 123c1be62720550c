package simpview.scene.simp;

import java.util.List;
import simpview.stage.Painter;
import simpview.stage.PrimitiveSink;

/**
 * The primitives of one stretch of a scene, at most {@link #CAPACITY}
 * commands long, in primitive arrays, with what the drawing thread must do
 * after drawing them: report progress, and then go on, stop at the end of
 * the scene, or throw the failure that ended the reading. Reused: the
 * reader thread fills it, the drawing thread drains it and hands it back.
 */
final class PrimitiveBatch implements PrimitiveSink {

    /** Commands per batch: the same stretch after which a single-threaded run reports and polls. */
    static final int CAPACITY = SimpInterpreter.COMMANDS_PER_POLL;

    private final byte[] kinds = new byte[CAPACITY];
    private final double[] numbers = new double[CAPACITY * Painter.STRIDE];
    private int size;
    /** Lines read over all files when the batch was closed. */
    long linesRead;
    /** The share of the top file read when the batch was handed over (FileStack#topFileShare). */
    double topFileShare;
    /** True when the scene ended with this batch. */
    boolean last;
    /** The client's warnings at the end of the scene (when {@link #last}). */
    List<String> warnings = List.of();
    /** What ended the reading after this batch's primitives, or null. */
    Throwable failure;

    @Override
    public void add(int kind, double[] p) {
        kinds[size] = (byte) kind;
        System.arraycopy(p, 0, numbers, size * Painter.STRIDE, Painter.STRIDE);
        size++;
    }

    /** Draws the primitives in the order they were added. */
    void drawAll(Painter painter) {
        for (int k = 0; k < size; k++) {
            painter.draw(kinds[k], numbers, k * Painter.STRIDE);
        }
    }

    void clear() {
        size = 0;
        linesRead = 0;
        last = false;
        warnings = List.of();
        failure = null;
    }
}
