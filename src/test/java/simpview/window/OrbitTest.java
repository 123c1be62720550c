package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import simpview.geometry.Matrix4;

/** The orbit's turn in camera space: about its centre, nearer and farther along z, and nothing when unturned. */
public class OrbitTest {

    @Test
    void unturnedThereIsNoMatrixAtAll() {
        Orbit orbit = new Orbit();
        assertNull(orbit.matrix());
        orbit.drag(40, 10);
        orbit.wheel(-2);
        orbit.reset();
        assertFalse(orbit.turned());
        assertNull(orbit.matrix());
    }

    @Test
    void theCentreStaysWhereItIsAndOtherPointsTurnAboutIt() {
        Orbit orbit = new Orbit();
        orbit.about(new double[] {3, -2, -40});
        orbit.drag(180, 0); // 90 degrees about y
        Matrix4 m = orbit.matrix();
        assertPoint(m, 3, -2, -40, 3, -2, -40);
        // One unit along +x from the centre goes to one unit along -z (Ry(90) takes x to -z).
        assertPoint(m, 4, -2, -40, 3, -2, -41);
        orbit.about(new double[] {0, 0, 0});
        assertPoint(orbit.matrix(), 3, -2, -40, 3, -2, -40); // the centre is kept while turned
    }

    @Test
    void aDepthCuedSceneTurnsAboutTheViewVolumesCentre() {
        Orbit orbit = new Orbit();
        orbit.drag(0, 60); // 30 degrees about x
        assertPoint(orbit.matrix(), 0, 0, -100, 0, 0, -100);
        assertPoint(orbit.matrix(), 0, 0, 0, 0, -100 * Math.sin(Math.toRadians(30)), -100 + 100 * Math.cos(Math.toRadians(30)));
    }

    @Test
    void eachNotchNearerGoesATenthOfTheWayToTheEye() {
        Orbit orbit = new Orbit();
        orbit.about(new double[] {5, 0, -50});
        orbit.wheel(-1);
        assertTrue(orbit.turned());
        assertPoint(orbit.matrix(), 5, 0, -50, 5, 0, -45);
        orbit.wheel(-1);
        assertPoint(orbit.matrix(), 5, 0, -50, 5, 0, -40.5);
        orbit.wheel(3); // one notch farther than the start
        assertPoint(orbit.matrix(), 5, 0, -50, 5, 0, -50 / 0.9);
        assertEquals("turned 0° about y, 0° about x, 1 step farther (O resets)", orbit.describe());
        orbit.wheel(1000);
        assertPoint(orbit.matrix(), 5, 0, -50, 5, 0, -50 / Math.pow(0.9, Orbit.FARTHEST));
    }

    private static void assertPoint(Matrix4 m, double x, double y, double z, double ex, double ey, double ez) {
        assertEquals(ex, m.applyX(x, y, z), 1e-9, "x");
        assertEquals(ey, m.applyY(x, y, z), 1e-9, "y");
        assertEquals(ez, m.applyZ(x, y, z), 1e-9, "z");
    }
}
