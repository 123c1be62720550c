package simpview.pages;

import java.util.List;
import java.util.Random;
import simpview.geometry.Vertex;

/**
 * The four scenes of filled triangles of the first assignment's pages 4 and 5
 * (SPEC Part 3), in panel coordinates (origin bottom-left, y up) and drawing
 * order, each triangle one random colour: scene k is panel k.
 * Triangle i of a scene is the three vertices from {@code numbers[3 i N]},
 * N = {@link Vertex#NUMBERS}.
 *
 * <p>One {@code java.util.Random(seed)} gives, in this order: scene 1's 90
 * colours, scene 2's 162 colours, scene 3's offsets (point by point, row by
 * row from the bottom, dx then dy, {@code nextInt(25) - 12}) and then its 162
 * colours, scene 4's 20 triangles (x, y of each vertex by {@code
 * nextInt(300)}, then the colour). A colour is r, g, b by {@code nextDouble()}.
 */
public final class A1Polygons {

    /** Scene k's name, as SPEC Part 3 names it, at k - 1. */
    public static final List<String> NAMES = List.of("starburst", "mesh", "perturbed mesh", "random triangles");
    /** How many scenes: one a panel. */
    public static final int SCENES = NAMES.size();
    public static final int GRID = 10;
    public static final double GRID_START = 15;
    public static final double GRID_STEP = 30;
    public static final int MAX_SHIFT = 12;
    public static final int RANDOM_TRIANGLES = 20;
    private final double[][] scenes = new double[SCENES][];
    /** How far every vertex is moved up ({@link A1Rule#rowShift()}). */
    private final double rowShift;

    /**
     * The scenes for this seed, every vertex moved up by the rule's row
     * shift: under {@link A1Rule#COURSE} by half a pixel, so that Part 1's
     * fill rule, which samples pixel (i, j) at (i + 1/2, j + 1/2), samples
     * rows at integer y, as the course's pictures show its scanlines (its
     * mesh panel covers x 15..284 and y 16..285 of the grid's 15..285 square:
     * the top edge in, the bottom out), with the top-left rule unchanged.
     * Columns stay at centres: moving them too makes the starburst one-sided.
     */
    public A1Polygons(long seed, A1Rule rule) {
        rowShift = rule.rowShift();
        Random random = new Random(seed);
        scenes[0] = starburst(random);
        scenes[1] = mesh(random, false);
        scenes[2] = mesh(random, true);
        scenes[3] = randomTriangles(random);
    }

    /** Scene k (1..4): three vertices per triangle. Read only. */
    public double[] scene(int k) {
        return scenes[k - 1];
    }

    public int count(int k) {
        return scenes[k - 1].length / (3 * Vertex.NUMBERS);
    }

    public static int at(int i) {
        return 3 * i * Vertex.NUMBERS;
    }

    private double[] starburst(Random random) {
        int n = A1Lines.SPOKES;
        double[] out = new double[n * 3 * Vertex.NUMBERS];
        double c = A1Lines.CENTRE;
        double r = A1Lines.RADIUS;
        // The angles added up spoke after spoke, as for the line starburst (A1Lines.STEP): the course's
        // page 4 panel 1 has 99.82 % of its geometry so, 99.67 % with 4 i degrees computed afresh.
        double b = 0;
        for (int i = 0; i < n; i++) {
            double a = b;
            b += A1Lines.STEP;
            put(out, i, random, c, c, c + r * Math.cos(a), c + r * Math.sin(a), c + r * Math.cos(b), c + r * Math.sin(b));
        }
        return out;
    }

    private double[] mesh(Random random, boolean shifted) {
        double[] x = new double[GRID * GRID];
        double[] y = new double[GRID * GRID];
        for (int j = 0; j < GRID; j++) {
            for (int i = 0; i < GRID; i++) {
                int k = j * GRID + i;
                x[k] = GRID_START + GRID_STEP * i;
                y[k] = GRID_START + GRID_STEP * j;
                if (shifted) {
                    x[k] += random.nextInt(2 * MAX_SHIFT + 1) - MAX_SHIFT;
                    y[k] += random.nextInt(2 * MAX_SHIFT + 1) - MAX_SHIFT;
                }
            }
        }
        int cells = GRID - 1;
        double[] out = new double[2 * cells * cells * 3 * Vertex.NUMBERS];
        int t = 0;
        for (int j = 0; j < cells; j++) {
            for (int i = 0; i < cells; i++) {
                int p00 = j * GRID + i;
                int p10 = p00 + 1;
                int p01 = p00 + GRID;
                int p11 = p01 + 1;
                // The (min x, min y) to (max x, max y) diagonal: p00 to p11.
                put(out, t++, random, x[p00], y[p00], x[p10], y[p10], x[p11], y[p11]);
                put(out, t++, random, x[p00], y[p00], x[p11], y[p11], x[p01], y[p01]);
            }
        }
        return out;
    }

    private double[] randomTriangles(Random random) {
        double[] out = new double[RANDOM_TRIANGLES * 3 * Vertex.NUMBERS];
        int range = A1Lines.RANGE;
        for (int i = 0; i < RANDOM_TRIANGLES; i++) {
            put(out, i, random, random.nextInt(range), random.nextInt(range), random.nextInt(range),
                    random.nextInt(range), random.nextInt(range), random.nextInt(range));
        }
        return out;
    }

    /** Triangle i, its colour drawn now from the random source. */
    private void put(double[] out, int i, Random random, double x0, double y0, double x1, double y1,
            double x2, double y2) {
        double r = random.nextDouble();
        double g = random.nextDouble();
        double b = random.nextDouble();
        double o = rowShift;
        new Vertex(x0, y0 + o, 0, r, g, b).writeTo(out, at(i));
        new Vertex(x1, y1 + o, 0, r, g, b).writeTo(out, at(i) + Vertex.NUMBERS);
        new Vertex(x2, y2 + o, 0, r, g, b).writeTo(out, at(i) + 2 * Vertex.NUMBERS);
    }
}
