package simpview.stage;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Random;
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
 * A kept .obj model drawn alone on a page through the geometry stage, as an
 * {@code obj} command draws it: at once on one thread, recorded and drawn
 * in bands on more (LitPrimitives); and the rough terrain the stage's tests
 * draw, from a fixed seed.
 */
final class ModelPage {

    /** The name the models are read under. */
    static final Path FILE = Path.of("terrain.obj");

    private ModelPage() {
    }

    /** One drawing: the page's pixels, its depths' bits, and the geometry stage that drew it (for its counts). */
    record Drawing(int[] pixels, long[] depths, LitGeometry geometry) {
    }

    /**
     * The terrain: a grid of n x n cells, each a quad or, every third cell,
     * two triangles, counter-clockwise seen from above, from behind the eye
     * (seen from {@link #state}'s camera: faces clipped by the near plane) past
     * the sides of the view to far away (edges shorter than a pixel). Its
     * heights are drawn from {@code seed}.
     */
    static byte[] terrain(int n, long seed) {
        return terrain(n, seed, null);
    }

    /**
     * The terrain with normals of its own at every other cell's corners: 16
     * {@code vn} lines drawn from {@code normals} (one zero, one a million
     * long, the others between 0.01 and 1.01 long), each corner naming one by
     * its vertex number.
     */
    static byte[] terrain(int n, long seed, Random normals) {
        Random heights = new Random(seed);
        StringBuilder obj = new StringBuilder();
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                double x = -90 + 180.0 * j / n;
                double z = 5 - 400.0 * i / n;
                double y = -12 + 6 * heights.nextDouble();
                obj.append("v ").append(x).append(' ').append(y).append(' ').append(z).append('\n');
            }
        }
        int normalCount = normals == null ? 0 : 16;
        for (int k = 0; k < normalCount; k++) {
            double length = k == 0 ? 0 : k == 1 ? 1e6 : 0.01 + normals.nextDouble();
            obj.append("vn ").append(length * normals.nextGaussian()).append(' ')
                    .append(length * normals.nextGaussian()).append(' ').append(length * normals.nextGaussian())
                    .append('\n');
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int a = i * (n + 1) + j + 1; // 1-based
                int b = a + 1;
                int c = a + n + 2;
                int d = a + n + 1;
                int named = (i + j) % 2 == 0 ? normalCount : 0;
                if ((i + j) % 3 == 0) {
                    face(obj, named, a, b, c);
                    face(obj, named, a, c, d);
                } else {
                    face(obj, named, a, b, c, d);
                }
            }
        }
        return obj.toString().getBytes(StandardCharsets.US_ASCII);
    }

    /** A face line; with {@code normalCount} normals, each corner names one (none when 0). */
    private static void face(StringBuilder obj, int normalCount, int... corners) {
        obj.append('f');
        for (int c : corners) {
            obj.append(' ').append(c);
            if (normalCount > 0) {
                obj.append("//").append(1 + c % normalCount);
            }
        }
        obj.append('\n');
    }

    /** A lit scene's state with {@link #draw}'s camera: a perspective one at the origin, looking down -z. */
    static LitState state() {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -1, -300), Matrix4.identity());
        return state;
    }

    /**
     * The model drawn as {@code state} stands (made by {@link #state}), with
     * {@code threads}, turned a little about y; {@code wire} as outlines,
     * {@code edgesRead}: its faces telling which earlier face shares each
     * edge; {@code trace} following, when not null.
     */
    static Drawing draw(ObjModel model, LitState state, boolean wire, boolean edgesRead, PrimitiveTrace trace,
            DrawingThreads threads) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        canvas.drawWith(threads);
        canvas.clear();
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        FragmentStages stages = FragmentStages.keptBy(threads, canvas.zbuffer());
        LitGeometry geometry = new LitGeometry(state, stages.next(canvas.litPanel()));
        LitPrimitives record = threads.isOne() ? null : new LitPrimitives(threads, canvas.zbuffer(),
                canvas.owedPanelRows(), canvas.litPanel(), null, canvas.waitingPixels(), stages);
        geometry.recordTo(record);
        geometry.follow(trace);
        geometry.beginObj(Matrix4.rotation(Axis.Y, 7), wire, FILE);
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
        return new Drawing(Images.rgb(canvas.image()), DepthBits.of(canvas.zbuffer()), geometry);
    }
}
