package simpview.scene.simp;

import java.util.function.ToIntFunction;
import simpview.geometry.Axis;

/**
 * One SIMP command as read from a line. The reader refills the same instance
 * for every line, so nothing is allocated per command; whoever acts on it
 * reads it before asking for the next line.
 *
 * <p>Every command is described once, in {@link Kind}: its spelling, the
 * shape of its arguments and the numbers it takes. The reader parses by
 * shape, the recording stores by shape, and the messages say what a command
 * takes from the same entry; the client gives each kind its action (and says
 * which belong to the lit rules) in one switch with no default.
 */
public final class Command {

    /** How a command's arguments are written. */
    public enum Shape {
        /** Nothing after the word. */
        NONE,
        /** Numbers, any mix of blanks, commas and parentheses between them; the kind lists the counts it takes. */
        NUMBERS,
        /** An axis letter X, Y or Z and an angle in degrees. */
        AXIS_ANGLE,
        /** A file name, quoted or bare. */
        NAME
    }

    /**
     * Every command a SIMP file can hold. {@code counts} are the numbers a
     * NUMBERS command takes; for a line or polygon they are a point (3) per
     * vertex, or a point and a colour (6) per vertex.
     */
    public enum Kind {
        PUSH("{", Shape.NONE),
        POP("}", Shape.NONE),
        SCALE("scale", Shape.NUMBERS, 3),
        TRANSLATE("translate", Shape.NUMBERS, 3),
        ROTATE("rotate", Shape.AXIS_ANGLE),
        LINE("line", 2),
        POLYGON("polygon", 3),
        FILE("file", Shape.NAME),
        WIRE("wire", Shape.NONE),
        FILLED("filled", Shape.NONE),
        CAMERA("camera", Shape.NUMBERS, 6),
        OBJ("obj", Shape.NAME),
        AMBIENT("ambient", Shape.NUMBERS, 3),
        SURFACE("surface", Shape.NUMBERS, 3, 5),
        DEPTH("depth", Shape.NUMBERS, 5),
        LIGHT("light", Shape.NUMBERS, 5),
        FLAT("flat", Shape.NONE),
        GOURAUD("gouraud", Shape.NONE),
        PHONG("phong", Shape.NONE);

        public final String spelling;
        public final Shape shape;
        private final int vertices;
        private final int[] counts;

        Kind(String spelling, Shape shape, int... counts) {
            this.spelling = spelling;
            this.shape = shape;
            this.vertices = 0;
            this.counts = counts;
        }

        /** A line or polygon of {@code vertices} vertices: a point per vertex, or a point and a colour. */
        Kind(String spelling, int vertices) {
            this.spelling = spelling;
            this.shape = Shape.NUMBERS;
            this.vertices = vertices;
            this.counts = new int[] {3 * vertices, 6 * vertices};
        }

        /** Vertices of a line (2) or polygon (3); 0 for every other command. */
        public int vertices() {
            return vertices;
        }

        /** True when a NUMBERS command may take {@code n} numbers. */
        public boolean takes(int n) {
            for (int c : counts) {
                if (c == n) {
                    return true;
                }
            }
            return false;
        }

        /** The most numbers it takes. */
        public int mostNumbers() {
            return counts.length == 0 ? 0 : counts[counts.length - 1];
        }

        /** What it takes, for messages: "3 numbers", "9 numbers (3 points) or 18 (with colours)". */
        public String takesText() {
            return switch (shape) {
                case NONE -> "no arguments";
                case AXIS_ANGLE -> "an axis and an angle";
                case NAME -> "a file name";
                case NUMBERS -> vertices() > 0
                        ? counts[0] + " numbers (" + vertices() + " points) or " + counts[1]
                                + " (" + vertices() + " points, each followed by its colour)"
                        : counts.length == 1 ? counts[0] + " numbers" : counts[0] + " or " + counts[1] + " numbers";
            };
        }
    }

    /** Most numbers a command carries (a coloured polygon's 18), from the table. */
    public static final int MAX_NUMBERS = most(Kind::mostNumbers);
    /** Most vertices a command has (a polygon's three), from the table. */
    public static final int MAX_VERTICES = most(Kind::vertices);

    private static int most(ToIntFunction<Kind> of) {
        int most = 0;
        for (Kind k : Kind.values()) {
            most = Math.max(most, of.applyAsInt(k));
        }
        return most;
    }

    Kind kind;
    /** The numbers as written, count of them. */
    final double[] numbers = new double[MAX_NUMBERS];
    int count;
    /** Vertex k is (xyz[3k], xyz[3k+1], xyz[3k+2]) for a line or polygon. */
    final double[] xyz = new double[3 * MAX_VERTICES];
    /** Vertex k's colour, clamped to [0, 1], when {@link #colored}. */
    final double[] rgb = new double[3 * MAX_VERTICES];
    boolean colored;
    /** True when some colour channel of this line or polygon was outside [0, 1] and was clamped. */
    boolean clamped;
    Axis axis;
    double angle;
    String fileName;
    /** Where the command word starts in the line, as a byte index for error columns. */
    int commandIndex;
    /** Where the first argument starts, as a byte index (the file name for {@code file}). */
    int argumentIndex;

    public Kind kind() {
        return kind;
    }

    /** Number of vertices: 2 for a line, 3 for a polygon, else 0. */
    public int vertexCount() {
        return kind.vertices();
    }

    /** Number i of a NUMBERS command, as written. */
    public double number(int i) {
        return numbers[i];
    }

    /** How many numbers a NUMBERS command carries. */
    public int numberCount() {
        return count;
    }

    /** Coordinate c (0 = x, 1 = y, 2 = z) of vertex k of a line or polygon. */
    public double coordinate(int k, int c) {
        return xyz[3 * k + c];
    }

    public boolean colored() {
        return colored;
    }

    /** Channel c (0 = r, 1 = g, 2 = b) of vertex k's colour; white when the command has no colours. */
    public double color(int k, int c) {
        return colored ? rgb[3 * k + c] : 1;
    }

    public Axis axis() {
        return axis;
    }

    public double angle() {
        return angle;
    }

    /** The name after {@code file} or {@code obj}, without quotes. */
    public String fileName() {
        return fileName;
    }

    /** The largest colour channel as written, of a line or polygon whose vertices have colours. */
    double largestColourChannel() {
        int n = kind.vertices();
        int stride = count / n;
        double most = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < n; k++) {
            for (int c = 0; c < 3; c++) {
                most = Math.max(most, numbers[stride * k + 3 + c]);
            }
        }
        return most;
    }

    /**
     * Splits a line's or polygon's numbers into points and colours: a point
     * per vertex, each followed by its colour when there are twice as many
     * numbers. Colour channels outside [0, 1] are clamped.
     */
    void splitVertices() {
        int n = kind.vertices();
        int stride = count / n;
        colored = stride == 6;
        clamped = false;
        for (int k = 0; k < n; k++) {
            xyz[3 * k] = numbers[stride * k];
            xyz[3 * k + 1] = numbers[stride * k + 1];
            xyz[3 * k + 2] = numbers[stride * k + 2];
            if (colored) {
                for (int c = 0; c < 3; c++) {
                    double v = numbers[stride * k + 3 + c];
                    double kept = v < 0 ? 0 : v > 1 ? 1 : v;
                    clamped |= kept != v;
                    rgb[3 * k + c] = kept;
                }
            }
        }
    }
}
