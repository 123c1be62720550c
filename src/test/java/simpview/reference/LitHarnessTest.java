package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * What {@link LitReferenceComparisonTest} stands on, checked today while that
 * class waits for simpview's lit scenes: its adapter and measure pass
 * simpview's depth-cued pictures and catch a wrong one, and every random lit
 * scene it will use is lit, valid and drawn by the reference (the whole run
 * bounds its time: a timed assertion here failed only under load).
 */
class LitHarnessTest {

    @TempDir
    Path dir;

    private Path depthCuedScene(long seed) throws IOException {
        Files.writeString(dir.resolve("cube.simp"), RandomLitScenes.cube());
        Path scene = dir.resolve("cued" + seed + ".simp");
        Files.writeString(scene, ReferenceComparisonTest.randomScene(new Random(seed)));
        return scene;
    }

    @Test
    void theAdapterAndTheMeasurePassADepthCuedScene() throws Exception {
        Path scene = depthCuedScene(3);
        assertTrue(!ReferencePage.isLit(scene));
        LitReferenceComparisonTest.assertAgrees(scene);
    }

    @Test
    void theMeasureCatchesAWrongPicture() throws Exception {
        double share = LitReferenceComparisonTest.agreement(
                LitReferenceComparisonTest.simpviewRender(depthCuedScene(4)), ReferencePage.render(depthCuedScene(5)));
        assertTrue(share < LitReferenceComparisonTest.REQUIRED, "two different scenes agree on " + share);
    }

    /** The threshold is fine enough to tell the shading modes apart on the course's page-b (a specular cube row). */
    @Test
    void theMeasureTellsTheShadingModesApart() throws Exception {
        Path a4 = CourseFiles.require("course-simp-a4");
        BufferedImage flat = ReferencePage.render(a4.resolve("page-b1.simp"));
        BufferedImage gouraud = ReferencePage.render(a4.resolve("page-b2.simp"));
        BufferedImage phong = ReferencePage.render(a4.resolve("page-b3.simp"));
        double flatGouraud = LitReferenceComparisonTest.agreement(flat, gouraud);
        double gouraudPhong = LitReferenceComparisonTest.agreement(gouraud, phong);
        assertTrue(flatGouraud < LitReferenceComparisonTest.REQUIRED, "flat passes for gouraud: " + flatGouraud);
        assertTrue(gouraudPhong < LitReferenceComparisonTest.REQUIRED, "gouraud passes for phong: " + gouraudPhong);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24})
    void everyRandomLitSceneIsDrawnByTheReference(long seed) throws IOException {
        Path scene = RandomLitScenes.write(dir, seed);
        assertTrue(ReferencePage.isLit(scene));
        int[] panel = PanelAgreement.pagePanel(ReferencePage.render(scene));
        int drawn = 0;
        for (int rgb : panel) {
            drawn += rgb != 0 ? 1 : 0;
        }
        assertTrue(drawn > 500, "seed " + seed + " drew only " + drawn + " pixels");
    }
}
