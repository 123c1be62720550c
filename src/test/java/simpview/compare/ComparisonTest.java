package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;

import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Comparing panels: the shares, the slack, the regions and the heat map. */
class ComparisonTest {

    private static final int N = Comparison.N;
    private static final double EPS = 1e-12;

    /** The page with its panel content moved one pixel right; the column that comes in is black. */
    private static BufferedImage shiftedRight(BufferedImage page) {
        BufferedImage moved = copy(page);
        for (int y = 50; y < 700; y++) {
            moved.setRGB(50, y, 0);
            for (int x = 51; x < 700; x++) {
                moved.setRGB(x, y, page.getRGB(x - 1, y));
            }
        }
        return moved;
    }

    /** Every panel pixel's green channel one step of 2/255 brighter or darker (darker where it is at 255). */
    private static BufferedImage greenOffByTwo(BufferedImage page) {
        BufferedImage off = copy(page);
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                int rgb = page.getRGB(x, y);
                int g = rgb >> 8 & 0xFF;
                int moved = g >= 254 ? g - 2 : g + 2;
                off.setRGB(x, y, rgb & 0xFFFF00FF | moved << 8);
            }
        }
        return off;
    }

    static BufferedImage copy(BufferedImage image) {
        BufferedImage copy = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        copy.setData(image.getRaster());
        return copy;
    }

    private static Comparison compare(BufferedImage ours, BufferedImage theirs) throws CompareException {
        return Comparison.of(Picture.ofPage(ours, "ours").panel(), Picture.of(theirs, "theirs").panel());
    }

    @Test
    void aPageAgainstItselfIsIdentical() throws Exception {
        BufferedImage page = page(2);
        Comparison c = compare(page, copy(page));
        assertEquals(new Shares(1, 1, 1), c.exact());
        assertEquals(new Shares(1, 1, 1), c.withSlack());
        assertEquals(0, DiffRegions.of(c, 0, 5).count());
    }

    @Test
    void aPageShiftedByOnePixelMatchesOnlyWithSlack() throws Exception {
        BufferedImage page = page(2);
        BufferedImage shifted = shiftedRight(page);
        Comparison c = compare(page, shifted);
        assertTrue(c.exact().identical() < 0.9, "identical share " + c.exact().identical());
        assertEquals(1.0, c.withSlack().identical(), EPS);
        assertEquals(1.0, c.withSlack().within8(), EPS);
        assertEquals(IndependentShares.direct(page, 50, 50, shifted, 50, 50, 0), c.exact().identical(), EPS);
        assertEquals(IndependentShares.direct(page, 50, 50, shifted, 50, 50, 8), c.exact().within8(), EPS);
    }

    @Test
    void oneChannelOffByTwoEverywhereIsNeverIdenticalButAlwaysWithinEight() throws Exception {
        BufferedImage page = page(3);
        Comparison c = compare(page, greenOffByTwo(page));
        assertEquals(new Shares(0, 0, 1), c.exact());
        assertEquals(new Shares(0, 0, 1), c.withSlack());
        assertEquals(1.0, c.share(2, false), EPS);
        assertEquals(0.0, c.share(1, true), EPS);
    }

    @Test
    void sharesAgreeWithAnIndependentComputation() throws Exception {
        BufferedImage ours = page(1);
        BufferedImage theirs = page(2);
        // Some of it slightly off, some a pixel away, some wholly different.
        theirs = shiftedRight(greenOffByTwo(theirs));
        Comparison c = compare(ours, theirs);
        for (int tolerance : new int[] {0, 1, 2, 8, 40}) {
            assertEquals(IndependentShares.direct(ours, 50, 50, theirs, 50, 50, tolerance), c.share(tolerance, false), EPS,
                    "direct, tolerance " + tolerance);
            assertEquals(IndependentShares.withSlack(ours, 50, 50, theirs, 50, 50, tolerance), c.share(tolerance, true), EPS,
                    "with slack, tolerance " + tolerance);
        }
    }

    @Test
    void aLineMissingFromEitherSideDiffersEvenWithSlack() throws Exception {
        int[] black = new int[N * N];
        int[] line = new int[N * N];
        for (int x = 100; x < 300; x++) {
            line[400 * N + x] = 0xFFFFFF;
        }
        for (Comparison c : List.of(Comparison.of(black, line), Comparison.of(line, black))) {
            assertEquals(1.0 - 200.0 / (N * N), c.share(8, true), EPS);
        }
    }

    @Test
    void regionsAreRectanglesInPanelCoordinatesWithYUp() throws Exception {
        int[] ours = new int[N * N];
        int[] theirs = new int[N * N];
        paint(theirs, 10, 20, 30, 5, 0xFF0000);   // panel x 10-39, y 20-24: 150 pixels
        paint(theirs, 600, 600, 3, 40, 0x00FF00); // x 600-602, y 600-639: 120 pixels
        paint(theirs, 300, 0, 1, 1, 0x0000FF);    // one pixel at the bottom row
        DiffRegions.Found found = DiffRegions.of(Comparison.of(ours, theirs), 8, 2);
        assertEquals(3, found.count());
        assertEquals(271, found.pixels());
        assertEquals(List.of(new DiffRegion(10, 20, 39, 24, 150), new DiffRegion(600, 600, 602, 639, 120)), found.largest());
    }

    /** Fills panel pixels x..x+w-1, y..y+h-1 (y up, as the course counts) in a raster stored from the top. */
    private static void paint(int[] panel, int x, int y, int w, int h, int rgb) {
        for (int py = y; py < y + h; py++) {
            for (int px = x; px < x + w; px++) {
                panel[(N - 1 - py) * N + px] = rgb;
            }
        }
    }

    @Test
    void theHeatMapSaysHowEachPixelDiffers() throws Exception {
        int[] ours = new int[N * N];
        int[] theirs = new int[N * N];
        ours[0] = 0xC0C0C0;
        theirs[0] = 0xC0C0C0;   // identical: ours dimmed to a quarter
        theirs[5] = 0x000004;   // within the tolerance
        theirs[10 * N + 10] = 0xFFFFFF;   // a lone white pixel: differs even with slack
        ours[20 * N + 20] = 0xFFFFFF;   // a white pixel one to the right in theirs
        theirs[20 * N + 21] = 0xFFFFFF;
        Comparison c = Comparison.of(ours, theirs);
        assertEquals(0x303030, HeatMap.colour(c, 0, 8));
        assertEquals(HeatMap.WITHIN, HeatMap.colour(c, 5, 8));
        assertEquals(0xFF0000, HeatMap.colour(c, 10 * N + 10, 8));
        assertEquals(HeatMap.SLACK_ONLY, HeatMap.colour(c, 20 * N + 20, 8));
        assertEquals(0, HeatMap.colour(c, 100 * N + 100, 8));
        BufferedImage diff = HeatMap.diffImage(c, 8);
        assertEquals(3 * N + 2 * HeatMap.GAP, diff.getWidth());
        assertEquals(0xFFFFFF, diff.getRGB(N + HeatMap.GAP + 10, 10) & 0xFFFFFF, "theirs in the middle");
        assertEquals(0xFF0000, diff.getRGB(2 * N + 2 * HeatMap.GAP + 10, 10) & 0xFFFFFF, "the heat map on the right");
        assertEquals(HeatMap.GAP_COLOUR, diff.getRGB(N, 0) & 0xFFFFFF);
    }

    @Test
    void percentagesAreRoundedDownSoNinetyNineNinesIsNotAHundred() {
        assertEquals("99.99 %", Percent.of(0.999999));
        assertEquals("100.00 %", Percent.of(1.0));
        assertEquals("92.58", Percent.number(0.925849));
        assertEquals("0.00 %", Percent.of(0));
    }
}
