package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import simpview.compare.SystematicError.Turn;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * A panel moved, turned or with red and blue swapped is named so, and
 * nothing else is. The wrong pictures are made here by plain formulas over
 * simpview's own panel, written apart from the finder's: each turn as the
 * (column, row) it reads.
 */
class SystematicErrorTest {

    private static final int N = Comparison.N;

    /** Page 2 (the blerped mesh: colours everywhere) or page 4 (green depth-cued boxes on black). */
    private static int[] panel(int page) throws Exception {
        BufferedImage image = new PageRenderer().renderImage(page, PageContext.defaults());
        return Picture.ofPage(image, "ours").panel();
    }

    /**
     * Theirs: at (x, y), simpview's pixel at the turn of (x - right, y - down), black where that lies outside,
     * red and blue swapped when asked.
     */
    private static int[] made(int[] ours, int n, String turn, int right, int down, boolean swap) {
        int[] theirs = new int[n * n];
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int u = x - right;
                int v = y - down;
                if (u < 0 || u >= n || v < 0 || v >= n) {
                    continue;
                }
                int[] read = switch (turn) {
                    case "NONE" -> new int[] {u, v};
                    case "UPSIDE_DOWN" -> new int[] {u, n - 1 - v};
                    case "MIRRORED" -> new int[] {n - 1 - u, v};
                    case "HALF_TURN" -> new int[] {n - 1 - u, n - 1 - v};
                    case "TRANSPOSED" -> new int[] {v, u};
                    default -> throw new IllegalArgumentException(turn);
                };
                int c = ours[read[1] * n + read[0]];
                int r = c >> 16 & 0xFF;
                int g = c >> 8 & 0xFF;
                int b = c & 0xFF;
                theirs[y * n + x] = swap ? b << 16 | g << 8 | r : c;
            }
        }
        return theirs;
    }

    /** The share of pixels whose channels all differ by at most the tolerance. */
    private static double within(int[] a, int[] b, int tolerance) {
        long in = 0;
        for (int i = 0; i < a.length; i++) {
            boolean near = true;
            for (int shift = 0; shift <= 16; shift += 8) {
                near &= Math.abs((a[i] >> shift & 0xFF) - (b[i] >> shift & 0xFF)) <= tolerance;
            }
            in += near ? 1 : 0;
        }
        return (double) in / a.length;
    }

    @ParameterizedTest(name = "page {0}: {1} moved ({2}, {3}), swapped {4}")
    @CsvSource({
        "2, NONE, 3, -2, false",
        "2, NONE, 0, 1, false", // row 650 - y: a row down, which slack hides
        "2, NONE, -4, 4, false",
        "2, NONE, 5, 0, false", // beyond the first search: followed out, not called 4
        "2, NONE, 0, 6, false",
        "2, NONE, -9, -7, false",
        "2, NONE, 20, 0, false", // followed out from the first search's 4 px, a pixel at a time
        "2, TRANSPOSED, 2, 0, false",
        "2, UPSIDE_DOWN, 0, 0, false",
        "2, UPSIDE_DOWN, 0, -1, false",
        "2, MIRRORED, 0, 0, false",
        "2, HALF_TURN, 1, 0, false",
        "2, TRANSPOSED, 0, 0, false",
        "2, NONE, 0, 0, true",
        "2, UPSIDE_DOWN, 2, 0, true",
        "4, NONE, -1, 0, false",
        "4, UPSIDE_DOWN, 0, 0, false"})
    void aPanelMovedOrTurnedIsNamedSo(int page, String turn, int right, int down, boolean swap) throws Exception {
        int[] ours = panel(page);
        int[] theirs = made(ours, N, turn, right, down, swap);
        SystematicError found = SystematicError.find(ours, theirs, N, 8);
        assertNotNull(found, "nothing found");
        assertEquals(Turn.valueOf(turn), found.turn());
        assertEquals(right, found.right());
        assertEquals(down, found.down());
        assertEquals(swap, found.redBlueSwapped());
        assertEquals(1.0, found.shareThere(), "undone, it is simpview's panel");
        assertEquals(within(ours, theirs, 8), found.shareAsIs(), 1e-12);
        assertTrue(found.hint(N).startsWith("your panel is simpview's " + found.brief() + ": so "), found.hint(N));
    }

    @Test
    void theWordsSayWhichWayAndWhereToLook() throws Exception {
        int[] ours = panel(2);
        SystematicError moved = SystematicError.find(ours, made(ours, N, "NONE", 3, -2, false), N, 8);
        assertEquals("moved 3 px right and 2 px up", moved.brief());
        assertTrue(moved.hint(N).contains("so moved back, 100.00 % of the pixels it then matches are within 8/255"),
                moved.hint(N));
        assertTrue(moved.hint(N).contains("row 650 - y puts everything a row down"), moved.hint(N));
        SystematicError over = SystematicError.find(ours, made(ours, N, "UPSIDE_DOWN", 0, -1, true), N, 8);
        assertEquals("upside down, then moved 1 px up, red and blue swapped", over.brief());
        assertTrue(over.hint(N).contains("so turned and moved back, red and blue swapped too"), over.hint(N));
        assertTrue(over.hint(N).contains("the pixel of y is row 649 - y"), over.hint(N));
        assertTrue(over.hint(N).contains("0xRRGGBB has red in bits 16-23"), over.hint(N));
        SystematicError swapped = SystematicError.find(ours, made(ours, N, "TRANSPOSED", 0, 0, false), N, 8);
        assertEquals("transposed (x and y swapped)", swapped.brief());
        assertTrue(swapped.hint(N).contains("so x and y swapped back, 100.00 %"), swapped.hint(N));
        assertTrue(swapped.hint(N).contains("x is the column, y the row"), swapped.hint(N));
    }

    @Test
    void aRightPanelOrAnotherDrawingIsNoSystematicError() throws Exception {
        int[] ours = panel(2);
        assertNull(SystematicError.find(ours, ours.clone(), N, 8));
        assertNull(SystematicError.find(ours, panel(3), N, 8), "another page is not a moved one");
        assertNull(SystematicError.find(ours, new int[N * N], N, 8), "a black panel explains nothing");
        // Noise on every tenth pixel: wrong pixels that no move or turn puts right.
        int[] noisy = ours.clone();
        Random random = new Random(28);
        for (int i = 0; i < noisy.length; i += 10) {
            noisy[i] = random.nextInt(0x1000000);
        }
        assertNull(SystematicError.find(ours, noisy, N, 8));
        // A grey page with red and blue swapped is the same page.
        int[] grey = panel(4);
        for (int i = 0; i < grey.length; i++) {
            int g = grey[i] >> 8 & 0xFF;
            grey[i] = g << 16 | g << 8 | g;
        }
        assertNull(SystematicError.find(grey, made(grey, N, "NONE", 0, 0, true), N, 8));
    }

    /** A moved panel that is also wrong elsewhere is named only while the move explains 98 % of it. */
    @Test
    void aMoveIsNamedOnlyWhereItExplainsThePanel() throws Exception {
        int[] ours = panel(2);
        int[] theirs = made(ours, N, "NONE", 2, 0, false);
        int[] alsoWrong = theirs.clone();
        for (int y = 100; y < 150; y++) {
            for (int x = 100; x < 150; x++) {
                alsoWrong[y * N + x] ^= 0x808080; // 2,500 pixels: 0.6 % of the panel
            }
        }
        SystematicError found = SystematicError.find(ours, alsoWrong, N, 8);
        assertNotNull(found);
        assertEquals(2, found.right());
        assertTrue(found.shareThere() < 1 && found.shareThere() >= SystematicError.MIN_SHARE, "" + found.shareThere());
        int[] mostlyWrong = theirs.clone();
        for (int y = 100; y < 300; y++) {
            for (int x = 100; x < 300; x++) {
                mostlyWrong[y * N + x] ^= 0x808080; // 40,000 pixels: 9.5 %
            }
        }
        assertNull(SystematicError.find(ours, mostlyWrong, N, 8));
    }

    /**
     * The first assignment's starburst (page 1) is symmetric under y to 300 - y (upside down, then a pixel up):
     * turned so, simpview's antialiased panel differs from itself only where ties round (0.7 % of it). A panel
     * drawn so, as a student who rounds those ties the other way draws it with y the right way up, is not called
     * upside down; a panel whose drawing the turn does change (page 2's parallelogram) still is.
     */
    @Test
    void aTurnThatLaysSimpviewsPanelOnItselfIsNotNamed() {
        int n = 300;
        int[] starburst = firstAssignmentPanel(1, 4);
        int[] turned = made(starburst, n, "UPSIDE_DOWN", 0, -1, false);
        assertTrue(within(starburst, turned, 8) < 1 - SystematicError.MIN_WRONG, "it differs enough to be looked at");
        assertTrue(within(starburst, turned, 8) > SystematicError.MIN_SHARE, "but is nearly the same picture");
        SystematicError found = SystematicError.find(starburst, turned, n, 8);
        assertTrue(found == null || found.turn() == Turn.NONE, found == null ? "" : found.hint(n));

        int[] parallelogram = firstAssignmentPanel(2, 4);
        SystematicError over = SystematicError.find(parallelogram, made(parallelogram, n, "UPSIDE_DOWN", 0, -1, false),
                n, 8);
        assertNotNull(over);
        assertEquals(Turn.UPSIDE_DOWN, over.turn());
        assertEquals(-1, over.down());
    }

    /**
     * The first assignment's page 4, panel 2: a mesh of 30 px cells, each one flat colour. Sampled every 9th or
     * 3rd pixel, many turns and moves match it as well as the true one (none of the samples falls where they
     * differ); measured on every pixel, only the true one does, and it is named.
     */
    @ParameterizedTest(name = "the mesh {0} moved ({1}, {2})")
    @CsvSource({
        "UPSIDE_DOWN, 0, 0",
        "MIRRORED, 0, 0",
        "HALF_TURN, 0, 0",
        "TRANSPOSED, 0, 0",
        "UPSIDE_DOWN, 0, -1",
        "NONE, 1, 0",
        "NONE, 0, -1",
        "NONE, -3, 2",
        "NONE, 0, 6", // beyond the first search: followed out through steps the samples tie on
        "MIRRORED, 1, 0",
        "TRANSPOSED, 0, 1"})
    void aFlatColouredMeshTurnedOrMovedIsNamedSo(String turn, int right, int down) {
        int n = 300;
        int[] mesh = firstAssignmentPanel(4, 2);
        int[] theirs = made(mesh, n, turn, right, down, false);
        SystematicError found = SystematicError.find(mesh, theirs, n, 8);
        assertNotNull(found, "nothing found");
        assertEquals(Turn.valueOf(turn), found.turn());
        assertEquals(right, found.right());
        assertEquals(down, found.down());
        assertEquals(1.0, found.shareThere(), "undone, it is simpview's panel");
    }

    /** Panel k of the first assignment's page, 300x300 0xRRGGBB pixels row by row from the top. */
    private static int[] firstAssignmentPanel(int page, int k) {
        BufferedImage image = Assignment1.render(page, PageContext.defaults());
        int n = 300;
        int[] panel = new int[n * n];
        int left = k % 2 == 1 ? 50 : 400;
        int top = k <= 2 ? 50 : 400;
        image.getRGB(left, top, n, n, panel, 0, n);
        for (int i = 0; i < panel.length; i++) {
            panel[i] &= 0xFFFFFF;
        }
        return panel;
    }

    @Test
    void aFirstAssignmentPanelIsLookedAtAtItsOwnSize() {
        BufferedImage page = Assignment1.render(2, PageContext.defaults());
        int n = 300;
        int[] ours = new int[n * n];
        page.getRGB(50, 50, n, n, ours, 0, n);
        for (int i = 0; i < ours.length; i++) {
            ours[i] &= 0xFFFFFF;
        }
        SystematicError found = SystematicError.find(ours, made(ours, n, "UPSIDE_DOWN", 0, 0, false), n, 8);
        assertNotNull(found);
        assertEquals(Turn.UPSIDE_DOWN, found.turn());
        assertTrue(found.hint(n).contains("the pixel of y is row 299 - y"), found.hint(n));
        assertThrows(IllegalArgumentException.class, () -> SystematicError.find(ours, new int[5], n, 8));
    }
}
