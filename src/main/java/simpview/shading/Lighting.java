package simpview.shading;

/**
 * SPEC's lighting formula, once, for every shading mode:
 *
 * <pre>
 * I = kd * Ia + sum over lights i of (Ii * fi) * (kd * (N . Li) + ks * max(0, V . Ri)^p)
 *     Li = unit vector from P to light i,  V = unit vector from P to the eye,
 *     Ri = 2 (N . Li) N - Li,  fi = 1 / (Ai + Bi |light i - P|)
 * </pre>
 *
 * each channel then clamped to [0, 1]. Everything is in camera space, the eye
 * at the origin; a parallel view has V = (0, 0, 1) everywhere.
 *
 * <p>Use: one {@code Lighting} per drawing thread, on the scene's {@link Lights}.
 * Per primitive, {@link #prepare} sets what its command had in force (ambient
 * light, ks and p, how many lights, the view); then {@link #shade} per point
 * (each pixel in phong, each vertex in gouraud, the centroid in flat) writes
 * the clamped colour. Nothing is allocated after construction.
 *
 * <p>Edge cases, as SPEC has them: a light adds nothing where N . Li &lt;= 0,
 * and so nothing when it sits at the lit point itself; a zero normal gives the
 * ambient term only; max(0, V . R)^0 is 1. N may have any length (it is made
 * unit here), and so may P - light (lengths from 1e-300 to 1e300 work). No
 * channel is ever NaN, whatever the input: a product with no value
 * (infinity times 0, from huge intensities or a zero attenuation) adds 0, and
 * a channel that still comes out NaN (NaN or infinite input) is written as 0.
 * When V and Ri are both unit, V . Ri is at most 1; rounding can exceed that,
 * so it is taken as at most 1 (huge p never overflows).
 */
public final class Lighting {

    /** Squared lengths inside [LOW, HIGH] are used as they are; others are rescaled first. */
    static final double LOW = 1e-150;
    static final double HIGH = 1e150;
    /**
     * How far behind the surface {@link #unlitAt} wants each light: the
     * cosine of the angle between N and L below minus this. On a flat face
     * N . L has one sign all over; on a curved one it changes sign near where
     * the light grazes it, which the margin keeps out of the guess.
     */
    static final double PLAINLY_BEHIND = 0.1;
    /** Integer exponents up to this are raised by repeated squaring (within 2e-13 of Math.pow). */
    static final int MAX_SQUARING_EXPONENT = 1024;

    final Lights lights;
    private final BatchLighting batch = new BatchLighting(this);

    // What the primitive's command had in force, set by prepare (read by
    // BatchLighting too, which lights a batch of points with the same).
    double ambientRed;
    double ambientGreen;
    double ambientBlue;
    double ks;
    double p;
    int exponent;
    int lightCount;
    boolean perspective;

    // The point being shaded, set by aim: N and E (P to the eye) as given or
    // rescaled, their inverse lengths, and V . N.
    private double normalX;
    private double normalY;
    private double normalZ;
    private double inverseNormal;
    private double eyeX;
    private double eyeY;
    private double eyeZ;
    private double inverseEye;
    private double vn;

    public Lighting(Lights lights) {
        this.lights = lights;
        prepare(0, 0, 0, Material.START.ks(), Material.START.p(), 0, false);
    }

    /**
     * What a primitive is lit with: the ambient light Ia, the specular ks and
     * p of its surface, the first {@code lightCount} lights, and the view
     * (perspective: V points from P to the origin; parallel: V = (0, 0, 1)).
     *
     * @throws IllegalArgumentException if lightCount is negative or more than there are lights
     */
    public void prepare(double ambientRed, double ambientGreen, double ambientBlue, double ks, double p,
            int lightCount, boolean perspective) {
        if (lightCount < 0 || lightCount > lights.count()) {
            throw new IllegalArgumentException("light count " + lightCount + " of " + lights.count() + " lights");
        }
        this.ambientRed = ambientRed;
        this.ambientGreen = ambientGreen;
        this.ambientBlue = ambientBlue;
        this.ks = ks;
        this.p = p;
        this.exponent = p >= 0 && p <= MAX_SQUARING_EXPONENT && p == Math.rint(p) ? (int) p : -1;
        this.lightCount = lightCount;
        this.perspective = perspective;
    }

    /** {@link #prepare(double, double, double, double, double, int, boolean)} with the surface's ks and p. */
    public void prepare(double ambientRed, double ambientGreen, double ambientBlue, Material surface,
            int lightCount, boolean perspective) {
        prepare(ambientRed, ambientGreen, ambientBlue, surface.ks(), surface.p(), lightCount, perspective);
    }

    /**
     * The colour at camera-space point P with normal N (any length) and
     * diffuse colour kd, clamped to [0, 1]: red, green, blue into
     * out[at], out[at + 1], out[at + 2].
     */
    public void shade(double px, double py, double pz, double nx, double ny, double nz,
            double kdRed, double kdGreen, double kdBlue, double[] out, int at) {
        double r = kdRed * ambientRed;
        double g = kdGreen * ambientGreen;
        double b = kdBlue * ambientBlue;
        if (lightCount > 0 && aim(px, py, pz, nx, ny, nz)) {
            double[] data = lights.data();
            int end = lightCount * Lights.STRIDE;
            for (int o = 0; o < end; o += Lights.STRIDE) {
                double lx = data[o + Lights.X] - px;
                double ly = data[o + Lights.Y] - py;
                double lz = data[o + Lights.Z] - pz;
                double nl = normalX * lx + normalY * ly + normalZ * lz;
                if (!(nl > 0)) {
                    continue; // behind the surface, edge on, or at the lit point
                }
                double d2 = lx * lx + ly * ly + lz * lz;
                double scale = 1;
                if (!(d2 >= LOW && d2 <= HIGH)) {
                    scale = largest(lx, ly, lz);
                    if (!(scale <= Double.MAX_VALUE)) {
                        continue; // infinitely far
                    }
                    lx /= scale;
                    ly /= scale;
                    lz /= scale;
                    nl = normalX * lx + normalY * ly + normalZ * lz;
                    d2 = lx * lx + ly * ly + lz * lz;
                }
                double s = Math.sqrt(d2);
                double is = 1 / s;
                double cos = nl * (inverseNormal * is);
                double vl = (eyeX * lx + eyeY * ly + eyeZ * lz) * (inverseEye * is);
                double specular = ks * power(2 * cos * vn - vl);
                // With b = 0, 1 / (a + 0 d) is 1 / a, kept with the light: one division fewer.
                double lb = data[o + Lights.B];
                double f = lb == 0 ? data[o + Lights.INVERSE_A] : 1 / (data[o + Lights.A] + lb * (s * scale));
                r += contribution(data[o + Lights.RED] * f, kdRed * cos + specular);
                g += contribution(data[o + Lights.GREEN] * f, kdGreen * cos + specular);
                b += contribution(data[o + Lights.BLUE] * f, kdBlue * cos + specular);
            }
        }
        out[at] = clamp(r);
        out[at + 1] = clamp(g);
        out[at + 2] = clamp(b);
    }

    /**
     * Lights every point of the batch into its colour, each to the same bits
     * as {@link #shade(double, double, double, double, double, double, double,
     * double, double, double[], int)} gives it alone (see {@link BatchLighting}).
     */
    public void shade(LitPoints points) {
        batch.shade(points);
    }

    /**
     * A guess, for lighting points in batches: true when every light is
     * plainly behind the surface at point P with normal N (any length), so
     * that it reaches neither P nor, most likely, the points around it on one
     * face: N . L below -{@value #PLAINLY_BEHIND} |N| |L| (L = light - P, the
     * cosine of the angle between N and L below -{@value #PLAINLY_BEHIND}).
     * False with no light, and for any NaN on the way. Nothing drawn depends
     * on the answer ({@link LitPoints#unlit}).
     */
    public boolean unlitAt(double px, double py, double pz, double nx, double ny, double nz) {
        if (lightCount == 0) {
            return false;
        }
        double[] data = lights.data();
        double n2 = nx * nx + ny * ny + nz * nz;
        int end = lightCount * Lights.STRIDE;
        for (int o = 0; o < end; o += Lights.STRIDE) {
            double lx = data[o + Lights.X] - px;
            double ly = data[o + Lights.Y] - py;
            double lz = data[o + Lights.Z] - pz;
            double nl = nx * lx + ny * ly + nz * lz;
            // nl < -c |N| |L|, squared: no square root.
            if (!(nl < 0 && nl * nl > PLAINLY_BEHIND * PLAINLY_BEHIND * n2 * (lx * lx + ly * ly + lz * lz))) {
                return false;
            }
        }
        return true;
    }

    /**
     * False when a colour is the ambient term alone (no light is prepared):
     * then {@link #shade(LitPoints)} reads the points' kd only, not P or N.
     */
    /** How many lights a point adds up. */
    public int lightCount() {
        return lightCount;
    }

    public boolean usesPoint() {
        return lightCount > 0;
    }

    /**
     * Sets the point's normal and eye vectors (each rescaled when its length
     * is tiny or huge, with its inverse length) and V . N; false for a zero
     * or non-finite normal, which gets the ambient term only.
     */
    private boolean aim(double px, double py, double pz, double nx, double ny, double nz) {
        double n2 = nx * nx + ny * ny + nz * nz;
        if (!(n2 >= LOW && n2 <= HIGH)) {
            double m = largest(nx, ny, nz);
            if (!(m > 0 && m <= Double.MAX_VALUE)) {
                return false;
            }
            nx /= m;
            ny /= m;
            nz /= m;
            n2 = nx * nx + ny * ny + nz * nz;
        }
        // E points from P to the eye; V = E / |E|.
        double ex = perspective ? -px : 0;
        double ey = perspective ? -py : 0;
        double ez = perspective ? -pz : 1;
        double e2 = ex * ex + ey * ey + ez * ez;
        if (!(e2 >= LOW && e2 <= HIGH)) {
            // The eye at the lit point (or P not finite) gives V = 0.
            double m = largest(ex, ey, ez);
            boolean usable = m > 0 && m <= Double.MAX_VALUE;
            ex = usable ? ex / m : 0;
            ey = usable ? ey / m : 0;
            ez = usable ? ez / m : 0;
            e2 = usable ? ex * ex + ey * ey + ez * ez : 1;
        }
        // 1/|N| and 1/|E| from one division.
        double sn = Math.sqrt(n2);
        double se = Math.sqrt(e2);
        double q = 1 / (sn * se);
        normalX = nx;
        normalY = ny;
        normalZ = nz;
        inverseNormal = se * q;
        eyeX = ex;
        eyeY = ey;
        eyeZ = ez;
        inverseEye = sn * q;
        vn = (ex * nx + ey * ny + ez * nz) * q;
        return true;
    }

    /** max(0, x)^p, x taken as at most 1 (so 0^0 = 1, and NaN counts as 0). */
    private double power(double x) {
        double c = x > 0 ? (x < 1 ? x : 1) : 0;
        return exponent >= 0 ? bySquaring(c, exponent) : Math.pow(c, p);
    }

    /** x^e for e >= 0 by repeated squaring. */
    static double bySquaring(double x, int e) {
        double result = 1;
        double square = x;
        while (true) {
            if ((e & 1) != 0) {
                result *= square;
            }
            e >>>= 1;
            if (e == 0) {
                return result;
            }
            square *= square;
        }
    }

    /** (Ii fi) times its factor; a product with no value (infinity times 0) adds nothing. */
    static double contribution(double light, double factor) {
        double c = light * factor;
        return c == c ? c : 0;
    }

    private static double largest(double x, double y, double z) {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /** [0, 1]; NaN is 0. */
    static double clamp(double c) {
        return c > 0 ? (c < 1 ? c : 1) : 0;
    }
}
