package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * simpview's first-assignment pages against the course's pictures of them
 * (reference/images/a1; SPEC Part 3), panel by panel, without slack. The
 * shares are those measured on 2026-12-02 (docs/assignment1.md), each held
 * at the measurement minus 0.05 percentage points, and never below the
 * issue's aim where it is reached.
 */
class A1CoursePicturesTest {

    private static double percent(double share) {
        return 100 * share;
    }

    /** Pages 1 and 2, panels 1-3 (DDA, Bresenham, alternating): identical pixels. */
    @ParameterizedTest(name = "page {0} panel {1}")
    @CsvSource({
        // page, panel, measured % identical
        "1, 1, 99.98",
        "1, 2, 96.62",
        "1, 3, 98.30",
        "2, 1, 100.00",
        "2, 2, 100.00",
        "2, 3, 100.00"})
    void linePanelsAreIdentical(int page, int panel, double measured) throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.share(ours(page, panel), theirs(page, panel), 0));
        assertTrue(share >= measured - 0.05, String.format(Locale.ROOT,
                "page %d panel %d: %.2f %% identical (measured %.2f %%)", page, panel, share, measured));
    }

    /** Panel 4 (antialiased): within 8/255, at least 98 %. */
    @ParameterizedTest(name = "page {0} panel 4")
    @CsvSource({"1, 99.02", "2, 100.00"})
    void antialiasedPanelsAreWithin8(int page, double measured) throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.share(ours(page, 4), theirs(page, 4), 8));
        assertTrue(share >= Math.max(98, measured - 0.05), String.format(Locale.ROOT,
                "page %d panel 4: %.2f %% within 8/255 (measured %.2f %%)", page, share, measured));
    }

    /** Pages 4 and 5, panels 1 and 2 (random colours, fixed geometry): the same pixels drawn, at least 99.5 %. */
    @ParameterizedTest(name = "page {0} panel {1}")
    @CsvSource({"4, 1, 99.67", "4, 2, 100.00", "5, 1, 99.67", "5, 2, 100.00"})
    void polygonPanelsHaveTheCoursesGeometry(int page, int panel, double measured) throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.sameGeometry(ours(page, panel), theirs(page, panel)));
        assertTrue(share >= Math.max(99.5, measured - 0.05), String.format(Locale.ROOT,
                "page %d panel %d: %.2f %% the same geometry (measured %.2f %%)", page, panel, share, measured));
    }

    /**
     * Page 5 where no polygon overlaps another (the starburst and both meshes):
     * wherever both pictures drew, the grey is the same, 36, exactly.
     */
    @Test
    void ghostGreysAreExactWhereNothingOverlaps() throws IOException {
        CourseFiles.require("reference/images/a1");
        for (int panel = 1; panel <= 3; panel++) {
            int[] a = ours(5, panel);
            int[] b = theirs(5, panel);
            int both = 0;
            for (int i = 0; i < a.length; i++) {
                if (a[i] != 0 && b[i] != 0) {
                    both++;
                    assertEquals(0x242424, a[i], "ours, panel " + panel);
                    assertEquals(0x242424, b[i], "the course's, panel " + panel);
                }
            }
            assertTrue(both > 40_000, "panel " + panel + ": " + both + " pixels drawn in both");
        }
    }

    /**
     * The tie rule, as far as the course's page 1 panel 2 shows one: at every
     * step of a spoke where the line through its rounded ends passes exactly
     * half-way between two pixels, which of the two the picture lit. The
     * picture steps (away from the start's side) at 30 of the 60 where it
     * lit one of the two, and keeps at the other 30: no rule of an integer
     * Bresenham. simpview steps (so it agrees with the DDA on rising lines).
     */
    @Test
    void theCoursesBresenhamTiesSplitEvenlyAndSimpviewSteps() throws IOException {
        CourseFiles.require("reference/images/a1");
        int[] theirs = theirs(1, 2);
        int[] ours = ours(1, 2);
        simpview.pages.A1Lines spokes = simpview.pages.A1Lines.starburst();
        int stepped = 0;
        int kept = 0;
        int oursStepped = 0;
        for (int i = 0; i < spokes.count(); i++) {
            long x0 = (long) Math.floor(spokes.start(i).x() + 0.5);
            long y0 = (long) Math.floor(spokes.start(i).y() + 0.5);
            long x1 = (long) Math.floor(spokes.end(i).x() + 0.5);
            long y1 = (long) Math.floor(spokes.end(i).y() + 0.5);
            boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
            boolean swap = xMajor ? x1 < x0 : y1 < y0;
            long ax = swap ? x1 : x0;
            long ay = swap ? y1 : y0;
            long steps = Math.abs(xMajor ? x1 - x0 : y1 - y0);
            long rise = xMajor ? (swap ? y0 - y1 : y1 - y0) : (swap ? x0 - x1 : x1 - x0);
            long direction = rise >= 0 ? 1 : -1;
            for (long k = 1; k < steps; k++) {
                if (Math.floorMod(2 * k * Math.abs(rise), 2 * steps) != steps) {
                    continue;
                }
                long keep = (2 * k * Math.abs(rise) - steps) / (2 * steps);
                int keepAt = at(xMajor, ax, ay, k, direction * keep);
                int stepAt = at(xMajor, ax, ay, k, direction * (keep + 1));
                boolean keepLit = theirs[keepAt] != 0;
                boolean stepLit = theirs[stepAt] != 0;
                if (keepLit != stepLit) {
                    stepped += stepLit ? 1 : 0;
                    kept += keepLit ? 1 : 0;
                    oursStepped += ours[stepAt] != 0 && ours[keepAt] == 0 ? 1 : 0;
                }
            }
        }
        assertEquals(30, stepped, "ties where the course's picture stepped (kept: " + kept + ")");
        assertEquals(30, kept, "ties where it kept the start's side");
        assertEquals(stepped + kept, oursStepped, "simpview steps at every one");
    }

    /** Where panel pixel (major k from the start, minor offset) is in a panel packed row 0 at the top. */
    private static int at(boolean xMajor, long ax, long ay, long k, long offset) {
        long x = xMajor ? ax + k : ax + offset;
        long y = xMajor ? ay + offset : ay + k;
        return (int) ((A1Panels.N - 1 - y) * A1Panels.N + x);
    }

    /** A negative control: the starburst's DDA panel against the parallelogram's does not agree. */
    @Test
    void anotherPagesPanelDoesNotAgree() throws IOException {
        CourseFiles.require("reference/images/a1");
        double share = percent(A1Panels.share(ours(1, 1), theirs(2, 1), 0));
        assertTrue(share < 90, share + " %");
    }

    private static int[] ours(int page, int panel) {
        return A1Panels.ourPanel(A1Panels.ourPage(page), panel);
    }

    private static int[] theirs(int page, int panel) throws IOException {
        BufferedImage capture = A1Panels.coursePicture(CourseFiles.shared(), page);
        return A1Panels.coursePanel(capture, panel);
    }
}
