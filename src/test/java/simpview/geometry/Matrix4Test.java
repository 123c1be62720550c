package simpview.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class Matrix4Test {

    private static void assertPoint(double x, double y, double z, Vertex v) {
        assertEquals(x, v.x(), 0, "x of " + v);
        assertEquals(y, v.y(), 0, "y of " + v);
        assertEquals(z, v.z(), 0, "z of " + v);
    }

    @Test
    void quarterTurnsAreExactAndRightHanded() {
        assertPoint(0, 1, 0, Matrix4.rotation(Axis.Z, 90).apply(Vertex.of(1, 0, 0)));
        assertPoint(0, 0, 1, Matrix4.rotation(Axis.X, 90).apply(Vertex.of(0, 1, 0)));
        assertPoint(1, 0, 0, Matrix4.rotation(Axis.Y, 90).apply(Vertex.of(0, 0, 1)));
        assertPoint(-1, 0, 0, Matrix4.rotation(Axis.Z, 180).apply(Vertex.of(1, 0, 0)));
        assertPoint(0, -1, 0, Matrix4.rotation(Axis.Z, -90).apply(Vertex.of(1, 0, 0)));
        assertPoint(0, -1, 0, Matrix4.rotation(Axis.Z, 630).apply(Vertex.of(1, 0, 0)));
    }

    @Test
    void otherAnglesFollowSineAndCosine() {
        Vertex v = Matrix4.rotation(Axis.Z, 30).apply(Vertex.of(2, 0, 0));
        assertEquals(Math.sqrt(3), v.x(), 1e-15);
        assertEquals(1, v.y(), 1e-15);
    }

    @Test
    void theLastTransformationNamedIsTheFirstApplied() {
        // CTM = T * S: a point is scaled first, then translated.
        Matrix4 ctm = Matrix4.identity().times(Matrix4.translation(10, 0, 0)).times(Matrix4.scaling(2, 3, 4));
        assertPoint(12, 3, 4, ctm.apply(Vertex.of(1, 1, 1)));
        Matrix4 other = Matrix4.identity().times(Matrix4.scaling(2, 3, 4)).times(Matrix4.translation(10, 0, 0));
        assertPoint(22, 3, 4, other.apply(Vertex.of(1, 1, 1)));
    }

    @Test
    void applyKeepsTheColour() {
        Vertex v = Matrix4.translation(1, 2, 3).apply(new Vertex(0, 0, 0, 0.1, 0.2, 0.3));
        assertEquals(new Vertex(1, 2, 3, 0.1, 0.2, 0.3), v);
    }

    @Test
    void worldMapsOntoThePanelAsSpecWritesIt() {
        assertEquals(0, Camera.PARALLEL.panelX(-100, -1));
        assertEquals(325, Camera.PARALLEL.panelY(0, -1));
        assertEquals(650, Camera.PARALLEL.panelX(100, -1));
        for (double x = -100; x <= 100; x += 0.37) {
            assertEquals((x + 100) * 650 / 200, Camera.PARALLEL.panelX(x, -5), "bit for bit as SPEC writes it");
        }
        assertEquals(0.25, Camera.PARALLEL.nearness(-150));
    }
}
