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
        for (int i = 0; i < n; i++) {
            t.red[i] = t.kdRed[i] * l.ambientRed;
            t.green[i] = t.kdGreen[i] * l.ambientGreen;
            t.blue[i] = t.kdBlue[i] * l.ambientBlue;
        }
        if (l.lightCount == 0) {
            // The ambient term alone: no point is lit alone.
            for (int i = 0; i < n; i++) {
                t.red[i] = Lighting.clamp(t.red[i]);
                t.green[i] = Lighting.clamp(t.green[i]);
                t.blue[i] = Lighting.clamp(t.blue[i]);
            }
            return;
        }
        aim(t, n);
        int end = l.lightCount * Lights.STRIDE;
        for (int o = 0; o < end; o += Lights.STRIDE) {
            light(t, n, o);
        }
        for (int i = 0; i < n; i++) {
            double r = t.red[i];
            double g = t.green[i];
            double b = t.blue[i];
            // A NaN sum: some term had no value (Lighting adds 0 for it) or
            // the terms cancelled; either way the point is lit alone.
            t.alone[i] |= r != r | g != g | b != b;
            t.red[i] = Lighting.clamp(r);
            t.green[i] = Lighting.clamp(g);
            t.blue[i] = Lighting.clamp(b);
        }
        for (int i = 0; i < n; i++) {
            if (t.alone[i]) {
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
        for (int i = 0; i < n; i++) {
            // Lit alone at the end; what the steps make of it meanwhile is replaced.
            t.alone[i] = !(usual(t.normal2[i]) & usual(t.eye2[i]));
        }
    }

    /** x x + y y + z z for every point. */
    private static void squaredLengths(double[] x, double[] y, double[] z, double[] out, int n) {
        for (int i = 0; i < n; i++) {
            out[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
        }
    }

    /** A squared length that Lighting uses as it is. */
    private static boolean usual(double length2) {
        return length2 >= Lighting.LOW & length2 <= Lighting.HIGH;
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
        squaredLengths(lx, ly, lz, t.distance2, n);
        double[] s = t.distance;
        double[] is = t.inverseDistance;
        for (int i = 0; i < n; i++) {
            s[i] = Math.sqrt(t.distance2[i]);
        }
        for (int i = 0; i < n; i++) {
            is[i] = 1 / s[i];
        }
        for (int i = 0; i < n; i++) {
            t.cosine[i] = t.dot[i] * (t.inverseNormal[i] * is[i]);
        }
        double[] h = t.highlight; // V . L, then V . R
        for (int i = 0; i < n; i++) {
            h[i] = (t.eyeX[i] * lx[i] + t.eyeY[i] * ly[i] + t.eyeZ[i] * lz[i]) * (t.inverseEye[i] * is[i]);
        }
        for (int i = 0; i < n; i++) {
            h[i] = 2 * t.cosine[i] * t.vn[i] - h[i];
        }
        double a = data[o + Lights.A];
        double b = data[o + Lights.B];
        if (b != 0) {
            // Lighting's s * scale is s here: the scale of a usual length is 1.
            for (int i = 0; i < n; i++) {
                t.attenuation[i] = 1 / (a + b * s[i]);
            }
        }
        raise(t, n);
        add(t, n, o);
    }

    /** Lighting.power for every point's highlight: max(0, h) at most 1, to the p. */
    private void raise(LitPoints t, int n) {
        double[] c = t.highlight;
        double[] result = t.raised;
        // As Lighting.power, but a NaN stays NaN: only a point lit alone, or
        // one whose sum the NaN then makes NaN (lit alone too), can have one.
        for (int i = 0; i < n; i++) {
            c[i] = Math.min(Math.max(c[i], 0), 1);
        }
        int e = lighting.exponent;
        if (e < 0) {
            double p = lighting.p;
            for (int i = 0; i < n; i++) {
                result[i] = Math.pow(c[i], p);
            }
            return;
        }
        // Lighting.bySquaring, each step over every point; c holds the squares.
        for (int i = 0; i < n; i++) {
            result[i] = 1;
        }
        while (true) {
            if ((e & 1) != 0) {
                for (int i = 0; i < n; i++) {
                    result[i] *= c[i];
                }
            }
            e >>>= 1;
            if (e == 0) {
                return;
            }
            for (int i = 0; i < n; i++) {
                c[i] *= c[i];
            }
        }
    }

    /** Each point the light reaches gets its contribution; one at an unusual |L| is left to be lit alone. */
    private void add(LitPoints t, int n, int o) {
        Lighting l = lighting;
        double[] data = l.lights.data();
        double red = data[o + Lights.RED];
        double green = data[o + Lights.GREEN];
        double blue = data[o + Lights.BLUE];
        boolean constant = data[o + Lights.B] == 0;
        double inverseA = data[o + Lights.INVERSE_A];
        double ks = l.ks;
        // Lighting.contribution's test for a product with no value is left
        // out: such a product makes the sum NaN, and shade() then lights the
        // point alone. Without one, the sums are the same as with the test.
        for (int i = 0; i < n; i++) {
            if (t.dot[i] > 0) { // not behind the surface, edge on, or at the lit point
                t.alone[i] |= !usual(t.distance2[i]); // lit alone at the end
                double cos = t.cosine[i];
                double specular = ks * t.raised[i];
                double f = constant ? inverseA : t.attenuation[i];
                t.red[i] += red * f * (t.kdRed[i] * cos + specular);
                t.green[i] += green * f * (t.kdGreen[i] * cos + specular);
                t.blue[i] += blue * f * (t.kdBlue[i] * cos + specular);
            }
        }
    }
}
