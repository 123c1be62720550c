package simpview.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
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

    /**
     * An angle so large that angle + 90 == angle turns as its remainder mod
     * 360 does: its cosine was taken from angle + 90, the angle itself, and
     * came out 0 beside a sine of 0, a matrix that flattened everything.
     */
    @Test
    void aHugeAngleTurnsAsItsRemainderDoes() {
        for (double huge : new double[] {1e300, -1e300, 1e20, 0x1p52, 0x1p52 + 2, Double.MAX_VALUE, 1e300 + 1e285}) {
            for (Axis axis : Axis.values()) {
                assertSameBits(entries(Matrix4.rotation(axis, huge % 360)), Matrix4.rotation(axis, huge),
                        axis + " " + huge);
            }
        }
        assertPoint(1, 0, 0, Matrix4.rotation(Axis.Z, 1e300).apply(Vertex.of(1, 0, 0)));
    }

    /**
     * Every angle below 2^52 degrees rotates to the same bits as before huge
     * angles were reduced: the rotations of the course's scenes and goldens
     * are untouched. The reference is the former computation, kept here.
     */
    @Test
    void everyOtherAngleKeepsItsBits() {
        Random random = new Random(7);
        List<Double> angles = new ArrayList<>();
        for (int k = -4000; k <= 4000; k++) {
            angles.add(k * 0.25);
        }
        for (int k = 0; k < 20000; k++) {
            angles.add((random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(16)));
        }
        angles.addAll(List.of(1e15, -1e15 + 90, 0x1p52 - 1, -(0x1p52 - 0.5), 1e-300, -0.0));
        for (double angle : angles) {
            for (Axis axis : Axis.values()) {
                assertSameBits(formerRotation(axis, angle), Matrix4.rotation(axis, angle), axis + " " + angle);
            }
        }
    }

    private static void assertSameBits(double[] expected, Matrix4 actual, String what) {
        for (int row = 0; row < 4; row++) {
            for (int column = 0; column < 4; column++) {
                assertEquals(Double.doubleToRawLongBits(expected[4 * row + column]),
                        Double.doubleToRawLongBits(actual.get(row, column)), what + " at " + row + "," + column);
            }
        }
    }

    /** The entries of m, row by row. */
    private static double[] entries(Matrix4 m) {
        double[] r = new double[16];
        for (int k = 0; k < 16; k++) {
            r[k] = m.get(k / 4, k % 4);
        }
        return r;
    }

    /** Matrix4.rotation's entries, row by row, as it computed them before huge angles were reduced. */
    private static double[] formerRotation(Axis axis, double degrees) {
        double quarterCos = formerQuarterTurn(degrees + 90);
        double c = Double.isNaN(quarterCos) ? StrictMath.cos(StrictMath.toRadians(degrees)) : quarterCos;
        double quarterSin = formerQuarterTurn(degrees);
        double s = Double.isNaN(quarterSin) ? StrictMath.sin(StrictMath.toRadians(degrees)) : quarterSin;
        // the two axes the rotation turns, in the order that makes it right-handed
        int a = (axis.ordinal() + 1) % 3;
        int b = (axis.ordinal() + 2) % 3;
        double[] r = new double[16];
        r[0] = r[5] = r[10] = r[15] = 1;
        r[4 * a + a] = c;
        r[4 * a + b] = -s;
        r[4 * b + a] = s;
        r[4 * b + b] = c;
        return r;
    }

    private static double formerQuarterTurn(double degrees) {
        double d = degrees % 360;
        if (d < 0) {
            d += 360;
        }
        if (d == 0 || d == 180) {
            return 0;
        }
        if (d == 90) {
            return 1;
        }
        return d == 270 ? -1 : Double.NaN;
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
