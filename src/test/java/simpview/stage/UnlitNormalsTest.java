package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
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
 * A filled polygon's normals are made only when something reads them
 * (LitGeometry's normalsRead): under the ambient term alone none are, in
 * flat, gouraud and phong shading, on one thread and recorded in bands on
 * two, and a phong polygon is recorded with z and kd only. The proof that
 * leaving them out draws the same: the pixels and depths are to the bit
 * those drawn while a trace follows (which reads every normal, and keeps P
 * and N in the record); and a model drawn with its own normals and drawn
 * with other ones (some zero, one long, the others turned anywhere) gives
 * the same picture under the ambient term alone, and another under a light,
 * where every drawn face has its normals made. The model is a rough terrain of quads and
 * triangles from a fixed seed, from behind the eye past the sides of the view
 * to far away, every other face with normals of its own, the rest lit with
 * their face normals.
 */
class UnlitNormalsTest {

    private static final Path FILE = Path.of("terrain.obj");
    private static final int CELLS = 40;

    /** The terrain, its own normals from {@code normalSeed}: every other cell's corners name one. */
    private static byte[] terrain(long normalSeed) {
        Random heights = new Random(49);
        Random normals = new Random(normalSeed);
        StringBuilder obj = new StringBuilder();
        int n = CELLS;
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                double x = -90 + 180.0 * j / n;
                double z = 5 - 400.0 * i / n;
                double y = -12 + 6 * heights.nextDouble();
                obj.append("v ").append(x).append(' ').append(y).append(' ').append(z).append('\n');
            }
        }
        int normalCount = 16;
        for (int k = 0; k < normalCount; k++) {
            double scale = k == 0 ? 0 : k == 1 ? 1e6 : 0.01 + normals.nextDouble();
            obj.append("vn ").append(scale * normals.nextGaussian()).append(' ')
                    .append(scale * normals.nextGaussian()).append(' ').append(scale * normals.nextGaussian())
                    .append('\n');
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int a = i * (n + 1) + j + 1; // 1-based, counter-clockwise seen from above
                int[] corners = {a, a + 1, a + n + 2, a + n + 1};
                boolean own = (i + j) % 2 == 0;
                if ((i + j) % 3 == 0) {
                    face(obj, own, normalCount, corners[0], corners[1], corners[2]);
                    face(obj, own, normalCount, corners[0], corners[2], corners[3]);
                } else {
                    face(obj, own, normalCount, corners);
                }
            }
        }
        return obj.toString().getBytes(StandardCharsets.US_ASCII);
    }

    private static void face(StringBuilder obj, boolean ownNormals, int normalCount, int... corners) {
        obj.append('f');
        for (int c : corners) {
            obj.append(' ').append(c);
            if (ownNormals) {
                obj.append("//").append(1 + c % normalCount);
            }
        }
        obj.append('\n');
    }

    /** One drawing: the page's pixels, its depths' bits, and how many faces had their normals made. */
    private record Drawing(int[] pixels, long[] depths, long facesWithNormals) {
    }

    /**
     * The model filled, shaded so, under ambient light and {@code lit}: one light too; {@code traced}: with a
     * trace following that reads every primitive and draws it.
     */
    private static Drawing draw(ObjModel model, LitState.ShadingMode shading, boolean lit, boolean traced,
            DrawingThreads threads) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        canvas.drawWith(threads);
        canvas.clear();
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -1, -300), Matrix4.identity());
        state.setAmbient(0.3, 0.5, 0.7);
        state.setSurface(0.9, 0.6, 0.4, 0.5, 8);
        state.setShading(shading);
        if (lit) {
            state.addLight(10, 40, -60, 1, 1, 0.8, 1, 0);
        }
        FragmentStages stages = FragmentStages.keptBy(threads, canvas.zbuffer());
        LitGeometry geometry = new LitGeometry(state, stages.next(canvas.litPanel()));
        LitPrimitives record = threads.isOne() ? null : new LitPrimitives(threads, canvas.zbuffer(),
                canvas.owedPanelRows(), canvas.litPanel(), null, canvas.waitingPixels(), stages);
        geometry.recordTo(record);
        if (traced) {
            geometry.follow(new PrimitiveTrace() {
                @Override
                public void read(int index, Path file, int line, int kind, double[] p, int at, int stride,
                        int vertices) {
                }

                @Override
                public boolean drawing(int index) {
                    return true;
                }
            });
        }
        geometry.beginObj(Matrix4.rotation(Axis.Y, 7), false, FILE);
        model.replay(new ObjSink() {
            @Override
            public void face(ObjFace face) {
                geometry.face(face);
            }
        });
        if (record != null) {
            record.flush();
        }
        stages.keep();
        return new Drawing(Images.rgb(canvas.image()), DepthBits.of(canvas.zbuffer()), geometry.facesWithNormals());
    }

    @Test
    void underTheAmbientTermAloneNoNormalIsMadeAndThePictureIsTheTracedOne() throws Exception {
        ObjModel own = ObjModel.of(FILE, terrain(1));
        ObjModel other = ObjModel.of(FILE, terrain(2));
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (LitState.ShadingMode shading : LitState.ShadingMode.values()) {
                    String what = shading + " on " + threads + " thread(s)";
                    Drawing first = draw(own, shading, false, false, drawing);
                    Drawing second = draw(other, shading, false, false, drawing);
                    Drawing traced = draw(own, shading, false, true, drawing);
                    assertEquals(0, first.facesWithNormals(), what + ": normals made");
                    assertEquals(0, second.facesWithNormals(), what + ": normals made");
                    assertTrue(traced.facesWithNormals() > CELLS * CELLS / 2, what + ": normals made, traced");
                    assertTrue(Arrays.stream(first.pixels()).distinct().count() > 2, what + ": something drawn");
                    assertArrayEquals(traced.pixels(), first.pixels(), what + ": the picture, as traced");
                    assertArrayEquals(traced.depths(), first.depths(), what + ": the depths, as traced");
                    assertArrayEquals(first.pixels(), second.pixels(), what + ": the picture");
                    assertArrayEquals(first.depths(), second.depths(), what + ": the depths, to the bit");
                }
            }
        }
    }

    @Test
    void underALightEveryDrawnFaceMakesItsNormalsAndTheyChangeThePicture() throws Exception {
        ObjModel own = ObjModel.of(FILE, terrain(1));
        ObjModel other = ObjModel.of(FILE, terrain(2));
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (LitState.ShadingMode shading : LitState.ShadingMode.values()) {
                    String what = shading + " on " + threads + " thread(s)";
                    Drawing first = draw(own, shading, true, false, drawing);
                    Drawing second = draw(other, shading, true, false, drawing);
                    assertTrue(first.facesWithNormals() > CELLS * CELLS / 2, what + ": normals made "
                            + first.facesWithNormals());
                    assertEquals(first.facesWithNormals(), second.facesWithNormals(), what + ": the same faces");
                    assertArrayEquals(first.depths(), second.depths(), what + ": the depths, to the bit");
                    assertFalse(Arrays.equals(first.pixels(), second.pixels()), what + ": the normals lit it");
                }
            }
        }
    }
}
