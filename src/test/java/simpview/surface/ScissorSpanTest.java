package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;

/**
 * {@link ScissorDrawable}'s span path passes on the run that a plain trim
 * finds, pixel by pixel from both ends with the depth range's test at each
 * (sharing no code with it), for spans whose depths cross the near plane,
 * the far plane, both or neither, in either direction, with zero, tiny,
 * huge, infinite and NaN slopes and depths, and spans reaching past both
 * sides: its search for the run's ends is held to the plain trim.
 */
class ScissorSpanTest {

    private static final int WIDTH = 97;
    private static final double NEAR = Camera.PARALLEL.hither();
    private static final double FAR = Camera.PARALLEL.yon();

    /** Every fillSpan it is given, as the run it was given. */
    private static final class Runs implements Drawable {
        final List<int[]> runs = new ArrayList<>();

        @Override
        public int width() {
            return WIDTH;
        }

        @Override
        public int height() {
            return 3;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            runs.add(new int[] {x, x + 1});
        }

        @Override
        public int getPixel(int x, int y) {
            return 0;
        }

        @Override
        public void fillSpan(Span s) {
            runs.add(new int[] {s.x0, s.x1});
        }
    }

    /** The plain trim: from each end, one pixel at a time, while its depth is outside [FAR, NEAR]. */
    private static List<int[]> plainTrim(Span s) {
        int from = Math.max(s.x0, 0);
        int to = Math.min(s.x1, WIDTH);
        while (from < to && !inRange(s.z + (from - s.xBase) * s.dz)) {
            from++;
        }
        while (to > from && !inRange(s.z + (to - 1 - s.xBase) * s.dz)) {
            to--;
        }
        List<int[]> runs = new ArrayList<>();
        if (from < to) {
            runs.add(new int[] {from, to});
        }
        return runs;
    }

    private static boolean inRange(double z) {
        return z <= NEAR && z >= FAR;
    }

    private static void check(Span s) {
        int x0 = s.x0;
        int x1 = s.x1;
        List<int[]> expected = plainTrim(s);
        Runs out = new Runs();
        new ScissorDrawable(Camera.PARALLEL, out).fillSpan(s);
        String what = "z " + s.z + " dz " + s.dz + " xBase " + s.xBase + " [" + x0 + ", " + x1 + ")";
        assertEquals(expected.size(), out.runs.size(), what);
        for (int i = 0; i < expected.size(); i++) {
            assertEquals(expected.get(i)[0], out.runs.get(i)[0], "start, " + what);
            assertEquals(expected.get(i)[1], out.runs.get(i)[1], "end, " + what);
        }
        assertEquals(x0, s.x0, "x0 put back");
        assertEquals(x1, s.x1, "x1 put back");
    }

    private static Span span(int x0, int x1, int xBase, double z, double dz) {
        Span s = new Span();
        s.y = 1;
        s.x0 = x0;
        s.x1 = x1;
        s.xBase = xBase;
        s.z = z;
        s.dz = dz;
        return s;
    }

    @Property(tries = 3000, seed = "1204013")
    void theRunIsThePlainTrims(@ForAll @IntRange(min = -30, max = WIDTH + 30) int a,
            @ForAll @IntRange(min = -30, max = WIDTH + 30) int b, @ForAll @IntRange(min = -60, max = 160) int xBase,
            @ForAll("depths") double z, @ForAll("slopes") double dz) {
        check(span(Math.min(a, b), Math.max(a, b), xBase, z, dz));
    }

    @Provide
    Arbitrary<Double> depths() {
        return Arbitraries.oneOf(Arbitraries.doubles().between(-420, 220),
                Arbitraries.of(NEAR, FAR, -0.0, Math.nextUp(NEAR), Math.nextDown(FAR), Math.nextUp(FAR), 1e300,
                        -1e300, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN));
    }

    @Provide
    Arbitrary<Double> slopes() {
        return Arbitraries.oneOf(Arbitraries.doubles().between(-12, 12), Arbitraries.doubles().between(-0.5, 0.5),
                Arbitraries.of(0.0, -0.0, Double.MIN_VALUE, -Double.MIN_VALUE, 1e-300, 1e290, -1e290, 1e308,
                        Double.MAX_VALUE, -Double.MAX_VALUE, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                        Double.NaN));
    }

    /** Spans that cross a plane exactly at a pixel, one step after another, from both sides. */
    @Test
    void runsThatStartAndEndOnAPlaneAreThePlainTrims() {
        for (int at = -3; at <= WIDTH + 3; at++) {
            for (double dz : new double[] {1, -1, 0.25, -0.25, 7, -7, 200, -200, 1e-9, -1e-9}) {
                for (double plane : new double[] {NEAR, FAR}) {
                    // z reaches the plane exactly at pixel `at`: z(at) = plane.
                    check(span(-5, WIDTH + 5, at, plane, dz));
                    check(span(0, WIDTH, at, Math.nextUp(plane), dz));
                    check(span(3, WIDTH - 2, at, Math.nextDown(plane), dz));
                    check(span(at - 1, at + 2, at, plane, dz));
                }
            }
        }
    }
}
