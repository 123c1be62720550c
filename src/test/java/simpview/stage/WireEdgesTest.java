package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjModel;
import simpview.surface.DrawingThreads;

/**
 * A wire model's edges that two faces share, drawn once (LitGeometry's
 * edgesKnown): the picture and the depths are to the bit those of every face
 * drawing all its edges, drawn at once on one thread and recorded and drawn
 * in bands by two (LitPrimitives). The model is {@link ModelPage}'s rough
 * terrain, which runs from behind the eye (faces clipped by the near plane)
 * past the sides of the view (faces clipped by them) to far away (edges
 * shorter than a pixel, some with both ends on one pixel).
 */
class WireEdgesTest {

    /** The model drawn as wire with {@code threads}; {@code edgesRead}: its faces tell which earlier face shares each edge. */
    private static ModelPage.Drawing draw(ObjModel model, boolean edgesRead, DrawingThreads threads)
            throws SceneException {
        return ModelPage.draw(model, ModelPage.state(), true, edgesRead, null, threads);
    }

    @Test
    void edgesSharedByFacesWholeInViewAreDrawnOnceToTheSamePicture() throws Exception {
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (int n : new int[] {12, 80, 240}) {
                    String what = n + "x" + n + " on " + threads + " thread(s)";
                    ObjModel model = ObjModel.of(ModelPage.FILE, ModelPage.terrain(n, 48 + n));
                    ModelPage.Drawing every = draw(model, false, drawing);
                    ModelPage.Drawing once = draw(model, true, drawing);
                    assertEquals(0, every.geometry().edgesLeftOut(), "every edge drawn");
                    long leftOut = once.geometry().edgesLeftOut();
                    assertTrue(leftOut > n * n / 2, what + ": shared edges left out: " + leftOut);
                    assertArrayEquals(every.pixels(), once.pixels(), what + ": the picture");
                    assertArrayEquals(every.depths(), once.depths(), what + ": the depths, to the bit");
                }
            }
        }
    }
}
