package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The vertex table's answer to "does this primitive cover this pixel's
 * centre, and why", against what the drawing did: a primitive covers a pixel
 * by the table exactly when the pixel's history has a write from it. The
 * scenes put pixel centres exactly on shared edges, where only the top-left
 * rule decides.
 */
class CentreCoverageTest {

    @TempDir
    Path dir;

    /** One inspector for every replay of a test, as the window keeps one: its canvas and models reused. */
    private final PixelInspector inspector = new PixelInspector();

    /**
     * A depth-cued scene's world x = -100 + 4j lands on panel x = 13j exactly
     * ((x + 100) 650 / 200), so these triangles' vertices are whole panel
     * points, and an edge of odd slope (1, 1/3, 3, -1, ...) runs through pixel
     * centres. A fan of eight triangles around the panel's centre (325, 325),
     * each sharing its two edges with its neighbours: every pixel near the
     * centre is covered by exactly one of them, the ones on the shared edges
     * by the top-left rule.
     */
    private static final int[][] AROUND = {{4, 4}, {-4, 12}, {-12, 4}, {-12, -4}, {-4, -12}, {4, -12}, {12, -4},
        {12, 4}};

    private Path fan() throws Exception {
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < AROUND.length; k++) {
            int[] a = AROUND[k];
            int[] b = AROUND[(k + 1) % AROUND.length];
            sb.append("polygon (0, 0, -").append(10 + k).append(") (").append(4 * a[0]).append(", ").append(4 * a[1])
                    .append(", -").append(10 + k).append(") (").append(4 * b[0]).append(", ").append(4 * b[1])
                    .append(", -").append(10 + k).append(")\n");
        }
        Path file = dir.resolve("fan.simp");
        Files.writeString(file, sb.toString());
        return file;
    }

    @Test
    void onASharedDiagonalTheTopLeftRuleIsNamed() throws Exception {
        Path file = dir.resolve("diagonal.simp");
        Files.writeString(file, "polygon (-100, -100, -10) (100, -100, -10) (100, 100, -10)\n"
                + "polygon (-100, -100, -20) (100, 100, -20) (-100, 100, -20)\n");
        for (int i = 0; i < 650; i += 59) {
            PixelReport report = inspector.inspect(InspectedScene.of(file), i, i, 1);
            Terms below = report.vertices(0).terms("centre");
            Terms above = report.vertices(1).terms("centre");
            String where = "pixel (" + i + ", " + i + ")";
            assertEquals(true, below.get("covered"), where);
            assertTrue(String.valueOf(below.get("why")).contains("a top or left edge"), where + ": " + below.get("why"));
            assertEquals(false, above.get("covered"), where);
            assertTrue(String.valueOf(above.get("why")).contains("a right or bottom edge"), where + ": " + above.get("why"));
            assertEquals(1, report.history().size(), where + ": one write");
            assertEquals(0, report.history().get(0).primitive(), where);
        }
        // a vertex on the panel's edge rounds to a pixel past it, and the table says so
        Terms corner = inspector.inspect(InspectedScene.of(file), 300, 300, 0).vertices(0).list("vertices")
                .get(2);
        assertEquals("past the panel's pixels, 0 to 649 each way", corner.get("pixel_outside"));
        assertEquals(null, inspector.inspect(InspectedScene.of(file), 300, 300, 0).vertices(0)
                .list("vertices").get(0).get("pixel_outside"), "vertex (0, 0) is the panel's first pixel");
        // off the diagonal, above it: outside the first, inside the second
        PixelReport report = inspector.inspect(InspectedScene.of(file), 100, 400, 0);
        assertEquals("the centre is outside the outline", report.vertices(0).terms("centre").get("why"));
        assertEquals("the centre is inside the triangle", report.vertices(1).terms("centre").get("why"));
    }

    @Test
    void theTableCoversExactlyWhereTheDrawingWrote() throws Exception {
        Path file = fan();
        int ties = 0;
        for (int y = 312; y < 338; y++) {
            for (int x = 312; x < 338; x++) {
                int covering = 0;
                for (int k = 0; k < AROUND.length; k++) {
                    int p = k;
                    PixelReport report = inspector.inspect(InspectedScene.of(file), x, y, p);
                    Terms centre = report.vertices(p).terms("centre");
                    assertNotNull(centre, "no centre for primitive " + p);
                    boolean covered = (Boolean) centre.get("covered");
                    boolean wrote = report.history().stream().anyMatch(e -> e.primitive() == p);
                    String where = "pixel (" + x + ", " + y + "), primitive " + (p + 1) + ": " + centre.get("why");
                    assertEquals(wrote, covered, where);
                    if (covered) {
                        covering++;
                        if (String.valueOf(centre.get("why")).contains("exactly on edge")) {
                            ties++;
                        }
                    }
                }
                assertEquals(1, covering, "pixel (" + x + ", " + y + ") is covered by one triangle of the fan");
            }
        }
        assertTrue(ties >= 20, "too few centres on shared edges to test the rule: " + ties);
    }

    /**
     * A lit triangle through the near plane, clipped to a quadrilateral and
     * filled as a fan of two: the table follows the drawn outline, clipped
     * and projected.
     */
    @Test
    void aLitPolygonsFanTrianglesAgreeWithItsPixels() throws Exception {
        Path file = dir.resolve("lit.simp");
        Files.writeString(file, "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                + "polygon (0.2, 0.1, -0.5) (4, -1, -10) (-1, 4, -10)\n");
        int inside = 0;
        int outside = 0;
        for (int y = 150; y < 500; y += 7) {
            for (int x = 150; x < 500; x += 7) {
                PixelReport report = inspector.inspect(InspectedScene.of(file), x, y, 0);
                Terms centre = report.vertices(0).terms("centre");
                boolean covered = (Boolean) centre.get("covered");
                // a write reached the pixel (an entry "clipped" says only that the uncut triangle would have covered it)
                boolean wrote = report.history().stream().anyMatch(e -> e.outcome() != Outcome.CLIPPED);
                assertEquals(wrote, covered, "pixel (" + x + ", " + y + "): " + centre.get("why"));
                assertEquals(2, centre.list("fan").size());
                if (covered) {
                    inside++;
                } else {
                    outside++;
                }
            }
        }
        assertTrue(inside > 100 && outside > 100, inside + " inside, " + outside + " outside");
    }
}
