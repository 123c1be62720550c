package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;

/**
 * A surface changes the lighting only when its ks or p does: kd reaches each
 * point as a channel of its own, so objects of one ks and p keep one frozen
 * shader (one look), and the lighting, kd aside, lights every point alike.
 */
class LitStateTest {

    private static LitState lit() {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.addLight(3, 4, -2, 0.9, 0.8, 0.7, 1, 0);
        return state;
    }

    @Test
    void aSurfaceOfTheSameKsAndPKeepsTheLighting() {
        LitState state = lit();
        state.setSurface(0.2, 0.4, 0.6, 0.5, 16);
        int version = state.lightingVersion();
        Supplier<PointShader> frozen = state.frozenShader();
        state.setSurface(0.9, 0.1, 0.3, 0.5, 16);
        assertEquals(version, state.lightingVersion());
        assertSame(frozen, state.frozenShader());
        assertEquals(0.9, state.kdR());
    }

    @Test
    void aSurfaceOfAnotherKsOrPChangesIt() {
        LitState state = lit();
        state.setSurface(0.2, 0.4, 0.6, 0.5, 16);
        int version = state.lightingVersion();
        state.setSurface(0.2, 0.4, 0.6, 0.5, 17);
        assertNotEquals(version, state.lightingVersion(), "p");
        version = state.lightingVersion();
        state.setSurface(0.2, 0.4, 0.6, 0.25, 17);
        assertNotEquals(version, state.lightingVersion(), "ks");
        version = state.lightingVersion();
        state.setSurface(0.2, 0.4, 0.6, -0.0, 17);
        state.setSurface(0.2, 0.4, 0.6, 0.0, 17);
        assertEquals(version + 2, state.lightingVersion(), "-0 and +0 are two values of ks");
        double[] out = new double[3];
        double[] alone = new double[3];
        state.shade(1, 2, -5, 0, 0, 1, 0.5, 0.5, 0.5, out);
        Lighting lighting = new Lighting(state.lights());
        lighting.prepare(0, 0, 0, 0.0, 17, 1, true);
        lighting.shade(1, 2, -5, 0, 0, 1, 0.5, 0.5, 0.5, alone, 0);
        assertEquals(alone[0], out[0]);
        assertEquals(alone[1], out[1]);
        assertEquals(alone[2], out[2]);
    }
}
