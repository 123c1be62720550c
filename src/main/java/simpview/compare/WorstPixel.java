package simpview.compare;

/**
 * One pixel to look at first: of the largest patch that differs, the pixel
 * whose colour is farthest from simpview's (without slack; with the FLIP
 * metric, of the patch FLIP fails, the pixel of another colour whose FLIP
 * value is highest), and which way the patch's pixels differ, brighter or
 * darker. A student who asks how simpview made that one pixel ({@code simpview inspect --at X,Y --explain})
 * sees the terms their own renderer must have got otherwise there.
 *
 * @param x the pixel's x in panel coordinates (right from the panel's left column)
 * @param y the pixel's y in panel coordinates (up from the panel's bottom row)
 * @param ours simpview's colour there, 0xRRGGBB
 * @param theirs the picture's colour there, 0xRRGGBB
 * @param brighter how many of the patch's pixels that differ are brighter in the picture (their channels' sum higher)
 * @param darker how many are darker
 * @param differing how many of the patch's pixels differ beyond the tolerance even with slack
 */
public record WorstPixel(int x, int y, int ours, int theirs, int brighter, int darker, int differing) {

    /**
     * The pixel of {@code patch} (a patch of {@code comparison} beyond {@code tolerance}) that differs most, the
     * first from the top-left of those that differ as much; or null when no pixel in the patch's box fails. With the
     * FLIP metric a pixel fails by its FLIP value, and the one that differs most is the one FLIP rates highest (the
     * one the verdict fails on most; the colour farthest from simpview's may be one the eye sees little of) of those
     * whose colour is not simpview's: FLIP also fails the pixels beside one that differs, and a pixel of simpview's
     * own colour is no place to look.
     */
    public static WorstPixel in(Comparison comparison, DiffRegion patch, int tolerance) {
        int n = comparison.size();
        int[] ours = comparison.ours();
        int[] theirs = comparison.theirs();
        boolean flip = comparison.metric() == Comparison.Metric.FLIP;
        int best = -1;
        double worst = -1;
        int brighter = 0;
        int darker = 0;
        int differing = 0;
        for (int row = n - 1 - patch.top(); row <= n - 1 - patch.bottom(); row++) {
            for (int x = patch.left(); x <= patch.right(); x++) {
                int i = row * n + x;
                if (!comparison.fails(i, tolerance)) {
                    continue;
                }
                differing++;
                int way = brightness(theirs[i]) - brightness(ours[i]);
                if (way > 0) {
                    brighter++;
                } else if (way < 0) {
                    darker++;
                }
                // with FLIP, a pixel of simpview's colour (failed for its neighbour) comes after every other
                double by = !flip ? comparison.distance(i) : comparison.distance(i) == 0 ? -0.5 : comparison.flip(i);
                if (by > worst) {
                    worst = by;
                    best = i;
                }
            }
        }
        return best < 0 ? null : new WorstPixel(best % n, n - 1 - best / n, ours[best] & 0xFFFFFF,
                theirs[best] & 0xFFFFFF, brighter, darker, differing);
    }

    private static int brightness(int rgb) {
        return (rgb >> 16 & 0xFF) + (rgb >> 8 & 0xFF) + (rgb & 0xFF);
    }

    /** "x 172, y 256", as {@code inspect --at} is given it: "172,256". */
    public String at() {
        return x + "," + y;
    }

    /**
     * The report's line (after "look:    "): where, both colours, and which way the patch differs, e.g. "x 172, y
     * 256 differs most in patch 1: yours (255,200,180), simpview's (120,60,30); of the patch's 9,844 pixels that
     * differ, yours is brighter at 97 % and darker at 3 %".
     */
    public String describe() {
        return describe("x " + x + ", y " + y);
    }

    /**
     * The same, the pixel named by {@code place} ("panel 2 (Bresenham) x 150, y 149 (page x 550, y 549)"), as a
     * page of several panels names it.
     */
    public String describe(String place) {
        return place + " differs most in patch 1: yours " + Rasters.words(theirs) + ", simpview's "
                + Rasters.words(ours) + "; of the patch's " + Count.of(differing, "pixel") + " that "
                + (differing == 1 ? "differs" : "differ") + ", yours is brighter at "
                + Percent.of((double) brighter / differing) + " and darker at " + Percent.of((double) darker / differing);
    }
}
