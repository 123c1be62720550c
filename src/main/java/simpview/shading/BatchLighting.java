package simpview.shading;

/**
 * {@link Lighting#shade(LitPoints)}: a batch of points lit with what its
 * {@link Lighting} was prepared with, each point to the same bits as
 * {@link Lighting#shade(double, double, double, double, double, double,
 * double, double, double, double[], int)} gives it alone.
 *
 * <p>How: the formula is cut into steps, and each step runs over every point
 * of the batch in a loop of plain arithmetic on arrays, with no branch, which
 * C2 compiles to packed (SIMD) operations: four square roots or divisions
 * at once instead of one after another. Each point still gets exactly the
 * operations it gets alone, in the same order (Java never fuses or reorders
 * floating point, and a packed IEEE operation rounds each lane as the single
 * one does), so the bits cannot differ. The steps are written for the usual
 * point: lengths inside [{@link Lighting#LOW}, {@link Lighting#HIGH}]. A
 * point with a length outside that (N, E or some L, which Lighting rescales)
 * is lit again alone, by Lighting's own scalar code, so every edge case
 * keeps the one implementation it has.
 *
 * <p>Why the steps are small: C2 packs a loop only after unrolling it, and
 * unrolls it (on JDK 17) only while its body is under {@code
 * LoopUnrollLimit}, 60 nodes by default, where each array read or written
 * costs several. A loop over ten arrays stays one point at a time. So a
 * step reads and writes few arrays, even where that means storing a value
 * and reading it back in the next loop (a stored double is the same bits):
 * the light's L and N . L, and |L| and 1 / |L|, and V . L and its scale,
 * are each two loops. Split so, with two lights, a point measured 0.87 of
 * its time in one loop each (session 12), as fast as the loops in one
 * with the limit raised to 240.
 */
final class BatchLighting {

    /**
     * The length test without a branch. A point is lit alone (by Lighting)
     * when one of |N|^2, |E|^2 and its lights' |L|^2 is outside [LOW, HIGH],
     * as Lighting rescales it then. Instead of comparing each, the batch adds
     * up |N|, |E|, 1 / |N|, 1 / |E|, and each light's |L| and 1 / |L|, times
     * 2^777, and lights alone a point whose sum is infinite or NaN. A squared
     * length above HIGH = 1e150 has its root above 1e75 (less an ulp or two),
     * one below LOW its inverse root above 1e75, and 1e75 times 2^777 (7.9e233)
     * is beyond the largest double (1.8e308); every term is +0 or more (a sum
     * of squares is never -0), so one infinite term makes the sum infinite,
     * and every such point is lit alone. So may be one whose lengths are near
     * those bounds (within a factor of 4.4) or whose terms overflow together,
     * needlessly, and it gets the same bits all the same.
     */
    private static final double LENGTHS = 0x1p777;

    /**
     * max(x, 0), to the bit, for every x but -inf, with no Math.max, which C2
     * packs into several instructions (its rules for NaN and -0; the clamps
     * of a batch measured a third faster without, session 10): (x + |x|) / 2.
     * x + x and the halving are exact (an x above half the largest double
     * doubles to +inf, and min(+inf, 1) is min(x, 1)); a negative x and -0
     * give +0, as max does; NaN stays NaN. -inf gives NaN where max gives 0:
     * where that can happen, a NaN is clamped by Lighting's rule or its
     * point lit alone.
     */
    static double positive(double x) {
        return (x + Math.abs(x)) * 0.5;
    }

    private final Lighting lighting;

    BatchLighting(Lighting lighting) {
        this.lighting = lighting;
    }

    void shade(LitPoints t) {
        int n = t.count;
        Lighting l = lighting;
        double ar = l.ambientRed;
        double ag = l.ambientGreen;
        double ab = l.ambientBlue;
        double[] red = t.red;
        double[] green = t.green;
        double[] blue = t.blue;
        if (l.lightCount == 0) {
            // The ambient term alone, clamped (positive, then min); only a NaN,
            // which the clamp keeps (or makes, of -inf), is then clamped by
            // Lighting's rule.
            for (int i = 0; i < n; i++) {
                double r = t.kdRed[i] * ar;
                double g = t.kdGreen[i] * ag;
                double b = t.kdBlue[i] * ab;
                red[i] = Math.min(positive(r), 1);
                green[i] = Math.min(positive(g), 1);
                blue[i] = Math.min(positive(b), 1);
            }
            for (int i = 0; i < n; i++) {
                double sum = red[i] + green[i] + blue[i];
                if (sum != sum) {
                    red[i] = Lighting.clamp(t.kdRed[i] * ar);
                    green[i] = Lighting.clamp(t.kdGreen[i] * ag);
                    blue[i] = Lighting.clamp(t.kdBlue[i] * ab);
                }
            }
            return;
        }
        for (int i = 0; i < n; i++) {
            red[i] = t.kdRed[i] * ar;
            green[i] = t.kdGreen[i] * ag;
            blue[i] = t.kdBlue[i] * ab;
        }
        aim(t, n);
        int end = l.lightCount * Lights.STRIDE;
        for (int o = 0; o < end; o += Lights.STRIDE) {
            light(t, n, o);
        }
        // Clamped (positive, then min): as Lighting.clamp, but a NaN stays NaN, and -inf becomes NaN.
        for (int i = 0; i < n; i++) {
            double r = red[i];
            double g = green[i];
            double b = blue[i];
            red[i] = Math.min(positive(r), 1);
            green[i] = Math.min(positive(g), 1);
            blue[i] = Math.min(positive(b), 1);
        }
        for (int i = 0; i < n; i++) {
            // Lit alone: a point with a length Lighting rescales (N, E or some
            // L), or with a NaN sum (a term with no value, which Lighting adds
            // as 0, terms that cancelled, or a sum of -inf); what the steps
            // made of it is replaced.
            double sum = red[i] + green[i] + blue[i];
            if (!(t.lengths[i] < Double.POSITIVE_INFINITY) | sum != sum) {
                shadeAlone(t, i);
            }
        }
    }

    /** Point i lit by Lighting alone, its colour replacing what the steps made of it. */
    private void shadeAlone(LitPoints t, int i) {
        double[] out = t.aloneColour;
        lighting.shade(t.px[i], t.py[i], t.pz[i], t.nx[i], t.ny[i], t.nz[i], t.kdRed[i], t.kdGreen[i],
                t.kdBlue[i], out, 0);
        t.red[i] = out[0];
        t.green[i] = out[1];
        t.blue[i] = out[2];
    }

    /**
     * Lighting.aim for every point: E, then N and E's inverse lengths and
     * V . N; and the start of the point's length test (see {@link #LENGTHS}).
     */
    private void aim(LitPoints t, int n) {
        double[] ex = t.eyeX;
        double[] ey = t.eyeY;
        double[] ez = t.eyeZ;
        double[] sn = t.inverseNormal; // |N| until the last step
        double[] se = t.inverseEye; // |E| until the last step
        if (lighting.perspective) {
            for (int i = 0; i < n; i++) {
                double x = -t.px[i];
                double y = -t.py[i];
                double z = -t.pz[i];
                ex[i] = x;
                ey[i] = y;
                ez[i] = z;
                se[i] = Math.sqrt(x * x + y * y + z * z);
            }
        } else {
            for (int i = 0; i < n; i++) {
                ex[i] = 0;
                ey[i] = 0;
                ez[i] = 1;
                se[i] = 1; // the square root of 0 0 + 0 0 + 1 1
            }
        }
        for (int i = 0; i < n; i++) {
            sn[i] = Math.sqrt(t.nx[i] * t.nx[i] + t.ny[i] * t.ny[i] + t.nz[i] * t.nz[i]);
        }
        double[] q = t.vn;
        for (int i = 0; i < n; i++) {
            q[i] = 1 / (sn[i] * se[i]);
        }
        for (int i = 0; i < n; i++) {
            double normal = sn[i];
            double eye = se[i];
            double inverseNormal = eye * q[i];
            double inverseEye = normal * q[i];
            sn[i] = inverseNormal;
            se[i] = inverseEye;
            t.lengths[i] = (normal + eye + inverseNormal + inverseEye) * LENGTHS;
        }
        for (int i = 0; i < n; i++) {
            q[i] = (ex[i] * t.nx[i] + ey[i] * t.ny[i] + ez[i] * t.nz[i]) * q[i];
        }
    }

    /**
     * Adds the light at data[o] to every point: the body of Lighting.shade's
     * light loop, step by step; and |L| and 1 / |L| to the point's length test.
     */
    private void light(LitPoints t, int n, int o) {
        double[] data = lighting.lights.data();
        double[] lx = t.lightX;
        double[] ly = t.lightY;
        double[] lz = t.lightZ;
        double x = data[o + Lights.X];
        double y = data[o + Lights.Y];
        double z = data[o + Lights.Z];
        for (int i = 0; i < n; i++) {
            lx[i] = x - t.px[i];
            ly[i] = y - t.py[i];
            lz[i] = z - t.pz[i];
        }
        for (int i = 0; i < n; i++) {
            t.dot[i] = t.nx[i] * lx[i] + t.ny[i] * ly[i] + t.nz[i] * lz[i];
        }
        double[] s = t.distance;
        double[] is = t.inverseDistance;
        for (int i = 0; i < n; i++) {
            // Every |L| counts, also where the light does not reach: a point
            // lit alone needlessly gets the same bits all the same.
            s[i] = Math.sqrt(lx[i] * lx[i] + ly[i] * ly[i] + lz[i] * lz[i]);
        }
        for (int i = 0; i < n; i++) {
            double d = s[i];
            double w = 1 / d;
            is[i] = w;
            t.lengths[i] += (d + w) * LENGTHS;
        }
        for (int i = 0; i < n; i++) {
            t.cosine[i] = t.dot[i] * (t.inverseNormal[i] * is[i]);
        }
        double[] h = t.highlight; // V . L, then max(0, V . R) at most 1
        for (int i = 0; i < n; i++) {
            h[i] = t.eyeX[i] * lx[i] + t.eyeY[i] * ly[i] + t.eyeZ[i] * lz[i];
        }
        for (int i = 0; i < n; i++) {
            h[i] = h[i] * (t.inverseEye[i] * is[i]);
        }
        for (int i = 0; i < n; i++) {
            // V . R = 2 cos (V . N) - V . L, then as Lighting.power takes it:
            // at least 0 (positive), at most 1 (see positive; a NaN stays
            // NaN, see raise).
            double r = 2 * t.cosine[i] * t.vn[i] - h[i];
            h[i] = Math.min(positive(r), 1);
        }
        double a = data[o + Lights.A];
        double b = data[o + Lights.B];
        if (b != 0) {
            // Lighting's s * scale is s here: the scale of a usual length is 1.
            for (int i = 0; i < n; i++) {
                t.attenuation[i] = 1 / (a + b * s[i]);
            }
        }
        add(t, n, o, raise(t, n));
    }

    /**
     * Lighting.power for every point's highlight (already max(0, V . R) at
     * most 1): the array that holds it. As Lighting.power, but a NaN stays
     * NaN: only a point lit alone, or one whose sum the NaN then makes NaN
     * (lit alone too), can have one.
     */
    private double[] raise(LitPoints t, int n) {
        double[] c = t.highlight; // then its squares
        double[] result = t.raised;
        int e = lighting.exponent;
        if (e < 0) {
            double p = lighting.p;
            for (int i = 0; i < n; i++) {
                result[i] = Math.pow(c[i], p);
            }
            return result;
        }
        if (e == 0) {
            for (int i = 0; i < n; i++) {
                result[i] = 1;
            }
            return result;
        }
        // Lighting.bySquaring, each step over every point. Its result starts
        // at 1, and 1 times the first square it takes is that square: so the
        // squares up to e's lowest bit, then that square is the result so far.
        int zeros = Integer.numberOfTrailingZeros(e);
        square(c, n, zeros);
        e >>>= zeros + 1;
        if (e == 0) {
            return c;
        }
        boolean first = true;
        while (e != 0) {
            // The squares up to the next bit of e, then the result times that square.
            int squares = Integer.numberOfTrailingZeros(e) + 1;
            e >>>= squares;
            if (first) {
                for (int i = 0; i < n; i++) {
                    double v = c[i];
                    result[i] = v;
                    c[i] = v * v;
                }
                squares--;
                first = false;
            }
            square(c, n, squares);
            for (int i = 0; i < n; i++) {
                result[i] *= c[i];
            }
        }
        return result;
    }

    /**
     * Each c squared {@code times} times in place, up to four squares in one
     * loop: the same products, one after another, as a loop per square.
     */
    private static void square(double[] c, int n, int times) {
        for (; times >= 4; times -= 4) {
            for (int i = 0; i < n; i++) {
                double v = c[i] * c[i];
                v *= v;
                v *= v;
                c[i] = v * v;
            }
        }
        if (times == 3) {
            for (int i = 0; i < n; i++) {
                double v = c[i] * c[i];
                v *= v;
                c[i] = v * v;
            }
        } else if (times == 2) {
            for (int i = 0; i < n; i++) {
                double v = c[i] * c[i];
                c[i] = v * v;
            }
        } else if (times == 1) {
            for (int i = 0; i < n; i++) {
                c[i] *= c[i];
            }
        }
    }

    /**
     * Each point's contribution, added where the light reaches it (N . L &gt;
     * 0) and times 0 elsewhere, with no branch, so that C2 packs it. Where
     * the light does not reach, a finite contribution times 0 adds a zero,
     * which leaves the sum as it was (but for the sign of a zero sum, which
     * the clamp makes +0 either way); an infinite or NaN one makes the sum
     * NaN, and the point is lit alone, as it is for a NaN where the light
     * reaches (Lighting.contribution's test for a product with no value).
     * Without either, the sums are Lighting's.
     */
    private void add(LitPoints t, int n, int o, double[] raised) {
        Lighting l = lighting;
        double[] data = l.lights.data();
        double red = data[o + Lights.RED];
        double green = data[o + Lights.GREEN];
        double blue = data[o + Lights.BLUE];
        double ks = l.ks;
        double[] reach = t.reach;
        double[] specular = t.specular;
        for (int i = 0; i < n; i++) {
            // 1 where N . L > 0 (the least positive double times 2^2000 is
            // above 1), 0 where not, NaN for a NaN N . L (see positive).
            double d = t.dot[i];
            reach[i] = Math.min(positive(d) * 0x1p1000 * 0x1p1000, 1);
            specular[i] = ks * raised[i];
        }
        if (data[o + Lights.B] == 0) {
            double inverseA = data[o + Lights.INVERSE_A];
            double rf = red * inverseA;
            double gf = green * inverseA;
            double bf = blue * inverseA;
            for (int i = 0; i < n; i++) {
                t.red[i] += rf * (t.kdRed[i] * t.cosine[i] + specular[i]) * reach[i];
            }
            for (int i = 0; i < n; i++) {
                t.green[i] += gf * (t.kdGreen[i] * t.cosine[i] + specular[i]) * reach[i];
            }
            for (int i = 0; i < n; i++) {
                t.blue[i] += bf * (t.kdBlue[i] * t.cosine[i] + specular[i]) * reach[i];
            }
        } else {
            double[] f = t.attenuation;
            for (int i = 0; i < n; i++) {
                t.red[i] += red * f[i] * (t.kdRed[i] * t.cosine[i] + specular[i]) * reach[i];
            }
            for (int i = 0; i < n; i++) {
                t.green[i] += green * f[i] * (t.kdGreen[i] * t.cosine[i] + specular[i]) * reach[i];
            }
            for (int i = 0; i < n; i++) {
                t.blue[i] += blue * f[i] * (t.kdBlue[i] * t.cosine[i] + specular[i]) * reach[i];
            }
        }
    }
}
