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
 */
final class BatchLighting {

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
        if (l.lightCount == 0) {
            // The ambient term alone, clamped by min and max (which C2 packs);
            // only a NaN, which they keep, is then clamped by Lighting's rule.
            for (int i = 0; i < n; i++) {
                t.red[i] = Math.min(Math.max(t.kdRed[i] * ar, 0), 1);
                t.green[i] = Math.min(Math.max(t.kdGreen[i] * ag, 0), 1);
                t.blue[i] = Math.min(Math.max(t.kdBlue[i] * ab, 0), 1);
            }
            for (int i = 0; i < n; i++) {
                double sum = t.red[i] + t.green[i] + t.blue[i];
                if (sum != sum) {
                    t.red[i] = Lighting.clamp(t.red[i]);
                    t.green[i] = Lighting.clamp(t.green[i]);
                    t.blue[i] = Lighting.clamp(t.blue[i]);
                }
            }
            return;
        }
        for (int i = 0; i < n; i++) {
            t.red[i] = t.kdRed[i] * ar;
            t.green[i] = t.kdGreen[i] * ag;
            t.blue[i] = t.kdBlue[i] * ab;
        }
        aim(t, n);
        int end = l.lightCount * Lights.STRIDE;
        for (int o = 0; o < end; o += Lights.STRIDE) {
            light(t, n, o);
        }
        // Clamped by min and max: as Lighting.clamp, but a NaN stays NaN.
        for (int i = 0; i < n; i++) {
            t.red[i] = Math.min(Math.max(t.red[i], 0), 1);
            t.green[i] = Math.min(Math.max(t.green[i], 0), 1);
            t.blue[i] = Math.min(Math.max(t.blue[i], 0), 1);
        }
        for (int i = 0; i < n; i++) {
            // Lit alone: a point with a length Lighting rescales (N, E or some
            // L), or with a NaN sum (a term with no value, which Lighting adds
            // as 0, or terms that cancelled); what the steps made of it is replaced.
            double sum = t.red[i] + t.green[i] + t.blue[i];
            if (!(t.smallest[i] >= Lighting.LOW & t.largest[i] <= Lighting.HIGH) | sum != sum) {
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
     * V . N. Each loop is kept this small so that C2 unrolls it, which it
     * must before it packs the points' operations.
     */
    private void aim(LitPoints t, int n) {
        double[] ex = t.eyeX;
        double[] ey = t.eyeY;
        double[] ez = t.eyeZ;
        if (lighting.perspective) {
            for (int i = 0; i < n; i++) {
                ex[i] = -t.px[i];
                ey[i] = -t.py[i];
                ez[i] = -t.pz[i];
            }
        } else {
            for (int i = 0; i < n; i++) {
                ex[i] = 0;
                ey[i] = 0;
                ez[i] = 1;
            }
        }
        squaredLengths(t.nx, t.ny, t.nz, t.normal2, n);
        squaredLengths(ex, ey, ez, t.eye2, n);
        double[] sn = t.inverseNormal; // |N| until the last step
        double[] se = t.inverseEye;
        double[] q = t.vn;
        for (int i = 0; i < n; i++) {
            sn[i] = Math.sqrt(t.normal2[i]);
        }
        for (int i = 0; i < n; i++) {
            se[i] = Math.sqrt(t.eye2[i]);
        }
        for (int i = 0; i < n; i++) {
            q[i] = 1 / (sn[i] * se[i]);
        }
        for (int i = 0; i < n; i++) {
            double normal = sn[i];
            sn[i] = se[i] * q[i];
            se[i] = normal * q[i];
        }
        for (int i = 0; i < n; i++) {
            q[i] = (ex[i] * t.nx[i] + ey[i] * t.ny[i] + ez[i] * t.nz[i]) * q[i];
        }
        // The smallest and largest squared length of the point so far: it is
        // lit alone at the end unless both are usual (each light adds |L|^2).
        for (int i = 0; i < n; i++) {
            t.smallest[i] = Math.min(t.normal2[i], t.eye2[i]);
            t.largest[i] = Math.max(t.normal2[i], t.eye2[i]);
        }
    }

    /** x x + y y + z z for every point. */
    private static void squaredLengths(double[] x, double[] y, double[] z, double[] out, int n) {
        for (int i = 0; i < n; i++) {
            out[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
        }
    }

    /** Adds the light at data[o] to every point: the body of Lighting.shade's light loop, step by step. */
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
        for (int i = 0; i < n; i++) {
            // Every |L|^2 counts, also where the light does not reach: a
            // point lit alone needlessly gets the same bits all the same.
            double d2 = lx[i] * lx[i] + ly[i] * ly[i] + lz[i] * lz[i];
            s[i] = Math.sqrt(d2);
            t.smallest[i] = Math.min(t.smallest[i], d2);
            t.largest[i] = Math.max(t.largest[i], d2);
        }
        double[] is = t.inverseDistance;
        for (int i = 0; i < n; i++) {
            is[i] = 1 / s[i];
        }
        for (int i = 0; i < n; i++) {
            t.cosine[i] = t.dot[i] * (t.inverseNormal[i] * is[i]);
        }
        double[] h = t.highlight;
        for (int i = 0; i < n; i++) {
            // V . R = 2 cos (V . N) - V . L, then as Lighting.power takes it:
            // max(0, V . R) at most 1 (min and max keep a NaN, see raise).
            double vl = (t.eyeX[i] * lx[i] + t.eyeY[i] * ly[i] + t.eyeZ[i] * lz[i]) * (t.inverseEye[i] * is[i]);
            h[i] = Math.min(Math.max(2 * t.cosine[i] * t.vn[i] - vl, 0), 1);
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
        while ((e & 1) == 0) {
            for (int i = 0; i < n; i++) {
                c[i] *= c[i];
            }
            e >>>= 1;
        }
        e >>>= 1;
        if (e == 0) {
            return c;
        }
        for (int i = 0; i < n; i++) {
            double v = c[i];
            result[i] = v;
            c[i] = v * v;
        }
        while (true) {
            boolean multiply = (e & 1) != 0;
            e >>>= 1;
            if (e == 0) { // e's highest bit
                for (int i = 0; i < n; i++) {
                    result[i] *= c[i];
                }
                return result;
            }
            if (multiply) {
                for (int i = 0; i < n; i++) {
                    result[i] *= c[i];
                    c[i] *= c[i];
                }
            } else {
                for (int i = 0; i < n; i++) {
                    c[i] *= c[i];
                }
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
            // above 1), 0 where not, NaN for a NaN N . L.
            reach[i] = Math.min(Math.max(t.dot[i], 0) * 0x1p1000 * 0x1p1000, 1);
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
