package simpview.raster;

/**
 * The arc cosine, as fast as a few multiplications: {@code Math.acos} goes
 * through a native call costing about as much as the rest of an antialiased
 * pixel ten times over. The angle is read from a table of 128ths and corrected
 * by the small angle between: with {@code cos theta0}, {@code sin theta0} and
 * {@code theta0} from the table, {@code sin(theta - theta0) = sin theta cos
 * theta0 - cos theta sin theta0 = u}, and {@code theta = theta0 + asin u},
 * {@code asin u = u + u^3/6 + 3u^5/40 + ...}. The table's point is the nearest
 * 128th of cos theta where {@code |cos theta| <= sin theta}, else the nearest of sin
 * theta, so {@code |theta - theta0| <= sqrt(2)/256} and the series' next term is below
 * 1e-17: within a few units in the last place of {@code Math.acos}
 * ({@code ArcCosineTest} measures it).
 */
final class ArcCosine {

    private static final int STEPS = 128;
    /** The largest index: 128 / sqrt 2 rounded up. */
    private static final int LAST = 91;
    /** By the nearest 128th of the cosine, from -LAST to LAST (at [j + LAST]): cos, sin, angle. */
    private static final double[] BY_COS_COS = new double[2 * LAST + 1];
    private static final double[] BY_COS_SIN = new double[2 * LAST + 1];
    private static final double[] BY_COS_ANGLE = new double[2 * LAST + 1];
    /** By the nearest 128th of the sine, 0 to LAST, the angle in [0, pi/2]: cos, sin, angle. */
    private static final double[] BY_SIN_COS = new double[LAST + 1];
    private static final double[] BY_SIN_SIN = new double[LAST + 1];
    private static final double[] BY_SIN_ANGLE = new double[LAST + 1];

    static {
        for (int j = -LAST; j <= LAST; j++) {
            double c = (double) j / STEPS;
            BY_COS_COS[j + LAST] = c;
            BY_COS_SIN[j + LAST] = Math.sqrt((1 - c) * (1 + c));
            BY_COS_ANGLE[j + LAST] = Math.acos(c);
        }
        for (int j = 0; j <= LAST; j++) {
            double s = (double) j / STEPS;
            BY_SIN_SIN[j] = s;
            BY_SIN_COS[j] = Math.sqrt((1 - s) * (1 + s));
            BY_SIN_ANGLE[j] = Math.asin(s);
        }
    }

    private ArcCosine() {
    }

    /** sqrt(1 - x^2) for x in [-1, 1], without the cancellation of 1 - x * x near the ends. */
    static double sine(double x) {
        return Math.sqrt((1 - x) * (1 + x));
    }

    /** The angle in [0, pi] whose cosine is x and sine s (s = {@link #sine}(x); x in [-1, 1]). */
    static double of(double x, double s) {
        double c0;
        double s0;
        double angle0;
        if (Math.abs(x) <= s) {
            int j = (int) Math.rint(x * STEPS) + LAST;
            c0 = BY_COS_COS[j];
            s0 = BY_COS_SIN[j];
            angle0 = BY_COS_ANGLE[j];
        } else {
            int j = (int) Math.rint(s * STEPS);
            s0 = BY_SIN_SIN[j];
            if (x > 0) {
                c0 = BY_SIN_COS[j];
                angle0 = BY_SIN_ANGLE[j];
            } else {
                c0 = -BY_SIN_COS[j];
                angle0 = Math.PI - BY_SIN_ANGLE[j];
            }
        }
        double u = s * c0 - x * s0;
        double u2 = u * u;
        return angle0 + u * (1 + u2 * (1.0 / 6 + u2 * (3.0 / 40)));
    }

    /** acos(x) for x in [-1, 1]. */
    static double of(double x) {
        return of(x, sine(x));
    }
}
