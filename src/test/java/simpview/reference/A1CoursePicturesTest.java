package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.math.BigDecimal;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import simpview.pages.A1Lines;
import simpview.pages.A1Rule;

/**
 * simpview's first-assignment pages against the course's pictures of them
 * (reference/images/a1; SPEC Part 3), panel by panel, without slack, under
 * both rules ({@link A1Rule}). The shares are those measured on 2026-12-02
 * (docs/assignment1.md), each held at the measurement minus 0.05 percentage
 * points, and never below the aim (99.5 % for panels 1-3 and the
 * polygons' geometry) where it is reached: under the course's rule
 * everywhere; under SPEC's rule on the DDA panels and page 2, while its
 * integer Bresenham (page 1 panels 2 and 3) and its fill rows at y + 1/2
 * (the mesh panel) stay below it, which is what the rules differ by.
 */
class A1CoursePicturesTest {

    private static double percent(double share) {
        return 100 * share;
    }

    /** Pages 1 and 2, panels 1-3 (DDA, Bresenham, alternating): identical pixels. */
    @ParameterizedTest(name = "page {0} panel {1}, {2}")
    @CsvSource({
        // page, panel, rule, measured % identical, whether the 99.5 % is reached
        "1, 1, SPEC, 99.98, true",
        "1, 2, SPEC, 96.62, false",
        "1, 3, SPEC, 98.30, false",
        "2, 1, SPEC, 100.00, true",
        "2, 2, SPEC, 100.00, true",
        "2, 3, SPEC, 100.00, true",
        "1, 1, COURSE, 99.98, true",
        "1, 2, COURSE, 99.98, true",
        "1, 3, COURSE, 99.98, true",
        "2, 1, COURSE, 100.00, true",
        "2, 2, COURSE, 100.00, true",
        "2, 3, COURSE, 100.00, true"})
    void linePanelsAreIdentical(int page, int panel, A1Rule rule, double measured, boolean aimReached) throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.share(ours(page, panel, rule), theirs(page, panel), 0));
        assertTrue(share >= Math.max(aimReached ? 99.5 : 0, measured - 0.05), String.format(Locale.ROOT,
                "page %d panel %d, %s: %.2f %% identical (measured %.2f %%)", page, panel, rule, share, measured));
        assertEquals(aimReached, share >= 99.5, "whether the issue's 99.5 % is reached");
    }

    /** Panel 4 (antialiased): within 8/255, at least 98 %. */
    @ParameterizedTest(name = "page {0} panel 4")
    @CsvSource({"1, 99.02", "2, 100.00"})
    void antialiasedPanelsAreWithin8(int page, double measured) throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.share(ours(page, 4, A1Rule.SPEC), theirs(page, 4), 8));
        assertEquals(share, percent(A1Panels.share(ours(page, 4, A1Rule.COURSE), theirs(page, 4), 8)),
                "the rules differ only in the Bresenham panels and the fills");
        assertTrue(share >= Math.max(98, measured - 0.05), String.format(Locale.ROOT,
                "page %d panel 4: %.2f %% within 8/255 (measured %.2f %%)", page, share, measured));
    }

    /** Pages 4 and 5, panels 1 and 2 (random colours, fixed geometry): the same pixels drawn, at least 99.5 %. */
    @ParameterizedTest(name = "page {0} panel {1}, {2}")
    @CsvSource({
        // page, panel, rule, measured % the same pixels drawn, whether the 99.5 % is reached
        "4, 1, SPEC, 99.65, true", "4, 2, SPEC, 99.40, false", "5, 1, SPEC, 99.65, true", "5, 2, SPEC, 99.40, false",
        "4, 1, COURSE, 99.82, true", "4, 2, COURSE, 100.00, true", "5, 1, COURSE, 99.82, true",
        "5, 2, COURSE, 100.00, true"})
    void polygonPanelsHaveTheCoursesGeometry(int page, int panel, A1Rule rule, double measured, boolean aimReached)
            throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.sameGeometry(ours(page, panel, rule), theirs(page, panel)));
        assertTrue(share >= Math.max(aimReached ? 99.5 : 0, measured - 0.05), String.format(Locale.ROOT,
                "page %d panel %d, %s: %.2f %% the same geometry (measured %.2f %%)", page, panel, rule, share, measured));
        assertEquals(aimReached, share >= 99.5, "whether the issue's 99.5 % is reached");
    }

    /**
     * Page 5 where no polygon overlaps another (the starburst and both meshes):
     * wherever both pictures drew, the grey is the same, 36, exactly.
     */
    @Test
    void ghostGreysAreExactWhereNothingOverlaps() throws IOException {
        CourseFiles.require("reference/images/a1");
        for (int k = 0; k < 3 * A1Rule.values().length; k++) {
            int panel = 1 + k % 3;
            A1Rule rule = A1Rule.values()[k / 3];
            int[] a = ours(5, panel, rule);
            int[] b = theirs(5, panel);
            int both = 0;
            for (int i = 0; i < a.length; i++) {
                if (a[i] != 0 && b[i] != 0) {
                    both++;
                    assertEquals(0x242424, a[i], "ours, panel " + panel + ", " + rule);
                    assertEquals(0x242424, b[i], "the course's, panel " + panel);
                }
            }
            assertTrue(both > 40_000, "panel " + panel + ": " + both + " pixels drawn in both");
        }
    }

    /**
     * The tie rule, as the course's page 1 panel 2 shows it: at every step of
     * a spoke where the line through its ends (major coordinates rounded,
     * minor ones as given) passes exactly half-way between two pixels,
     * which of the two the picture lit. Only the 60-degree spoke, whose end
     * is x = 217.5 exactly, has such ties: five, the last its end pixel, and
     * the picture keeps the start's side at all five, as simpview does.
     */
    @Test
    void theCoursesBresenhamKeepsAtItsTiesAndSoDoesSimpview() throws IOException {
        CourseFiles.require("reference/images/a1");
        int[] theirs = theirs(1, 2);
        int[] ours = ours(1, 2, A1Rule.COURSE);
        A1Lines spokes = A1Lines.starburst();
        int kept = 0;
        int stepped = 0;
        int oursKept = 0;
        Set<Integer> tiedSpokes = new TreeSet<>();
        for (int i = 0; i < spokes.count(); i++) {
            double[] p = {spokes.start(i).x(), spokes.start(i).y()};
            double[] q = {spokes.end(i).x(), spokes.end(i).y()};
            long x0 = (long) Math.floor(p[0] + 0.5);
            long y0 = (long) Math.floor(p[1] + 0.5);
            long x1 = (long) Math.floor(q[0] + 0.5);
            long y1 = (long) Math.floor(q[1] + 0.5);
            boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
            int major = xMajor ? 0 : 1;
            boolean swap = xMajor ? x1 < x0 : y1 < y0;
            double[] a = swap ? q : p;
            double[] b = swap ? p : q;
            long a0 = (long) Math.floor(a[major] + 0.5);
            long n = (long) Math.floor(b[major] + 0.5) - a0;
            BigDecimal b0 = new BigDecimal(a[1 - major]);
            BigDecimal b1 = new BigDecimal(b[1 - major]);
            BigDecimal twiceN = BigDecimal.valueOf(2 * n);
            for (long k = 1; k <= n; k++) {
                // n times the minor coordinate at step k; a tie when 2 (that) - n is a multiple of 2 n.
                BigDecimal at = b0.multiply(BigDecimal.valueOf(n)).add(b1.subtract(b0).multiply(BigDecimal.valueOf(k)));
                BigDecimal[] qr = at.multiply(BigDecimal.valueOf(2)).subtract(BigDecimal.valueOf(n)).divideAndRemainder(twiceN);
                if (qr[1].signum() != 0) {
                    continue;
                }
                tiedSpokes.add(i);
                long below = qr[0].longValueExact();
                boolean rising = b1.compareTo(b0) >= 0;
                long keep = rising ? below : below + 1;
                long step = rising ? below + 1 : below;
                int keepAt = at(xMajor, a0 + k, keep);
                int stepAt = at(xMajor, a0 + k, step);
                kept += theirs[keepAt] != 0 && theirs[stepAt] == 0 ? 1 : 0;
                stepped += theirs[stepAt] != 0 && theirs[keepAt] == 0 ? 1 : 0;
                oursKept += ours[keepAt] != 0 && ours[stepAt] == 0 ? 1 : 0;
            }
        }
        assertEquals(Set.of(15), tiedSpokes, "the spokes with exact ties");
        assertEquals(5, kept, "ties where the course's picture kept (stepped: " + stepped + ")");
        assertEquals(0, stepped, "ties where it stepped");
        assertEquals(kept, oursKept, "simpview keeps at every one");
    }

    /** Where panel pixel (major, minor) is in a panel packed row 0 at the top. */
    private static int at(boolean xMajor, long major, long minor) {
        long x = xMajor ? major : minor;
        long y = xMajor ? minor : major;
        return (int) ((A1Panels.N - 1 - y) * A1Panels.N + x);
    }

    /** A negative control: the starburst's DDA panel against the parallelogram's does not agree. */
    @Test
    void anotherPagesPanelDoesNotAgree() throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.share(ours(1, 1, A1Rule.SPEC), theirs(2, 1), 0));
        assertTrue(share < 90, share + " %");
    }

    /** Each page drawn once and each picture read once for the class (the tests within a class run one at a time). */
    private static final Map<String, BufferedImage> OURS = new HashMap<>();
    private static final Map<Integer, BufferedImage> THEIRS = new HashMap<>();

    private static int[] ours(int page, int panel, A1Rule rule) {
        return A1Panels.ourPanel(OURS.computeIfAbsent(page + " " + rule, key -> A1Panels.ourPage(page, rule)), panel);
    }

    private static int[] theirs(int page, int panel) throws IOException {
        BufferedImage capture = THEIRS.get(page);
        if (capture == null) {
            capture = A1Panels.coursePicture(CourseFiles.shared(), page);
            THEIRS.put(page, capture);
        }
        return A1Panels.coursePanel(capture, panel);
    }
}
