package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The shortcuts by which a failing picture's hints are found sooner: each must give exactly what the whole
 * computation gives, at the threshold too. Small panels, so every count of failing pixels can be tried.
 */
class FailingEarlyTest {

    private static RubricRule rule(int tolerance, int deviation, double minShare, int maxFailing,
            Comparison.Metric metric) {
        return new RubricRule("*", tolerance, deviation, minShare, maxFailing, 1, 90, metric, null, "visible",
                Comparison.FLIP_THRESHOLD);
    }

    /** A size x size panel of grey 100 whose first {@code wrong} pixels are white: that many fail, no more. */
    private static int[] spoiled(int size, int wrong) {
        int[] panel = new int[size * size];
        for (int i = 0; i < panel.length; i++) {
            panel[i] = i < wrong ? 0xFFFFFF : 0x646464;
        }
        return panel;
    }

    @Test
    void theFewestFailingPixelsThatFailAreWherePassesTurns() {
        int size = 10;
        int[] ours = spoiled(size, 0);
        // 99 % of 100 leaves 1; 99.5 % leaves none but a half; 33.33 % is no whole count; a pixel limit
        // below, at and above the share's; 0 % and 100 %.
        RubricRule[] rules = {rule(8, 0, 99, -1, Comparison.Metric.EXACT),
            rule(8, 0, 99.5, -1, Comparison.Metric.EXACT), rule(8, 0, 100 / 3.0, -1, Comparison.Metric.EXACT),
            rule(8, 0, 90, 3, Comparison.Metric.EXACT), rule(8, 0, 90, 10, Comparison.Metric.EXACT),
            rule(8, 0, 90, 50, Comparison.Metric.EXACT), rule(8, 0, 0, -1, Comparison.Metric.EXACT),
            rule(8, 0, 100, -1, Comparison.Metric.EXACT), rule(8, 0, 0, 100, Comparison.Metric.EXACT)};
        long[] expected = {2, 1, 67, 4, 11, 11, 101, 1, 101};
        for (int r = 0; r < rules.length; r++) {
            long fails = rules[r].failingThatFails(size * size);
            assertEquals(expected[r], fails, "rule " + r);
            for (int wrong = 0; wrong <= size * size; wrong++) {
                Comparison full = rules[r].compare(ours, spoiled(size, wrong), size);
                assertEquals(wrong, full.failing(8));
                assertEquals(wrong < fails, rules[r].passes(full), "rule " + r + ", " + wrong + " failing");
            }
        }
    }

    @Test
    void aComparisonCutShortIsTheWholeOneOrNullOnlyWhereEnoughFail() {
        Random random = new Random(37);
        int size = 21; // more rows than the stride between the rows measured first
        for (int trial = 0; trial < 12; trial++) {
            int[] ours = new int[size * size];
            int[] theirs = new int[size * size];
            for (int i = 0; i < ours.length; i++) {
                ours[i] = random.nextInt(4) == 0 ? random.nextInt(0x1000000) : 0x202020;
                theirs[i] = random.nextInt(3) == 0 ? ours[i] ^ random.nextInt(0x1000000) : ours[i];
            }
            Comparison.Metric metric = Comparison.Metric.values()[trial % 3];
            int deviation = trial / 3 % 3;
            int tolerance = trial % 2 == 0 ? 8 : 40;
            Comparison full = Comparison.of(ours, theirs, size, deviation, metric, 0.2);
            int failing = full.failing(tolerance);
            for (long enough : new long[] {1, failing / 2, failing, failing + 1, (long) size * size + 1}) {
                Comparison cut = Comparison.unlessFailing(ours, theirs, size, deviation, metric, 0.2, tolerance,
                        enough);
                String what = metric + ", deviation " + deviation + ", " + failing + " failing, enough " + enough;
                if (metric != Comparison.Metric.FLIP && failing >= enough) {
                    assertNull(cut, what);
                    continue;
                }
                assertNotNull(cut, what);
                assertEquals(failing, cut.failing(tolerance), what);
                assertEquals(full.verdictShare(tolerance), cut.verdictShare(tolerance), what);
                assertEquals(full.exact(), cut.exact(), what);
                for (int i = 0; i < ours.length; i++) {
                    assertEquals(full.distance(i), cut.distance(i), what);
                    assertEquals(full.distanceWithSlack(i), cut.distanceWithSlack(i), what);
                    assertEquals(full.flip(i), cut.flip(i), what);
                }
            }
        }
    }

    @Test
    void anotherPageIsNamedAtTheRulesLastAllowedFailingPixelAndNotOneMore() {
        int size = 10;
        RubricRule[] rules = {rule(8, 0, 98, -1, Comparison.Metric.EXACT)}; // 2 of 100 may fail
        int[] page1 = spoiled(size, 0);
        int[] page2 = new int[size * size];
        Arrays.fill(page2, 0x0000FF);
        for (int wrong = 0; wrong <= 4; wrong++) {
            int[] theirs = spoiled(size, wrong);
            OtherPage found = OtherPage.find(2, 2, new int[][] {theirs}, size, rules,
                    k -> new int[][] {k == 1 ? page1 : page2}, k -> "page " + k);
            if (wrong <= 2) {
                assertNotNull(found, wrong + " failing");
                assertEquals("page 1", found.page());
                assertEquals(1 - wrong / 100.0, found.shareThere(), 1e-12);
            } else {
                assertNull(found, wrong + " failing");
            }
        }
    }

    /**
     * A white page with the first assignment's four 300x300 panels white inside but dark on exactly half the
     * pixels their edges are sampled at (the least a panel is taken at), or one fewer on the last panel's left.
     */
    private static Picture fourPanelsBarelyDark(boolean oneFewer) throws CompareException {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        Arrays.fill(((DataBufferInt) page.getRaster().getDataBuffer()).getData(), 0xFFFFFF);
        for (int k = 0; k < 4; k++) {
            int x0 = 50 + k % 2 * 350;
            int y0 = 50 + k / 2 * 350;
            for (int i = 0; i < 300; i += 5) {
                page.setRGB(x0 + i, y0 + 299, 0x101010); // 60 samples along the bottom
                if (i > 0) {
                    page.setRGB(x0 + i, y0, 0x101010); // 59 along the top, its corner left white
                }
            }
            if (!(oneFewer && k == 3)) {
                page.setRGB(x0, y0 + 5, 0x101010); // the 120th of 240
            }
        }
        return Picture.of(page, "four.png");
    }

    @Test
    void aPageOfFourPanelsIsFoundWithTheLeastDarkAndNotWithoutIt() throws Exception {
        PanelGridComparison.Panel[] panels = new PanelGridComparison.Panel[4];
        for (int k = 0; k < 4; k++) {
            panels[k] = new PanelGridComparison.Panel(50 + k % 2 * 350, 50 + k / 2 * 350, 300);
        }
        assertTrue(PanelGridComparison.holds(fourPanelsBarelyDark(false), panels));
        assertFalse(PanelGridComparison.holds(fourPanelsBarelyDark(true), panels));
    }

    /**
     * A 40x40 panel of cells of a few colours (rows of cells, or a grid), and it turned and moved: cells of one
     * colour match under several ways, so ways tie on the sampled pixels and on every pixel too, and only the
     * smaller move decides. A way's share of every pixel is cut short only when it must be above the best's: cut
     * short at equal shares, the larger move would be named.
     */
    private static int[][] cellsTurned(long seed, int n) {
        Random random = new Random(seed);
        int cell = 2 + random.nextInt(8);
        int colours = 2 + random.nextInt(3);
        int[] palette = new int[colours];
        for (int i = 0; i < colours; i++) {
            palette[i] = random.nextInt(0x1000000);
        }
        int[] ours = new int[n * n];
        boolean rows = random.nextBoolean();
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int c = rows ? y / cell : y / cell * 7 + x / cell;
                ours[y * n + x] = palette[Math.floorMod(c * 31 + (c >> 2), colours)];
            }
        }
        SystematicError.Turn turn = SystematicError.Turn.values()[random.nextInt(5)];
        int right = random.nextInt(9) - 4;
        int down = random.nextInt(9) - 4;
        int[] theirs = new int[n * n];
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int sx = x - right;
                int sy = y - down;
                theirs[y * n + x] = sx >= 0 && sy >= 0 && sx < n && sy < n ? ours[turn.source(sx, sy, n)] : 0;
            }
        }
        return new int[][] {ours, theirs};
    }

    @Test
    void waysTiedOnEveryPixelAreToldApartByTheSmallerMove() {
        // seed, then the move named: as simpview named it before ways were cut short
        int[][] cases = {{3, -3, 0}, {63, 3, -1}, {181, 3, 0}};
        for (int[] c : cases) {
            int[][] panels = cellsTurned(c[0], 40);
            SystematicError found = SystematicError.find(panels[0], panels[1], 40, 8);
            assertNotNull(found, "seed " + c[0]);
            assertEquals(SystematicError.Turn.TRANSPOSED, found.turn(), "seed " + c[0]);
            assertEquals(c[1], found.right(), "seed " + c[0]);
            assertEquals(c[2], found.down(), "seed " + c[0]);
        }
    }
}
