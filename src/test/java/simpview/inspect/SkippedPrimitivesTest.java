package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SceneLibrary;

/**
 * The primitives that reach no rasterizer, projected by hand: SPEC's camera
 * maps camera (x, y, z) to panel ((x / -z - xlow) 650 / (xhigh - xlow), the
 * same for y).
 */
class SkippedPrimitivesTest {

    private static final double EPS = 1e-9;

    @TempDir
    Path dir;

    /**
     * Which outlines U cannot show, the panel (0 to 650 each way) cutting
     * them away whole. The corner triangle past the right and top planes at
     * z = -10 projects to (812.5, 520) (520, 812.5) (780, 780): its box
     * overlaps the panel, but its edge x + y = 1332.5 passes beyond the
     * panel's corner (650, 650), so none of it is on the panel. The one left
     * of the left plane lies at panel x -325 and less. The one beyond the far
     * plane is near the centre.
     */
    @Test
    void theOutlinesWhollyOutsideThePanelAreCounted() throws Exception {
        Path scene = dir.resolve("outside.simp");
        Files.writeString(scene, "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                + "polygon (-1, -1, -200) (1, -1, -200) (0, 1, -200)\n"
                + "polygon (15, 6, -10) (6, 15, -10) (14, 14, -10)\n"
                + "polygon (-20, 0, -10) (-20, 1, -10) (-20, 0, 5)\n");
        SkippedPrimitives.Found found = SkippedPrimitives.of(InspectedScene.of(scene), new SceneLibrary());
        assertEquals(3, found.outlined().size());
        assertFalse(SkippedPrimitives.missesThePanel(found.outlined().get(0).outline()));
        assertTrue(SkippedPrimitives.missesThePanel(found.outlined().get(1).outline()));
        assertTrue(SkippedPrimitives.missesThePanel(found.outlined().get(2).outline()));
        assertEquals(2, found.outsideThePanel());
        // A line across the panel with both ends outside it is on the panel; one beside it is not.
        assertFalse(SkippedPrimitives.missesThePanel(new double[] {-100, 325, 800, 325}));
        assertTrue(SkippedPrimitives.missesThePanel(new double[] {-100, -100, -50, 800}));
    }

    /**
     * U draws outlines, not fills: a skipped polygon whose outline runs all round the panel (a wide wall beyond
     * the far plane: at z = -200 the view reaches 200 each way, the wall 1,000 and more) shows nothing on it, and is
     * counted among those wholly outside. One with a corner on the panel, or an edge across it, shows.
     */
    @Test
    void anOutlineRunningAllRoundThePanelShowsNothingOfIt() throws Exception {
        Path scene = dir.resolve("wall.simp");
        Files.writeString(scene, "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                + "polygon (-1000, -1000, -200) (1000, -1000, -200) (0, 2000, -200)\n");
        SkippedPrimitives.Found found = SkippedPrimitives.of(InspectedScene.of(scene), new SceneLibrary());
        assertEquals(1, found.outlined().size());
        assertEquals(1, found.outsideThePanel());
        assertTrue(SkippedPrimitives.missesThePanel(new double[] {-1000, -100, 1650, -100, 325, 3000}));
        assertFalse(SkippedPrimitives.missesThePanel(new double[] {-100, -100, 800, -100, 325, 300}));
        assertFalse(SkippedPrimitives.missesThePanel(new double[] {-100, 325, 800, 325, 800, 2000}));
        assertFalse(SkippedPrimitives.missesThePanel(new double[] {100, 100, 200, 100, 150, 200}));
    }

    @Test
    void culledClippedAwayAndBehindTheEyeInALitScene() throws Exception {
        Path scene = dir.resolve("skips.simp");
        Files.writeString(scene, "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                // line 3: beyond the far plane (z = -200): culled, its projection near the centre
                + "polygon (-1, -1, -200) (1, -1, -200) (0, 1, -200)\n"
                // line 4: drawn
                + "polygon (-2, -2, -10) (2, -2, -10) (0, 2, -10)\n"
                // line 5: past the corner where the right (x = 10) and top (y = 10) planes meet at z = -10: each
                // vertex inside one of them, so not culled; none of it inside both: clipped away whole
                + "polygon (15, 6, -10) (6, 15, -10) (14, 14, -10)\n"
                // line 6: behind the eye: culled, and no outline
                + "polygon (0, 0, 5) (1, 0, 5) (0, 1, 5)\n"
                // line 7: left of the left plane (x < z) and through the eye's plane: culled, outlined by its
                // part in front of the eye
                + "polygon (-20, 0, -10) (-20, 1, -10) (-20, 0, 5)\n");
        SkippedPrimitives.Found found = SkippedPrimitives.of(InspectedScene.of(scene), new SceneLibrary());
        assertEquals(3, found.outlined().size());
        assertEquals(1, found.unprojectable());
        SkippedPrimitives.Skipped far = found.outlined().get(0);
        assertTrue(far.culled());
        assertEquals(3, far.line());
        assertEquals(scene, far.file());
        assertArrayEquals(new double[] {panel(-1, -200), panel(-1, -200), panel(1, -200), panel(-1, -200),
                panel(0, -200), panel(1, -200)}, far.outline(), EPS);
        SkippedPrimitives.Skipped corner = found.outlined().get(1);
        assertFalse(corner.culled());
        assertEquals(5, corner.line());
        assertArrayEquals(new double[] {panel(15, -10), panel(6, -10), panel(6, -10), panel(15, -10),
                panel(14, -10), panel(14, -10)}, corner.outline(), EPS);
        SkippedPrimitives.Skipped through = found.outlined().get(2);
        assertTrue(through.culled());
        assertEquals(7, through.line());
        // Its front part: its two vertices at z = -10 and the two cuts at the eye's plane (far off the panel).
        assertEquals(8, through.outline().length);
        int atTen = 0;
        for (int k = 0; k < 8; k += 2) {
            atTen += Math.abs(through.outline()[k] - panel(-20, -10)) < EPS ? 1 : 0;
        }
        assertEquals(2, atTen);
        assertEquals(2, found.culled());
        assertEquals(1, found.clipped());
    }

    /** A scene that stops at an error: the primitives skipped before the error, as its page is drawn. */
    @Test
    void aSceneWithAnErrorIsOutlinedAsFarAsTheError() throws Exception {
        Path scene = dir.resolve("broken.simp");
        Files.writeString(scene, "camera -1 -1 1 1 -1 -100\n"
                + "polygon (-1, -1, -200) (1, -1, -200) (0, 1, -200)\n"
                + "scale 1 2\n"
                + "polygon (-1, -1, -300) (1, -1, -300) (0, 1, -300)\n");
        SkippedPrimitives.Found found = SkippedPrimitives.of(InspectedScene.of(scene), new SceneLibrary());
        assertEquals(1, found.outlined().size());
        assertEquals(2, found.outlined().get(0).line());
    }

    @Test
    void aDepthCuedSceneBeyondItsDepthRangeIsCulled() throws Exception {
        Path scene = dir.resolve("cued.simp");
        Files.writeString(scene, "polygon (60, -90, -300) (90, -90, -300) (90, -60, -300)\n"
                + "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        SkippedPrimitives.Found found = SkippedPrimitives.of(InspectedScene.of(scene), new SceneLibrary());
        assertEquals(1, found.outlined().size());
        assertTrue(found.outlined().get(0).culled());
        assertEquals(0, found.unprojectable());
    }

    /** The window [-1, 1] on the plane z = -1, 650 pixels across. */
    private static double panel(double x, double z) {
        return (x / -z + 1) * 650 / 2;
    }
}
