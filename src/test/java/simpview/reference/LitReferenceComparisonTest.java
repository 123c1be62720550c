package simpview.reference;

import simpview.testing.DrawnScenes;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.surface.DrawingThreads;
import simpview.testing.Images;
import simpview.testing.ThreadCounts;

/**
 * simpview against the independent reference on lit scenes (SPEC Part 2):
 * every A3 page, every A4 page and random lit scenes must agree on at least
 * 99.9 % of panel pixels within 3/255 per channel, with one pixel of slack;
 * the margins stay white. simpview is asked through one adapter,
 * {@link #simpviewRender}, and each page is drawn by 1, 2 and 7 threads.
 */
class LitReferenceComparisonTest {

    static final double REQUIRED = 0.999;
    static final int TOLERANCE = 3;

    @TempDir
    Path dir;

    /** simpview's picture of a scene, as a 750x750 page, by the rules the scene calls for. */
    static BufferedImage simpviewRender(Path scene) throws Exception {
        return simpviewRender(scene, 1);
    }

    /** The same, drawn by that many threads. */
    static BufferedImage simpviewRender(Path scene, int threads) throws Exception {
        PageCanvas canvas = new PageCanvas();
        try (DrawingThreads drawing = DrawingThreads.of(threads)) {
            canvas.drawWith(drawing);
            DrawnScenes.draw(scene, canvas);
        }
        return canvas.image();
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pageA", "pageB", "pageC", "pageD", "pageE", "pageF", "pageG", "pageH", "pageI",
        "tomsPageJ"})
    void assignment3Pages(String scene) throws Exception {
        assertAgrees(CourseFiles.require("course-simp-a3").resolve(scene + ".simp"));
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"page-a1", "page-a2", "page-a3", "page-b1", "page-b2", "page-b3", "page-c1", "page-c2",
        "page-c3", "page-d", "page-e", "page-f1", "page-f2", "page-g", "page-h"})
    void assignment4Pages(String scene) throws Exception {
        assertAgrees(CourseFiles.require("course-simp-a4").resolve(scene + ".simp"));
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24})
    void randomLitScenes(long seed) throws Exception {
        assertAgrees(RandomLitScenes.write(dir, seed));
    }

    /** simpview's page agrees with the reference's, and its margins are white. */
    static void assertAgrees(Path scene) throws Exception {
        BufferedImage reference = ReferencePage.render(scene);
        for (int threads : ThreadCounts.ALL) {
            assertAgrees(scene, threads, simpviewRender(scene, threads), reference);
        }
    }

    private static void assertAgrees(Path scene, int threads, BufferedImage ours, BufferedImage reference) {
        double share = agreement(ours, reference);
        assertTrue(share >= REQUIRED, scene.getFileName() + " on " + threads + " threads: only " + String.format(Locale.ROOT, "%.4f", 100 * share)
                + " % of panel pixels match the reference");
        int[] page = Images.rgb(ours);
        for (int y = 0; y < RefRaster.PAGE; y++) {
            for (int x = 0; x < RefRaster.PAGE; x++) {
                if ((x < RefRaster.MARGIN || x >= RefRaster.PAGE - RefRaster.MARGIN || y < RefRaster.MARGIN
                        || y >= RefRaster.PAGE - RefRaster.MARGIN) && page[y * RefRaster.PAGE + x] != 0xFFFFFF) {
                    assertEquals(0xFFFFFF, page[y * RefRaster.PAGE + x], "margin " + x + "," + y + " on " + threads
                            + " threads");
                }
            }
        }
    }

    /** The share of simpview's panel pixels within 3/255 of the reference's, with 1 px of slack. */
    static double agreement(BufferedImage ours, BufferedImage reference) {
        return PanelAgreement.share(PanelAgreement.pagePanel(ours), PanelAgreement.pagePanel(reference), TOLERANCE,
                true);
    }
}
