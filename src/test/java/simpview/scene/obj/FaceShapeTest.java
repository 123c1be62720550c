package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The test of a face with no area against the cross product worked out in exact decimals here, on points
 * where doubles alone cannot tell: on one line or nearly, on grids of integers and of binary fractions, huge
 * and tiny.
 */
class FaceShapeTest {

    private static final int[] TRIANGLE = {0, 1, 2};

    /** (b - a) x (c - a) is zero, in exact decimals; p holds a, b and c. */
    private static boolean exactlyInLine(double[] p) {
        BigDecimal[] u = new BigDecimal[3];
        BigDecimal[] v = new BigDecimal[3];
        for (int i = 0; i < 3; i++) {
            u[i] = new BigDecimal(p[3 + i]).subtract(new BigDecimal(p[i]));
            v[i] = new BigDecimal(p[6 + i]).subtract(new BigDecimal(p[i]));
        }
        return u[1].multiply(v[2]).compareTo(u[2].multiply(v[1])) == 0
                && u[2].multiply(v[0]).compareTo(u[0].multiply(v[2])) == 0
                && u[0].multiply(v[1]).compareTo(u[1].multiply(v[0])) == 0;
    }

    /** A coordinate of one of the kinds of model the reader meets. */
    private static double coordinate(Random random, int kind) {
        return switch (kind) {
            case 0 -> random.nextInt(2001) - 1000; // small integers
            case 1 -> (double) (random.nextLong() >> 12); // integers up to 2^51
            // binary fractions
            case 2 -> Math.scalb((double) (random.nextInt(1 << 20) - (1 << 19)), -random.nextInt(40));
            case 3 -> (random.nextInt(20001) - 10000) / 1000.0; // decimals, as most .obj files hold
            case 4 -> Math.scalb(random.nextDouble() - 0.5, random.nextInt(2000) - 1000); // any size
            // huge and tiny
            default -> Math.scalb((double) (random.nextInt(1 << 10) - (1 << 9)), 900 - random.nextInt(1900));
        };
    }

    @Test
    void noAreaIsTheExactCrossProductOnEveryKindOfCoordinate() {
        Random random = new Random(20261207);
        int inLine = 0;
        for (int trial = 0; trial < 60_000; trial++) {
            int kind = trial % 6;
            double[] p = new double[9];
            for (int i = 0; i < 6; i++) {
                p[i] = coordinate(random, kind);
            }
            // The third point: anywhere, or on the line through the first two (t (b - a) + a, rounded), or that
            // point moved by one unit in the last place along one axis.
            int how = random.nextInt(3);
            double t = random.nextBoolean() ? random.nextInt(7) - 3 : random.nextInt(9) / 4.0 - 1;
            for (int i = 0; i < 3; i++) {
                p[6 + i] = how == 0 ? coordinate(random, kind) : p[i] + t * (p[3 + i] - p[i]);
            }
            if (how == 2) {
                int axis = random.nextInt(3);
                p[6 + axis] = Math.nextUp(p[6 + axis]);
            }
            boolean finite = true;
            for (int i = 3; i < 9; i++) {
                finite &= Double.isFinite(p[i] - p[i % 3]);
            }
            if (!finite) {
                continue;
            }
            boolean expected = exactlyInLine(p);
            inLine += expected ? 1 : 0;
            assertEquals(expected, FaceShape.noArea(p, TRIANGLE, 3), () -> Arrays.toString(p));
        }
        assertTrue(inLine > 10_000, "points on one line tried: " + inLine);
    }

    @Test
    void aDifferenceOrProductIsCalledExactOnlyWhenItIs() {
        Random random = new Random(1207);
        for (int trial = 0; trial < 60_000; trial++) {
            int kind = trial % 6;
            double x = coordinate(random, kind);
            double y = trial % 2 == 0 ? coordinate(random, kind) : coordinate(random, (kind + 1) % 6);
            double d = x - y;
            if (Double.isFinite(d)) {
                boolean exact = new BigDecimal(x).subtract(new BigDecimal(y)).compareTo(new BigDecimal(d)) == 0;
                assertEquals(exact, FaceShape.exactDifference(x, y, d), x + " - " + y);
            }
            double product = x * y;
            if (FaceShape.exactProduct(x, y)) {
                assertEquals(0, new BigDecimal(x).multiply(new BigDecimal(y)).compareTo(new BigDecimal(product)),
                        x + " * " + y);
            }
        }
        // At the edges: a product that underflows, and one that rounds.
        assertFalse(FaceShape.exactProduct(0x1p-600, 0x1p-500));
        assertFalse(FaceShape.exactProduct(1 + 0x1p-52, 1 + 0x1p-52));
        assertTrue(FaceShape.exactProduct(1e-300, 0));
        assertTrue(FaceShape.exactProduct(3, 1 + 0x1p-50));
        assertFalse(FaceShape.exactProduct(3, 1 + 0x1p-52));
    }
}
