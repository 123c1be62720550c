package simpview.scene.simp;

import java.util.Arrays;
import simpview.geometry.Axis;
import simpview.scene.simp.Command.Kind;

/**
 * The commands of one small file as read the first time, with where each
 * stood in the file, so that including the file again replays them instead
 * of scanning its bytes again. Where each command stood (line number, the
 * line's byte range, the command's and argument's byte index) is kept so
 * that an error found while acting on a replayed command names the same
 * line and column, and shows the same text, as on a first reading.
 */
final class Recording {

    private static final Kind[] KINDS = Kind.values();
    private static final Axis[] AXES = Axis.values();
    /** Per command: line number, line start, line end, command index, argument index, first number. */
    private static final int PLACE = 6;

    /** Numbers a plain polygon takes: room for these per line at first. */
    private static final int TYPICAL_NUMBERS = 10;

    private byte[] kinds;
    private int[] places;
    private double[] numbers;
    private String[] names;
    private int size;
    private int numberCount;
    private int lines = -1;

    /** @param lines the file's line count: no more commands than that, so the arrays rarely need to grow */
    Recording(int lines) {
        int capacity = Math.max(1, lines);
        kinds = new byte[capacity];
        places = new int[capacity * PLACE];
        names = new String[capacity];
        numbers = new double[capacity * TYPICAL_NUMBERS];
    }

    /** Appends c, read from the line b[lineStart, lineEnd), line number {@code line}. */
    void add(Command c, int line, int lineStart, int lineEnd) {
        if (size == kinds.length) {
            kinds = Arrays.copyOf(kinds, 2 * size);
            places = Arrays.copyOf(places, 2 * size * PLACE);
            names = Arrays.copyOf(names, 2 * size);
        }
        int n = numbersOf(c);
        if (numberCount + n > numbers.length) {
            numbers = Arrays.copyOf(numbers, 2 * numbers.length + n);
        }
        int p = size * PLACE;
        places[p] = line;
        places[p + 1] = lineStart;
        places[p + 2] = lineEnd;
        places[p + 3] = c.commandIndex;
        places[p + 4] = c.argumentIndex;
        places[p + 5] = numberCount;
        kinds[size] = (byte) c.kind.ordinal();
        names[size] = c.fileName;
        numberCount = copy(c, numbers, numberCount);
        size++;
    }

    /**
     * How many numbers c carries: a count and the numbers as written, or the
     * axis and the angle. A switch expression: a new Shape does not build
     * until it has its count here, and then {@link #copy} and {@link #get}
     * below want its numbers too.
     */
    private static int numbersOf(Command c) {
        return switch (c.kind.shape) {
            case NUMBERS -> 1 + c.count;
            case AXIS_ANGLE -> 2;
            case NONE, NAME -> 0;
        };
    }

    /** Writes c's numbers from to[at] on, as {@link #get} reads them back; returns where they end. */
    private static int copy(Command c, double[] to, int at) {
        return switch (c.kind.shape) {
            case NUMBERS -> {
                to[at] = c.count;
                System.arraycopy(c.numbers, 0, to, at + 1, c.count);
                yield at + numbersOf(c);
            }
            case AXIS_ANGLE -> {
                to[at] = c.axis.ordinal();
                to[at + 1] = c.angle;
                yield at + numbersOf(c);
            }
            case NONE, NAME -> at;
        };
    }

    /** The file was read to its end without an error, {@code lines} lines in all: the recording can be replayed. */
    void finish(int lines) {
        this.lines = lines;
    }

    boolean finished() {
        return lines >= 0;
    }

    int size() {
        return size;
    }

    /** Lines of the whole file, blank and comment lines included. */
    int lines() {
        return lines;
    }

    /** Place p (0 line number, 1 line start, 2 line end) of command k. */
    int place(int k, int p) {
        return places[k * PLACE + p];
    }

    /** Fills c with command k as it was read. */
    void get(int k, Command c) {
        int p = k * PLACE;
        c.kind = KINDS[kinds[k]];
        c.commandIndex = places[p + 3];
        c.argumentIndex = places[p + 4];
        c.fileName = names[k];
        c.colored = false;
        c.clamped = false;
        int at = places[p + 5];
        // A switch expression, its value unused, so that a new Shape does not build without its case here.
        Command.Shape read = switch (c.kind.shape) {
            case NUMBERS -> {
                // Copied in plain loops here and in splitVertices: with
                // System.arraycopy for these 3 to 18 numbers, a replayed
                // command took about 4 times as many of the reading thread's
                // samples on A3 pageD (session 17).
                int count = (int) numbers[at];
                c.count = count;
                double[] to = c.numbers;
                for (int i = 0; i < count; i++) {
                    to[i] = numbers[at + 1 + i];
                }
                if (c.kind.vertices() > 0) {
                    c.splitVertices();
                }
                yield Command.Shape.NUMBERS;
            }
            case AXIS_ANGLE -> {
                c.axis = AXES[(int) numbers[at]];
                c.angle = numbers[at + 1];
                yield Command.Shape.AXIS_ANGLE;
            }
            // nothing more to a brace, a style word or a file name
            case NONE, NAME -> c.kind.shape;
        };
    }

    /** Roughly the memory it holds, for the cache budget. */
    long bytes() {
        return kinds.length * (1L + 4 * PLACE + 8) + 8L * numbers.length;
    }
}
