package simpview.shading;

import java.util.Arrays;

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
 * <p>Why the steps are small: C2 (JDK 17) packs some loops and not others,
 * and not by how many arrays they touch alone. In a scratch program
 * (session 22) a loop of products and sums reading ten arrays and writing
 * one was packed (0.38 ns a point), while one with two square roots, a
 * division and four arrays written, over nine in all, was not (4.5 ns);
 * within this class, aim's four loops in two and three of a light's in one
 * were not either (7.0 and 5.5 ns a point for a whole light, against 4.0).
 * So a step reads and writes at most seven arrays, storing a value and
 * reading it back in the next step where it must (a stored double is the
 * same bits). Each loop costs a batch about 0.2 ns a point on the machine of
 * docs/performance-log.md whatever its arithmetic, so what a step can work out
 * again from the points is not stored: L = light - P is made in each of the
 * three steps that read it, E (-P or (0, 0, 1)) is never stored, and the
 * reach and ks times the power are made where the light is added, the
 * first light's sum starting from the ambient term there. With one
 * attenuated light and p = 8, these 16 loops take 4.3-4.4 ns a point where
 * 22 took 4.8-4.9, to the same bits (session 21; its three square roots and
 * three divisions alone take 1.5 ns). The whole light in one loop was
 * never packed (20 ns a point), and in three loops only in part, even with
 * the limit raised to 1,000 (11 ns).
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
        t.black = false;
        int n = t.count;
        Lighting l = lighting;
        if (l.lightCount == 0) {
            shadeAmbientAlone(t, n);
            return;
        }
        if (t.unlit) {
            shadeUnlit(t, n);
            return;
        }
        aim(t, n);
        int end = l.lightCount * Lights.STRIDE;
        for (int o = 0; o < end; o += Lights.STRIDE) {
            light(t, n, o, o == 0);
        }
        // Clamped (positive, then min): as Lighting.clamp, but a NaN stays NaN, and -inf becomes NaN.
        double[] red = t.red;
        double[] green = t.green;
        double[] blue = t.blue;
        for (int i = 0; i < n; i++) {
            double r = red[i];
            double g = green[i];
            double b = blue[i];
            red[i] = Math.min(positive(r), 1);
            green[i] = Math.min(positive(g), 1);
            blue[i] = Math.min(positive(b), 1);
        }
        // Lit alone: a point with a length Lighting rescales (N, E or some L),
        // or with a NaN sum (a term with no value, which Lighting adds as 0,
        // terms that cancelled, or a sum of -inf).
        shadeUnusualAlone(t, n);
    }

    /**
     * With no light: the ambient term alone, clamped; only a NaN, which the
     * clamp keeps (or makes, of -inf), is then clamped by Lighting's rule,
     * looked for where the batch's sum of colours is NaN (the colours are in
     * [0, 1] or NaN, so the sum cannot overflow).
     */
    private void shadeAmbientAlone(LitPoints t, int n) {
        ambientTerm(t, n);
        double[] red = t.red;
        double[] green = t.green;
        double[] blue = t.blue;
        double all = 0;
        for (int i = 0; i < n; i++) {
            all += red[i] + green[i] + blue[i];
        }
        if (all == all) {
            return;
        }
        Lighting l = lighting;
        for (int i = 0; i < n; i++) {
            double sum = red[i] + green[i] + blue[i];
            if (sum != sum) {
                red[i] = Lighting.clamp(t.kdRed[i] * l.ambientRed);
                green[i] = Lighting.clamp(t.kdGreen[i] * l.ambientGreen);
                blue[i] = Lighting.clamp(t.kdBlue[i] * l.ambientBlue);
            }
        }
    }

    /** Each point's kd times Ia, clamped (positive, then min): as Lighting.clamp, but a NaN stays NaN, and -inf becomes NaN. */
    private void ambientTerm(LitPoints t, int n) {
        Lighting l = lighting;
        double ar = l.ambientRed;
        double ag = l.ambientGreen;
        double ab = l.ambientBlue;
        double[] red = t.red;
        double[] green = t.green;
        double[] blue = t.blue;
        for (int i = 0; i < n; i++) {
            red[i] = Math.min(positive(t.kdRed[i] * ar), 1);
            green[i] = Math.min(positive(t.kdGreen[i] * ag), 1);
            blue[i] = Math.min(positive(t.kdBlue[i] * ab), 1);
        }
    }

    /**
     * Each point whose length test failed (t.lengths infinite or NaN) or
     * whose colour is NaN lit again by Lighting alone, replacing what the
     * steps made of it. First one sum over the batch, in a loop with no
     * branch: where it is finite, no point is such (each term is +0 or more,
     * or NaN), and the loop with its branch is not run (a sum that overflows
     * only runs it): A4 page-g 0.97 of its time, page-f1 0.99 (session 23).
     */
    private void shadeUnusualAlone(LitPoints t, int n) {
        double[] red = t.red;
        double[] green = t.green;
        double[] blue = t.blue;
        double[] lengths = t.lengths;
        if (finiteSum(lengths, red, green, blue, 1, n)) {
            return;
        }
        for (int i = 0; i < n; i++) {
            double sum = red[i] + green[i] + blue[i];
            if (!(lengths[i] < Double.POSITIVE_INFINITY) | sum != sum) {
                shadeAlone(t, i);
            }
        }
    }

    /**
     * A batch whose filler expects no light to reach it ({@link LitPoints#unlit}):
     * the ambient term, clamped, for each point no light reaches, in 3 + lights
     * loops instead of some 16 a light; every other point lit alone.
     *
     * <p>Why the bits are Lighting's. Where N's squared length is inside
     * [LOW, HIGH], Lighting takes N as it is, and a light adds nothing where
     * its N . L, made from that N as here (the same products, summed in the
     * same order), is not above 0; so where that holds for every light, the
     * colour is kd times Ia, clamped, made as {@link #shade} makes it with no
     * light. Any other point is lit alone, found by one sum per point, infinite
     * or NaN for it: (|N|^2 + 1 / |N|^2) times 2^526, infinite where |N|^2 is
     * outside [LOW, HIGH] (1e150 times 2^526 is beyond the largest double, and
     * so, needlessly, is anything above 8.2e149: within a factor of 1.3 of
     * HIGH, and of LOW the other way), NaN where it is NaN;
     * plus each light's max(0, N . L) times 2^3000, which is +0 where N . L is
     * not above 0, infinite where it is (the least positive double times 2^3000
     * is above 2^1900), NaN where it is NaN. A NaN colour (a NaN or -inf
     * kd Ia) is lit alone too, as in {@link #shade}.
     */
    private void shadeUnlit(LitPoints t, int n) {
        Lighting l = lighting;
        double[] px = t.px;
        double[] py = t.py;
        double[] pz = t.pz;
        double[] nx = t.nx;
        double[] ny = t.ny;
        double[] nz = t.nz;
        double[] lengths = t.lengths;
        for (int i = 0; i < n; i++) {
            double n2 = nx[i] * nx[i] + ny[i] * ny[i] + nz[i] * nz[i];
            lengths[i] = (n2 + 1 / n2) * 0x1p526;
        }
        double[] data = l.lights.data();
        int end = l.lightCount * Lights.STRIDE;
        for (int o = 0; o < end; o += Lights.STRIDE) {
            double x = data[o + Lights.X];
            double y = data[o + Lights.Y];
            double z = data[o + Lights.Z];
            for (int i = 0; i < n; i++) {
                double dot = nx[i] * (x - px[i]) + ny[i] * (y - py[i]) + nz[i] * (z - pz[i]);
                lengths[i] += positive(dot) * 0x1p1000 * 0x1p1000 * 0x1p1000;
            }
        }
        // Under an ambient light of zeros, where no point is lit alone and every
        // kd is finite (kd times 0 is then a zero), ambientTerm makes each
        // channel +0 (positive turns -0 into +0) and shadeUnusualAlone changes
        // nothing: three fills instead (LitPoints.black).
        if (l.ambientRed == 0 && l.ambientGreen == 0 && l.ambientBlue == 0
                && finiteSum(t.lengths, t.kdRed, t.kdGreen, t.kdBlue, 0, n)) {
            Arrays.fill(t.red, 0, n, 0.0);
            Arrays.fill(t.green, 0, n, 0.0);
            Arrays.fill(t.blue, 0, n, 0.0);
            t.black = true;
            return;
        }
        ambientTerm(t, n);
        shadeUnusualAlone(t, n);
    }

    /**
     * True when lengths[i] + (a[i] + b[i] + c[i]) times {@code scale}, summed
     * over the batch in a loop with no branch, is finite. Then every length
     * test passed (each term is +0 or more where it passed, infinite or NaN
     * where not); with scale 0, every a, b and c is finite (a NaN or an
     * infinity makes the product NaN); with scale 1 and colours (in [0, 1]
     * or NaN), none is NaN. A sum that overflows only says false, which a
     * caller takes as "look point by point".
     */
    private static boolean finiteSum(double[] lengths, double[] a, double[] b, double[] c, double scale, int n) {
        double sum = 0;
        for (int i = 0; i < n; i++) {
            sum += lengths[i] + (a[i] + b[i] + c[i]) * scale;
        }
        return sum < Double.POSITIVE_INFINITY;
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
     * Lighting.aim for every point: N's and E's inverse lengths and V . N;
     * and the start of the point's length test (see {@link #LENGTHS}). E is
     * not stored: it is -P under a perspective view, whose products and sums
     * are those of P with their signs turned (exactly; only a zero's sign may
     * differ, which max(0, V . R) does not see: see {@link #light}), and
     * (0, 0, 1) under a parallel one, each product kept as Lighting makes it.
     */
    private void aim(LitPoints t, int n) {
        double[] px = t.px;
        double[] py = t.py;
        double[] pz = t.pz;
        double[] nx = t.nx;
        double[] ny = t.ny;
        double[] nz = t.nz;
        double[] sn = t.inverseNormal; // |N| until the third step
        double[] se = t.inverseEye; // |E| until the third step
        double[] q = t.vn; // 1 / (|N| |E|) until the last step
        boolean perspective = lighting.perspective;
        if (perspective) {
            for (int i = 0; i < n; i++) {
                se[i] = Math.sqrt(px[i] * px[i] + py[i] * py[i] + pz[i] * pz[i]);
            }
        } else {
            for (int i = 0; i < n; i++) {
                se[i] = 1; // the square root of 0 0 + 0 0 + 1 1
            }
        }
        for (int i = 0; i < n; i++) {
            sn[i] = Math.sqrt(nx[i] * nx[i] + ny[i] * ny[i] + nz[i] * nz[i]);
        }
        for (int i = 0; i < n; i++) {
            double normal = sn[i];
            double eye = se[i];
            double inverse = 1 / (normal * eye);
            double inverseNormal = eye * inverse;
            double inverseEye = normal * inverse;
            q[i] = inverse;
            sn[i] = inverseNormal;
            se[i] = inverseEye;
            t.lengths[i] = (normal + eye + inverseNormal + inverseEye) * LENGTHS;
        }
        if (perspective) {
            for (int i = 0; i < n; i++) {
                q[i] = -(px[i] * nx[i] + py[i] * ny[i] + pz[i] * nz[i]) * q[i];
            }
        } else {
            for (int i = 0; i < n; i++) {
                q[i] = (0 * nx[i] + 0 * ny[i] + 1 * nz[i]) * q[i];
            }
        }
    }

    /**
     * Adds the light at data[o] to every point (the first light: to the
     * ambient term, kd times Ia, made here): the body of Lighting.shade's
     * light loop, step by step; and |L| and 1 / |L| to the point's length
     * test. L = light - P is worked out again in each step that reads it
     * (the same bits each time) rather than kept. V . L under a perspective
     * view is -(P . L), exactly -(E . L) but for a zero's sign; V . N too
     * (aim). Both reach only V . R = 2 cos (V . N) - V . L, taken as
     * max(0, V . R): where a zero's sign differs, a nonzero term leaves the
     * difference unseen, and a difference of zeros is a zero, which max
     * makes +0 either way.
     */
    private void light(LitPoints t, int n, int o, boolean first) {
        double[] data = lighting.lights.data();
        double x = data[o + Lights.X];
        double y = data[o + Lights.Y];
        double z = data[o + Lights.Z];
        double[] px = t.px;
        double[] py = t.py;
        double[] pz = t.pz;
        double[] dot = t.dot;
        for (int i = 0; i < n; i++) {
            dot[i] = t.nx[i] * (x - px[i]) + t.ny[i] * (y - py[i]) + t.nz[i] * (z - pz[i]);
        }
        double[] s = t.distance;
        double[] is = t.inverseDistance;
        for (int i = 0; i < n; i++) {
            // Every |L| counts, also where the light does not reach: a point
            // lit alone needlessly gets the same bits all the same.
            double lx = x - px[i];
            double ly = y - py[i];
            double lz = z - pz[i];
            double d = Math.sqrt(lx * lx + ly * ly + lz * lz);
            double w = 1 / d;
            s[i] = d;
            is[i] = w;
            t.lengths[i] += (d + w) * LENGTHS;
        }
        double a = data[o + Lights.A];
        double b = data[o + Lights.B];
        if (b != 0) {
            // Lighting's s * scale is s here: the scale of a usual length is 1.
            for (int i = 0; i < n; i++) {
                t.attenuation[i] = 1 / (a + b * s[i]);
            }
        }
        double[] cosine = t.cosine;
        for (int i = 0; i < n; i++) {
            cosine[i] = dot[i] * (t.inverseNormal[i] * is[i]);
        }
        double[] h = t.highlight; // V . L, then max(0, V . R) at most 1
        if (lighting.perspective) {
            for (int i = 0; i < n; i++) {
                h[i] = -(px[i] * (x - px[i]) + py[i] * (y - py[i]) + pz[i] * (z - pz[i])) * (t.inverseEye[i] * is[i]);
            }
        } else {
            for (int i = 0; i < n; i++) {
                h[i] = (0 * (x - px[i]) + 0 * (y - py[i]) + 1 * (z - pz[i])) * (t.inverseEye[i] * is[i]);
            }
        }
        for (int i = 0; i < n; i++) {
            // V . R = 2 cos (V . N) - V . L, then as Lighting.power takes it:
            // at least 0 (positive), at most 1 (see positive; a NaN stays
            // NaN, see raise).
            double r = 2 * cosine[i] * t.vn[i] - h[i];
            h[i] = Math.min(positive(r), 1);
        }
        add(t, n, o, raise(t, n), first);
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
     * 0) and times 0 elsewhere, with no branch, so that C2 packs it: the
     * reach is 1 where N . L &gt; 0 (the least positive double times 2^2000
     * is above 1), 0 where not, NaN for a NaN N . L (see positive). Where the
     * light does not reach, a finite contribution times 0 adds a zero, which
     * leaves the sum as it was (but for the sign of a zero sum, which the
     * clamp makes +0 either way); an infinite or NaN one makes the sum NaN,
     * and the point is lit alone, as it is for a NaN where the light
     * reaches (Lighting.contribution's test for a product with no value).
     * Without either, the sums are Lighting's. The first light's sum starts
     * from the ambient term, kd times Ia.
     */
    private void add(LitPoints t, int n, int o, double[] raised, boolean first) {
        Lighting l = lighting;
        double[] data = l.lights.data();
        // Unattenuated, Ii fi is Ii times 1 / a, kept with the light.
        boolean attenuated = data[o + Lights.B] != 0;
        double inverseA = data[o + Lights.INVERSE_A];
        double red = attenuated ? data[o + Lights.RED] : data[o + Lights.RED] * inverseA;
        double green = attenuated ? data[o + Lights.GREEN] : data[o + Lights.GREEN] * inverseA;
        double blue = attenuated ? data[o + Lights.BLUE] : data[o + Lights.BLUE] * inverseA;
        addChannel(t, n, t.red, t.kdRed, first, l.ambientRed, red, attenuated, raised);
        addChannel(t, n, t.green, t.kdGreen, first, l.ambientGreen, green, attenuated, raised);
        addChannel(t, n, t.blue, t.kdBlue, first, l.ambientBlue, blue, attenuated, raised);
    }

    /**
     * One channel of {@link #add}: into sum, each point's (Ii fi) times (kd
     * cos + ks times the raised highlight) times the reach, fi the point's
     * attenuation where {@code attenuated} (else already in the intensity);
     * added to kd times {@code ambient} for the first light, to the sum so
     * far for the others.
     */
    private void addChannel(LitPoints t, int n, double[] sum, double[] kd, boolean first, double ambient,
            double intensity, boolean attenuated, double[] raised) {
        double ks = lighting.ks;
        double[] cosine = t.cosine;
        double[] dot = t.dot;
        double[] f = t.attenuation;
        if (attenuated && first) {
            for (int i = 0; i < n; i++) {
                sum[i] = kd[i] * ambient + intensity * f[i] * (kd[i] * cosine[i] + ks * raised[i]) * reach(dot[i]);
            }
        } else if (attenuated) {
            for (int i = 0; i < n; i++) {
                sum[i] += intensity * f[i] * (kd[i] * cosine[i] + ks * raised[i]) * reach(dot[i]);
            }
        } else if (first) {
            for (int i = 0; i < n; i++) {
                sum[i] = kd[i] * ambient + intensity * (kd[i] * cosine[i] + ks * raised[i]) * reach(dot[i]);
            }
        } else {
            for (int i = 0; i < n; i++) {
                sum[i] += intensity * (kd[i] * cosine[i] + ks * raised[i]) * reach(dot[i]);
            }
        }
    }

    /** 1 where N . L &gt; 0, 0 where not, NaN for a NaN N . L (see {@link #add}). */
    private static double reach(double dot) {
        return Math.min(positive(dot) * 0x1p1000 * 0x1p1000, 1);
    }
}
