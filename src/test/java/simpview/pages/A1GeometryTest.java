package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;

/**
 * The first assignment's lines and triangles against SPEC Part 3's numbers
 * (under SPEC's rule), for many seeds: the starburst's spokes, the
 * parallelogram's two families, the random lines' and random triangles'
 * integer ends uniform over 0..299 (both ends of the range reached), the
 * meshes' grid and their integer offsets over [-12, 12]. The random panels
 * cannot be held against the course's pictures (another seed), and the
 * goldens keep whatever was drawn when they were made.
 */
class A1GeometryTest {

    private static final int SEEDS = 100;
    private static final int N = Vertex.NUMBERS;

    @Test
    void theStarburstIsNinetySpokesOf135FromTheCentreEveryFourDegrees() {
        double[] n = A1Lines.starburst().numbers();
        assertEquals(90, A1Lines.starburst().count());
        for (int i = 0; i < 90; i++) {
            double t = Math.toRadians(4 * i);
            assertEquals(150, n[A1Lines.from(i)]);
            assertEquals(150, n[A1Lines.from(i) + 1]);
            assertEquals(150 + 135 * Math.cos(t), n[A1Lines.to(i)], 1e-9, "spoke " + i);
            assertEquals(150 + 135 * Math.sin(t), n[A1Lines.to(i) + 1], 1e-9, "spoke " + i);
            assertWhite(n, A1Lines.from(i));
        }
    }

    @Test
    void theParallelogramIsTwoFamiliesOf51LinesInTheHandoutsTopDownFrame() {
        A1Lines lines = A1Lines.parallelogram();
        double[] n = lines.numbers();
        assertEquals(102, lines.count());
        for (int p = 0; p <= 50; p++) {
            assertLine(n, p, 20, 299 - (80 + p), 150, 299 - (150 + p));
            assertLine(n, 51 + p, 160 + p, 299 - 270, 240 + p, 299 - 40);
            assertWhite(n, A1Lines.from(p));
        }
    }

    private static void assertLine(double[] n, int i, double x0, double y0, double x1, double y1) {
        int a = A1Lines.from(i);
        int b = A1Lines.to(i);
        assertEquals(x0, n[a], "line " + i);
        assertEquals(y0, n[a + 1], "line " + i);
        assertEquals(x1, n[b], "line " + i);
        assertEquals(y1, n[b + 1], "line " + i);
    }

    private static void assertWhite(double[] n, int at) {
        assertEquals(1, n[at + Vertex.R]);
        assertEquals(1, n[at + Vertex.G]);
        assertEquals(1, n[at + Vertex.B]);
    }

    /** Each of x0, y0, x1 and y1 on its own, so that one drawn from a smaller range shows. */
    @Test
    void randomLinesHaveIntegerEndsOverTheWholePanel() {
        Range[] ranges = {new Range(), new Range(), new Range(), new Range()};
        for (long seed = 0; seed < SEEDS; seed++) {
            A1Lines lines = A1Lines.random(seed);
            assertEquals(30, lines.count());
            double[] n = lines.numbers();
            for (int i = 0; i < 30; i++) {
                int[] ends = {A1Lines.from(i), A1Lines.to(i)};
                for (int e = 0; e < 2; e++) {
                    ranges[2 * e].take(n[ends[e]], 0, 299);
                    ranges[2 * e + 1].take(n[ends[e] + 1], 0, 299);
                    assertColour(n, ends[e]);
                }
            }
        }
        for (Range range : ranges) {
            range.assertReached(0, 299);
        }
    }

    @Test
    void randomTrianglesHaveIntegerCornersOverTheWholePanel() {
        Range[] ranges = new Range[6];
        for (int r = 0; r < 6; r++) {
            ranges[r] = new Range();
        }
        for (long seed = 0; seed < SEEDS; seed++) {
            A1Polygons polygons = new A1Polygons(seed, A1Rule.SPEC);
            assertEquals(20, polygons.count(4));
            double[] n = polygons.scene(4);
            for (int i = 0; i < 20; i++) {
                for (int k = 0; k < 3; k++) {
                    int at = A1Polygons.at(i) + k * N;
                    ranges[2 * k].take(n[at], 0, 299);
                    ranges[2 * k + 1].take(n[at + 1], 0, 299);
                    assertColour(n, at);
                }
            }
        }
        for (Range range : ranges) {
            range.assertReached(0, 299);
        }
    }

    @Test
    void theStarburstOfTrianglesJoinsNeighbouringSpokes() {
        double[] n = new A1Polygons(3, A1Rule.SPEC).scene(1);
        for (int i = 0; i < 90; i++) {
            int at = A1Polygons.at(i);
            assertEquals(150, n[at]);
            assertEquals(150, n[at + 1]);
            for (int k = 1; k <= 2; k++) {
                double t = Math.toRadians(4 * (i + k - 1));
                assertEquals(150 + 135 * Math.cos(t), n[at + k * N], 1e-9, "triangle " + i + ", corner " + k);
                assertEquals(150 + 135 * Math.sin(t), n[at + k * N + 1], 1e-9, "triangle " + i + ", corner " + k);
            }
        }
    }

    /**
     * The mesh: each of the 81 squares of the points (15 + 30 i, 15 + 30 j)
     * is two triangles that share its (min x, min y) to (max x, max y)
     * diagonal; the perturbed mesh moves each point once, by integers in
     * [-12, 12], the same point by the same offset in every triangle.
     */
    @Test
    void theMeshesAreTheGridSplitAlongItsRisingDiagonalsAndMovedByAtMostTwelve() {
        Range offsetsX = new Range();
        Range offsetsY = new Range();
        for (long seed = 0; seed < SEEDS; seed++) {
            A1Polygons polygons = new A1Polygons(seed, A1Rule.SPEC);
            for (int scene = 2; scene <= 3; scene++) {
                double[] n = polygons.scene(scene);
                assertEquals(162, polygons.count(scene));
                double[][] moved = new double[100][];
                for (int j = 0; j < 9; j++) {
                    for (int i = 0; i < 9; i++) {
                        int cell = j * 9 + i;
                        int[][] corners = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}};
                        for (int c = 0; c < 6; c++) {
                            int at = A1Polygons.at(2 * cell + c / 3) + (c % 3) * N;
                            int gi = corners[c][0];
                            int gj = corners[c][1];
                            double dx = n[at] - (15 + 30 * gi);
                            double dy = n[at + 1] - (15 + 30 * gj);
                            if (scene == 2) {
                                if (dx != 0 || dy != 0) {
                                    fail("mesh, seed " + seed + ", cell " + cell + ", corner " + c + " off its grid");
                                }
                                continue;
                            }
                            offsetsX.take(dx, -12, 12);
                            offsetsY.take(dy, -12, 12);
                            double[] offset = {dx, dy};
                            int point = gj * 10 + gi;
                            if (moved[point] == null) {
                                moved[point] = offset;
                            } else if (moved[point][0] != dx || moved[point][1] != dy) {
                                fail("seed " + seed + ": point " + gi + "," + gj + " moved two ways");
                            }
                        }
                    }
                }
            }
        }
        offsetsX.assertReached(-12, 12);
        offsetsY.assertReached(-12, 12);
    }

    private static void assertColour(double[] n, int at) {
        for (int c = Vertex.R; c <= Vertex.B; c++) {
            if (!(n[at + c] >= 0 && n[at + c] <= 1)) {
                fail("colour " + n[at + c]);
            }
        }
    }

    /** The smallest and largest of integers taken, each checked to be an integer within its bounds. */
    private static final class Range {
        private double least = Double.MAX_VALUE;
        private double most = -Double.MAX_VALUE;

        void take(double v, double low, double high) {
            if (v != Math.rint(v) || v < low || v > high) {
                fail(v + " is not an integer in " + low + ".." + high);
            }
            least = Math.min(least, v);
            most = Math.max(most, v);
        }

        void assertReached(double low, double high) {
            assertTrue(least == low && most == high, "uniform over " + low + ".." + high + ": only " + least + ".."
                    + most + " came out");
        }
    }
}
