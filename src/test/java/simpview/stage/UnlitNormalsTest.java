package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjModel;
import simpview.shading.LitState;
import simpview.surface.DrawingThreads;

/**
 * A filled polygon's normals are made only when something reads them
 * (LitGeometry's normalsRead): under the ambient term alone none are, in
 * flat, gouraud and phong shading, on one thread and recorded in bands on
 * two, and a phong polygon is recorded with z and kd only. The proof that
 * leaving them out draws the same: the pixels and depths are to the bit
 * those drawn while a trace follows (which reads every normal, and keeps P
 * and N in the record); and a model drawn with its own normals and drawn
 * with other ones gives the same picture under the ambient term alone, and
 * another under a light, where every drawn face has its normals made. The
 * model is {@link ModelPage}'s rough terrain, from behind the eye past the
 * sides of the view to far away, every other face with normals of its own
 * (one of them zero, one long, the others turned anywhere), the rest lit with
 * their face normals.
 */
class UnlitNormalsTest {

    private static final int CELLS = 40;

    /** A trace that reads every primitive, and draws it. */
    private static final PrimitiveTrace EVERY_PRIMITIVE = new PrimitiveTrace() {
        @Override
        public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
        }

        @Override
        public boolean drawing(int index) {
            return true;
        }
    };

    /** The terrain, its own normals drawn from {@code normalSeed}. */
    private static ObjModel terrain(long normalSeed) throws SceneException {
        return ObjModel.of(ModelPage.FILE, ModelPage.terrain(CELLS, 49, new Random(normalSeed)));
    }

    /**
     * The model filled, shaded so, under ambient light and {@code lit}: one light too; {@code traced}: with a
     * trace following that reads every primitive and draws it.
     */
    private static ModelPage.Drawing draw(ObjModel model, LitState.ShadingMode shading, boolean lit,
            boolean traced, DrawingThreads threads) throws SceneException {
        LitState state = ModelPage.state();
        state.setAmbient(0.3, 0.5, 0.7);
        state.setSurface(0.9, 0.6, 0.4, 0.5, 8);
        state.setShading(shading);
        if (lit) {
            state.addLight(10, 40, -60, 1, 1, 0.8, 1, 0);
        }
        return ModelPage.draw(model, state, false, false, traced ? EVERY_PRIMITIVE : null, threads);
    }

    private static long normalsMade(ModelPage.Drawing d) {
        return d.geometry().facesWithNormals();
    }

    /** What is checked of one shading mode's drawings with some threads ({@code what} names them). */
    @FunctionalInterface
    private interface Check {
        void of(LitState.ShadingMode shading, DrawingThreads threads, String what) throws Exception;
    }

    /** The check in flat, gouraud and phong shading, on one thread and on two. */
    private static void everyWay(Check check) throws Exception {
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (LitState.ShadingMode shading : LitState.ShadingMode.values()) {
                    check.of(shading, drawing, shading + " on " + threads + " thread(s)");
                }
            }
        }
    }

    @Test
    void underTheAmbientTermAloneNoNormalIsMadeAndThePictureIsTheTracedOne() throws Exception {
        ObjModel own = terrain(1);
        ObjModel other = terrain(2);
        everyWay((shading, drawing, what) -> {
            ModelPage.Drawing first = draw(own, shading, false, false, drawing);
            ModelPage.Drawing second = draw(other, shading, false, false, drawing);
            ModelPage.Drawing traced = draw(own, shading, false, true, drawing);
            assertEquals(0, normalsMade(first), what + ": normals made");
            assertEquals(0, normalsMade(second), what + ": normals made");
            assertTrue(normalsMade(traced) > CELLS * CELLS / 2, what + ": normals made, traced");
            assertTrue(Arrays.stream(first.pixels()).distinct().count() > 2, what + ": something drawn");
            assertArrayEquals(traced.pixels(), first.pixels(), what + ": the picture, as traced");
            assertArrayEquals(traced.depths(), first.depths(), what + ": the depths, as traced");
            assertArrayEquals(first.pixels(), second.pixels(), what + ": the picture");
            assertArrayEquals(first.depths(), second.depths(), what + ": the depths, to the bit");
        });
    }

    @Test
    void underALightEveryDrawnFaceMakesItsNormalsAndTheyChangeThePicture() throws Exception {
        ObjModel own = terrain(1);
        ObjModel other = terrain(2);
        everyWay((shading, drawing, what) -> {
            ModelPage.Drawing first = draw(own, shading, true, false, drawing);
            ModelPage.Drawing second = draw(other, shading, true, false, drawing);
            assertTrue(normalsMade(first) > CELLS * CELLS / 2, what + ": normals made " + normalsMade(first));
            assertEquals(normalsMade(first), normalsMade(second), what + ": the same faces");
            assertArrayEquals(first.depths(), second.depths(), what + ": the depths, to the bit");
            assertFalse(Arrays.equals(first.pixels(), second.pixels()), what + ": the normals lit it");
        });
    }
}
