package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.geometry.Camera;
import simpview.surface.ScissorDrawable;
import simpview.testing.RecordingDrawable.Write;
import simpview.testing.RecordingDrawable;

class CullingTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {
        "polygon (-101, 0, -1) (-150, 50, -1) (-300, -90, -100)", // left of x = -100
        "polygon (101, 0, -1) (150, 50, -1) (300, -90, -100)", // right of x = 100
        "polygon (0, -101, -1) (50, -150, -1) (-90, -300, -100)", // below y = -100
        "polygon (0, 101, -1) (50, 150, -1) (-90, 300, -100)", // above y = 100
        "polygon (0, 0, 0.5) (50, 50, 1) (-90, 30, 100)", // nearer than z = 0
        "polygon (0, 0, -200.5) (50, 50, -201) (-90, 30, -1000)", // farther than z = -200
        "line (-500, 0, -1) (-100.001, 99, -1)",
        "line (0, 0, 1e-9) (0, 0, 5)"})
    void primitivesWhollyOutsideOnePlaneReachNoRenderer(String primitive) throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "wire", primitive, "filled", primitive);
        scene.run("s");
        assertEquals(0, scene.drawn());
        assertEquals(2, scene.client.culledCount());
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "polygon (-150, 0, -1) (150, 0, -1) (0, 300, -1)", // outside two different planes, crosses the volume
        "polygon (-150, -150, 10) (150, 150, -300) (0, 0, -100)", // outside left-bottom-near and right-top-far
        "polygon (100, 100, 0) (100, -100, -200) (-100, 0, -100)", // on the boundary planes is inside
        "line (-200, 0, -100) (200, 0, -100)",
        "line (0, 0, 50) (0, 0, -250)"})
    void primitivesNotOutsideOnePlaneAreDrawn(String primitive) throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", primitive);
        scene.run("s");
        assertEquals(1, scene.drawn());
        assertEquals(0, scene.client.culledCount());
    }

    @Test
    void cullingLooksAtWorldSpaceNotTheFile() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "translate 0 0 -300", "polygon (0,0,0) (10,0,0) (0,10,0)", "translate 0 0 250",
                "polygon (0,0,0) (10,0,0) (0,10,0)");
        scene.run("s");
        assertEquals(1, scene.filled.size());
        assertEquals(-50, scene.filled.get(0)[0].z());
    }

    @Test
    void outcodesMarkEachPlane() {
        Camera view = Camera.PARALLEL;
        assertEquals(0, view.outcode(0, 0, -100));
        assertEquals(0, view.outcode(100, -100, 0));
        assertEquals(0, view.outcode(Double.NaN, 0, -1));
        assertEquals(1 << Camera.LEFT, view.outcode(-101, 0, -1));
        assertEquals(1 << Camera.RIGHT | 1 << Camera.TOP | 1 << Camera.HITHER, view.outcode(101, 101, 1));
        assertEquals(1 << Camera.BOTTOM | 1 << Camera.YON, view.outcode(0, -101, -201));
        assertTrue(view.culls(new double[] {-101, 0, -1, -102, 500, -1}, 3, 2));
        assertFalse(view.culls(new double[] {-101, 0, -1, 101, 0, -1}, 3, 2));
    }

    /**
     * Behind the eye the side planes of a perspective view cross: (0.02, 0, 1) has x &lt; xlow (-z) = 1 and
     * x &gt; xhigh (-z) = -1, so it is outside the left and the right plane, and likewise the bottom and the
     * top. A triangle with that vertex and two right of the view is wholly outside the right plane: culled.
     */
    @Test
    void aPointBehindTheEyeIsOutsideBothSidesOfAPair() {
        Camera eye = Camera.perspective(-1, -1, 1, 1, -0.1, -200);
        assertEquals(1 << Camera.HITHER | 1 << Camera.LEFT | 1 << Camera.RIGHT | 1 << Camera.BOTTOM | 1 << Camera.TOP,
                eye.outcode(0.02, 0, 1));
        for (int plane = Camera.LEFT; plane <= Camera.TOP; plane++) {
            assertTrue(eye.distance(plane, 0.02, 0, 1) < 0, "outside plane " + plane + " by its distance too");
        }
        assertEquals(1 << Camera.RIGHT, eye.outcode(30, 0, -10));
        assertTrue(eye.culls(new double[] {0.02, 0, 1, 30, -5, -10, 30, 5, -10}, 3, 3));
    }

    @Test
    void partlyVisiblePrimitivesAreScissored() throws Exception {
        RecordingDrawable recorder = new RecordingDrawable(650, 650);
        SceneFixture scene = new SceneFixture(dir);
        // Sticks out of the left, the top and the near plane.
        scene.write("s", "polygon (-180, 0, 40) (50, 180, -100) (50, -50, -150)", "wire",
                "polygon (-180, 0, 40) (50, 180, -100) (50, -50, -150)", "line (-300, -10, 100) (300, 10, -300)");
        ScenePipeline.drawDepthCued(dir.resolve("s.simp"), new ScissorDrawable(Camera.PARALLEL, recorder), SceneMonitor.NONE);
        List<Write> writes = recorder.writes();
        assertTrue(writes.size() > 1000, "the visible part is drawn: " + writes.size());
        assertEquals(0, recorder.strays(), "writes outside the panel");
        for (Write w : writes) {
            assertTrue(w.z() <= 0 && w.z() >= -200, "inside the depth range");
        }
        assertTrue(writes.stream().anyMatch(w -> w.x() == 0), "reaches the left edge");
    }
}
