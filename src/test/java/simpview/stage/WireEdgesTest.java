package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.geometry.Axis;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjModel;
import simpview.scene.obj.ObjSink;
import simpview.shading.FragmentStages;
import simpview.shading.LitState;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.testing.DepthBits;
import simpview.testing.Images;

/**
 * A wire model's edges that two faces share, drawn once (LitGeometry's
 * edgesKnown): the picture and the depths are to the bit those of every face
 * drawing all its edges, drawn at once on one thread and recorded and drawn
 * in bands by two (LitPrimitives). The model is a rough terrain of quads and
 * triangles, from a fixed seed, running from behind the eye (faces clipped
 * by the near plane) past the sides of the view (faces clipped by them) to
 * far away (edges shorter than a pixel, some with both ends on one pixel).
 */
class WireEdgesTest {

    private static final Path FILE = Path.of("terrain.obj");

    /** A grid of n x n cells, each a quad or, every third cell, two triangles. */
    private static byte[] terrain(int n, long seed) {
        Random random = new Random(seed);
        StringBuilder obj = new StringBuilder();
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                double x = -90 + 180.0 * j / n;
                double z = 5 - 400.0 * i / n;
                double y = -12 + 6 * random.nextDouble();
                obj.append("v ").append(x).append(' ').append(y).append(' ').append(z).append('\n');
            }
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int a = i * (n + 1) + j + 1; // 1-based, counter-clockwise seen from above
                int b = a + 1;
                int c = a + n + 2;
                int d = a + n + 1;
                if ((i + j) % 3 == 0) {
                    obj.append("f ").append(a).append(' ').append(b).append(' ').append(c).append('\n');
                    obj.append("f ").append(a).append(' ').append(c).append(' ').append(d).append('\n');
                } else {
                    obj.append("f ").append(a).append(' ').append(b).append(' ').append(c).append(' ').append(d)
                            .append('\n');
                }
            }
        }
        return obj.toString().getBytes(StandardCharsets.US_ASCII);
    }

    /** One drawing: the page's pixels, its depths' bits, and how many edges were left out as drawn before. */
    private record Drawing(int[] pixels, long[] depths, long leftOut) {
    }

    /**
     * The model drawn as wire with {@code threads} (more than one: recorded and drawn in bands);
     * {@code edgesRead}: its faces tell which earlier face shares each edge.
     */
    private static Drawing draw(ObjModel model, boolean edgesRead, DrawingThreads threads) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        canvas.drawWith(threads);
        canvas.clear();
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -1, -300), Matrix4.identity());
        FragmentStages stages = FragmentStages.keptBy(threads, canvas.zbuffer());
        LitGeometry geometry = new LitGeometry(state, stages.next(canvas.litPanel()));
        LitPrimitives record = threads.isOne() ? null : new LitPrimitives(threads, canvas.zbuffer(),
                canvas.owedPanelRows(), canvas.litPanel(), null, canvas.waitingPixels(), stages);
        geometry.recordTo(record);
        geometry.beginObj(Matrix4.rotation(Axis.Y, 7), true, FILE);
        model.replay(new ObjSink() {
            @Override
            public void face(ObjFace face) {
                geometry.face(face);
            }

            @Override
            public boolean readsEdges() {
                return edgesRead && geometry.readsEdges();
            }
        });
        if (record != null) {
            record.flush();
        }
        stages.keep();
        return new Drawing(Images.rgb(canvas.image()), DepthBits.of(canvas.zbuffer()), geometry.edgesLeftOut());
    }

    @Test
    void edgesSharedByFacesWholeInViewAreDrawnOnceToTheSamePicture() throws Exception {
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (int n : new int[] {12, 80, 240}) {
                    String what = n + "x" + n + " on " + threads + " thread(s)";
                    ObjModel model = ObjModel.of(FILE, terrain(n, 48 + n));
                    Drawing every = draw(model, false, drawing);
                    Drawing once = draw(model, true, drawing);
                    assertEquals(0, every.leftOut(), "every edge drawn");
                    assertTrue(once.leftOut() > n * n / 2, what + ": shared edges left out: " + once.leftOut());
                    assertArrayEquals(every.pixels(), once.pixels(), what + ": the picture");
                    assertArrayEquals(every.depths(), once.depths(), what + ": the depths, to the bit");
                }
            }
        }
    }
}
