package simpview.compare;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import simpview.pages.A1Page;
import simpview.pages.LineTestPage;
import simpview.pages.PolygonTestPage;
import simpview.surface.PageCanvas;

/**
 * A first-assignment page drawn from the student's own random numbers: page 3's lines, page 4's colours, the
 * random triangles of pages 4 and 5. The handout asks each student to choose them; simpview draws its own from
 * the seed, so such a picture cannot match and every panel fails with nothing wrong in the renderer. Told by
 * the panels whose drawing does not depend on blending: on page 3, panels 1 to 3 (DDA, Bresenham,
 * alternating) light pixels that simpview's hardly light ({@link #OTHER_LINES}), and leave most of simpview's
 * black ({@link #OURS_LIT}); on pages 4 and 5, panel 4's
 * random triangles cover other pixels ({@link #OTHER_TRIANGLES}); on page 4, panels 1 and 2 (the starburst
 * and the mesh, whose shapes are fixed) fill simpview's pixels in other colours ({@link #OTHER_COLOURS}).
 * A student who drew simpview's values (its {@code --primitives} listing) with a mistake of their own lights
 * nearly the same pixels, in the same colours, and gets no such hint; nor does a right picture saved as a JPEG
 * (a pixel is lit when it is further than the tolerance from black); nor does one whose colours are simpview's
 * turned one way (halved, put through a gamma), which keeps their order ({@link #orderKept}).
 *
 * @param page the page, "A1 page 3 (seed 361)"
 * @param number the page's number, 1 to 5
 * @param seed the seed simpview drew it with
 * @param what what is not simpview's: "lines", "random triangles", "colours"
 * @param evidence what was measured, in words
 * @param firstAssignment whether the page is the first assignment's; else one of the eight pages (page 3)
 */
public record RandomValues(String page, int number, long seed, String what, String evidence, boolean firstAssignment)
        implements PanelHint {

    /** Of the pixels either of panels 1 to 3 lights, at most this share lit in both: other lines. */
    static final double OTHER_LINES = 0.25;
    /** And of the pixels simpview's panels 1 to 3 light, at most this share lit in the picture's too. */
    static final double OURS_LIT = 0.5;
    /** Of the pixels either of panel 4 fills, at most this share filled in both: other triangles. */
    static final double OTHER_TRIANGLES = 0.9;
    /** Of the pixels both fill in panels 1 and 2, at most this share of simpview's colour: other colours. */
    static final double OTHER_COLOURS = 0.5;
    /** Of the pairs of simpview's colours {@link #orderKept} compares, at most this share in the other order. */
    static final double ORDER_BROKEN = 0.05;
    /** The most of simpview's colours {@link #orderKept} compares. */
    static final int MOST_COLOURS = 1024;

    /**
     * The hint for first-assignment page {@code number} ({@code shown}, drawn with {@code seed}; ours and theirs
     * its four n x n panels, row by row from the top), or null when its values look like simpview's, or it draws
     * none at random.
     */
    public static RandomValues find(String page, int number, A1Page shown, long seed, int[][] ours, int[][] theirs,
            int n, int tolerance) {
        if (!shown.usesSeed() || ours.length != 4 || theirs.length != 4) {
            return null;
        }
        if (shown instanceof LineTestPage) {
            double most = 0;
            double mostOfOurs = 0;
            for (int k = 0; k < 3; k++) {
                if (!drawsAsMuch(ours[k], theirs[k], tolerance)) {
                    return null; // a panel left (nearly) empty is a mistake of its own
                }
                most = Math.max(most, bothOfEither(ours[k], theirs[k], n, tolerance));
                mostOfOurs = Math.max(mostOfOurs, ofOurs(ours[k], theirs[k], tolerance));
            }
            // a JPEG's rings light the pixels beside a line too: its lines share few of the pixels either lights,
            // yet they light every one of simpview's
            if (most > OTHER_LINES || mostOfOurs > OURS_LIT) {
                return null;
            }
            return new RandomValues(page, number, seed, "lines", "of the pixels either picture lights in panels 1 to "
                    + "3, both light " + Percent.of(most) + " at most", true);
        }
        double triangles = bothOfEither(ours[3], theirs[3], n, tolerance);
        if (triangles <= OTHER_TRIANGLES && drawsAsMuch(ours[3], theirs[3], tolerance)) {
            return new RandomValues(page, number, seed, "random triangles", "of the pixels either picture fills in "
                    + "panel 4, both fill " + Percent.of(triangles), true);
        }
        if (shown instanceof PolygonTestPage polygons && !polygons.ghost()) {
            double shapes = Math.min(bothOfEither(ours[0], theirs[0], n, tolerance),
                    bothOfEither(ours[1], theirs[1], n, tolerance));
            double colours = Math.max(sameColour(ours[0], theirs[0], tolerance),
                    sameColour(ours[1], theirs[1], tolerance));
            if (shapes > OTHER_TRIANGLES && colours <= OTHER_COLOURS
                    && !orderKept(new int[][] {ours[0], ours[1]}, new int[][] {theirs[0], theirs[1]}, tolerance)) {
                return new RandomValues(page, number, seed, "colours", "your triangles of panels 1 and 2 fill "
                        + "simpview's pixels, but of the pixels both fill, " + Percent.of(colours) + " at most have "
                        + "simpview's colour within " + tolerance + "/255", true);
            }
        }
        return null;
    }

    /**
     * Whether the colours of the pixels lit in both follow simpview's channel by channel, in the same order: of
     * each two of simpview's colours whose channel differs by more than the tolerance, the two colours drawn in
     * their place (the mean over the pixels of each) differ the other way by more than it in at most
     * {@value #ORDER_BROKEN} of them. A renderer that turns every colour one way (halves it, puts it through a
     * gamma, floors it on another scale) keeps the order; its own random colours break it about every second
     * time. Simpview's panels hold a colour per triangle, a few hundred at most; beyond {@value #MOST_COLOURS}
     * the rest are left out.
     */
    static boolean orderKept(int[][] ours, int[][] theirs, int tolerance) {
        Map<Integer, long[]> drawn = new HashMap<>();
        for (int k = 0; k < ours.length; k++) {
            for (int i = 0; i < ours[k].length; i++) {
                if (!lit(ours[k][i], tolerance) || !lit(theirs[k][i], tolerance)) {
                    continue;
                }
                long[] sum = drawn.get(ours[k][i] & 0xFFFFFF);
                if (sum == null) {
                    if (drawn.size() == MOST_COLOURS) {
                        continue;
                    }
                    sum = new long[4];
                    drawn.put(ours[k][i] & 0xFFFFFF, sum);
                }
                int t = theirs[k][i];
                sum[0] += t >> 16 & 0xFF;
                sum[1] += t >> 8 & 0xFF;
                sum[2] += t & 0xFF;
                sum[3]++;
            }
        }
        int count = drawn.size();
        int[] simpviews = new int[count];
        double[][] means = new double[count][3];
        int at = 0;
        for (Map.Entry<Integer, long[]> e : drawn.entrySet()) {
            simpviews[at] = e.getKey();
            long[] sum = e.getValue();
            for (int c = 0; c < 3; c++) {
                means[at][c] = (double) sum[c] / sum[3];
            }
            at++;
        }
        long compared = 0;
        long broken = 0;
        for (int c = 0; c < 3; c++) {
            int shift = 16 - 8 * c;
            for (int i = 0; i < count; i++) {
                for (int j = i + 1; j < count; j++) {
                    int ourStep = (simpviews[j] >> shift & 0xFF) - (simpviews[i] >> shift & 0xFF);
                    if (Math.abs(ourStep) <= tolerance) {
                        continue;
                    }
                    double theirStep = means[j][c] - means[i][c];
                    compared++;
                    broken += Math.abs(theirStep) > tolerance && Math.signum(theirStep) != Math.signum(ourStep) ? 1 : 0;
                }
            }
        }
        return compared > 0 && broken <= ORDER_BROKEN * compared;
    }

    /** Of the pixels lit in ours, the share lit in theirs too; 1 when ours lights none. */
    private static double ofOurs(int[] ours, int[] theirs, int tolerance) {
        int lit = 0;
        int both = 0;
        for (int i = 0; i < ours.length; i++) {
            if (lit(ours[i], tolerance)) {
                lit++;
                both += lit(theirs[i], tolerance) ? 1 : 0;
            }
        }
        return lit == 0 ? 1 : (double) both / lit;
    }

    /** Whether theirs lights at least half as many pixels as ours: a panel drawn, not left black. */
    private static boolean drawsAsMuch(int[] ours, int[] theirs, int tolerance) {
        int a = 0;
        int b = 0;
        for (int i = 0; i < ours.length; i++) {
            a += lit(ours[i], tolerance) ? 1 : 0;
            b += lit(theirs[i], tolerance) ? 1 : 0;
        }
        return 2L * b >= a;
    }

    /** Of the pixels lit (not the panel's black) in ours or theirs, the share lit in both; 1 when neither lights any. */
    private static double bothOfEither(int[] ours, int[] theirs, int n, int tolerance) {
        int either = 0;
        int both = 0;
        for (int i = 0; i < n * n; i++) {
            boolean a = lit(ours[i], tolerance);
            boolean b = lit(theirs[i], tolerance);
            either += a || b ? 1 : 0;
            both += a && b ? 1 : 0;
        }
        return either == 0 ? 1 : (double) both / either;
    }

    /** Of the pixels lit in both, the share within the tolerance in every channel; 1 when none is. */
    private static double sameColour(int[] ours, int[] theirs, int tolerance) {
        int both = 0;
        int same = 0;
        for (int i = 0; i < ours.length; i++) {
            if (lit(ours[i], tolerance) && lit(theirs[i], tolerance)) {
                both++;
                same += Rasters.distance(ours[i], theirs[i]) <= tolerance ? 1 : 0;
            }
        }
        return both == 0 ? 1 : (double) same / both;
    }

    /**
     * Whether a pixel is lit: further than the tolerance from the panel's black in some channel. A JPEG's black
     * is rarely 0 0 0 to the bit, and taken as lit everywhere it made a right picture's lines or triangles look
     * like others.
     */
    private static boolean lit(int rgb, int tolerance) {
        return Rasters.distance(rgb, PageCanvas.BACKGROUND) > tolerance;
    }

    /** The least share of the z-buffer page's panel of theirs in simpview's colours, each within the tolerance. */
    static final double OWN_COLOURS = 0.99;
    /** Of the pixels either picture draws (not black), at most this share drawn in both in one colour. */
    static final double SAME_PLACE = 0.75;

    /**
     * The hint for the z-buffer page of the eight (its six triangles turned and put at depths drawn at random; ours
     * and theirs its one n x n panel), or null. Its triangles are flat greys, so a picture whose pixels are all of
     * simpview's colours, but which draws them elsewhere, drew simpview's triangles from other random numbers.
     */
    public static RandomValues ofZBufferPage(String page, int number, long seed, int[] ours, int[] theirs,
            int tolerance) {
        int[] colours = new int[17];
        int count = 0;
        for (int colour : ours) {
            colour &= 0xFFFFFF;
            int k = 0;
            while (k < count && colours[k] != colour) {
                k++;
            }
            if (k == count) {
                if (count == colours.length) {
                    return null; // more colours than flat triangles have
                }
                colours[count++] = colour;
            }
        }
        long inColours = 0;
        long drawn = 0;
        long same = 0;
        int last = colours[0]; // the colour the pixel before matched: neighbours mostly share one
        for (int i = 0; i < theirs.length; i++) {
            int theirColour = theirs[i];
            if (Rasters.distance(last, theirColour) <= tolerance) {
                inColours++;
            } else {
                for (int k = 0; k < count; k++) {
                    if (Rasters.distance(colours[k], theirColour) <= tolerance) {
                        inColours++;
                        last = colours[k];
                        break;
                    }
                }
            }
            if (lit(ours[i], tolerance) || lit(theirColour, tolerance)) {
                drawn++;
                same += Rasters.distance(ours[i], theirColour) <= tolerance ? 1 : 0;
            }
        }
        if (inColours < OWN_COLOURS * theirs.length || same > SAME_PLACE * drawn) {
            return null;
        }
        return new RandomValues(page, number, seed, "triangles", "every pixel of yours is one of the "
                + count + " colours of simpview's panel, but of the pixels either picture draws, both draw "
                + Percent.of((double) same / drawn) + " in the same colour", false);
    }

    @Override
    public String brief() {
        return "drawn from other random numbers than simpview's seed " + seed;
    }

    @Override
    public String hint(int n) {
        return String.format(Locale.ROOT, "your %s are not simpview's, which it draws at random from seed %d: %s. A "
                + "page drawn from random numbers of your own cannot match; to compare your renderer, draw simpview's "
                + "lines and triangles with their colours, which simpview render %s--page %d --seed %d "
                + "--primitives %spage%d-primitives.txt lists (panel coordinates, y up), and compare again.",
                what, seed, evidence, firstAssignment ? "--assignment 1 " : "", number, seed,
                firstAssignment ? "a1-" : "", number);
    }

    @Override
    public boolean wholePage() {
        return true;
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}
