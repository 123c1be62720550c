package simpview.pages;

import java.util.Random;
import simpview.geometry.Vertex;
import simpview.surface.Colors;

/**
 * The lines of one of the first assignment's line tests (SPEC Part 3, pages
 * 1 to 3), in panel coordinates (origin bottom-left, y up) and in drawing
 * order: line i runs from the vertex at {@code numbers[2 i N]} to the one at
 * {@code numbers[(2 i + 1) N]}, N = {@link Vertex#NUMBERS}.
 */
public final class A1Lines {

    /** The starburst's centre, radius and count. */
    public static final double CENTRE = 150;
    public static final double RADIUS = 135;
    public static final int SPOKES = 90;
    /**
     * The angle between spokes, 4 degrees in radians, added up spoke after
     * spoke as the course's program does: the sum puts the 120-degree
     * spoke's end at x = 82.49999999999987, which rounds to 82 as in the
     * course's picture, where 4 i degrees computed afresh gives 82.50000000000003 and 83.
     */
    public static final double STEP = 2 * Math.PI / SPOKES;
    /** The parallelogram's offsets p = 0..50. */
    public static final int OFFSETS = 51;
    /** The random test's count and range (0..299). */
    public static final int RANDOM_LINES = 30;
    public static final int RANGE = 300;

    private final double[] numbers;

    private A1Lines(double[] numbers) {
        this.numbers = numbers;
    }

    public int count() {
        return numbers.length / (2 * Vertex.NUMBERS);
    }

    /** All the numbers, two vertices per line; read only. */
    public double[] numbers() {
        return numbers;
    }

    /** Where line i's first vertex starts in {@link #numbers()}. */
    public static int from(int i) {
        return 2 * i * Vertex.NUMBERS;
    }

    /** Where line i's second vertex starts in {@link #numbers()}. */
    public static int to(int i) {
        return (2 * i + 1) * Vertex.NUMBERS;
    }

    public Vertex start(int i) {
        return Vertex.readFrom(numbers, from(i));
    }

    public Vertex end(int i) {
        return Vertex.readFrom(numbers, to(i));
    }

    /** Page 1: 90 white lines from the centre, 135 long, at 0, 4, ..., 356 degrees. */
    public static A1Lines starburst() {
        double[] n = new double[SPOKES * 2 * Vertex.NUMBERS];
        double angle = 0;
        for (int i = 0; i < SPOKES; i++, angle += STEP) {
            put(n, i, CENTRE, CENTRE, CENTRE + RADIUS * Math.cos(angle), CENTRE + RADIUS * Math.sin(angle), 1, 1, 1);
        }
        return new A1Lines(n);
    }

    /**
     * Page 2: in the handout's top-down frame (y_top = 299 - y), (20, 80 + p)
     * to (150, 150 + p) for p = 0..50, then (160 + p, 270) to (240 + p, 40)
     * for p = 0..50; white.
     */
    public static A1Lines parallelogram() {
        double[] n = new double[2 * OFFSETS * 2 * Vertex.NUMBERS];
        int top = RANGE - 1;
        for (int p = 0; p < OFFSETS; p++) {
            put(n, p, 20, top - (80 + p), 150, top - (150 + p), 1, 1, 1);
            put(n, OFFSETS + p, 160 + p, top - 270, 240 + p, top - 40, 1, 1, 1);
        }
        return new A1Lines(n);
    }

    /**
     * Page 3: 30 lines with integer endpoints uniform in 0..299, each a
     * random colour. Drawn from {@code java.util.Random(seed)} in this order,
     * line by line: x0, y0, x1, y1 ({@code nextInt(300)}), then r, g, b
     * ({@code nextDouble()}), each channel made a whole number of 255ths by
     * {@link #wholeLevels}.
     */
    public static A1Lines random(long seed) {
        Random random = new Random(seed);
        double[] n = new double[RANDOM_LINES * 2 * Vertex.NUMBERS];
        for (int i = 0; i < RANDOM_LINES; i++) {
            int x0 = random.nextInt(RANGE);
            int y0 = random.nextInt(RANGE);
            int x1 = random.nextInt(RANGE);
            int y1 = random.nextInt(RANGE);
            put(n, i, x0, y0, x1, y1, wholeLevels(random.nextDouble()), wholeLevels(random.nextDouble()),
                    wholeLevels(random.nextDouble()));
        }
        return new A1Lines(n);
    }

    /**
     * A random channel d in [0, 1) as the colour the page draws: k / 255, k = round(255 d), the byte every
     * pixel of it gets where it is drawn whole. With d itself the antialiased panel blended the byte k (as the
     * pixels hold it) while SPEC's formula, {@code c * colour + (1 - c) * old}, and a student given d (the
     * primitives file printed it) blend d: one level apart on 3 % of that panel. With k / 255 the colour
     * printed, the colour blended and the formula agree; every pixel is what it was (k is the same k).
     */
    static double wholeLevels(double d) {
        return Colors.toByte(d) / 255.0;
    }

    private static void put(double[] n, int i, double x0, double y0, double x1, double y1,
            double r, double g, double b) {
        new Vertex(x0, y0, 0, r, g, b).writeTo(n, from(i));
        new Vertex(x1, y1, 0, r, g, b).writeTo(n, to(i));
    }
}
