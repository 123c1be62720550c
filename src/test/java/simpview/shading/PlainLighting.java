package simpview.shading;

import java.util.ArrayList;
import java.util.List;

/**
 * SPEC's lighting formula written out plainly, with unit vectors as arrays and
 * Math.pow, for the tests to compare {@link Lighting} against. It shares no
 * code with Lighting. Lights are {x, y, z, r, g, b, A, B}.
 */
final class PlainLighting {

    final List<double[]> lights = new ArrayList<>();
    double[] ambient = {0, 0, 0};
    double ks = 0.3;
    double p = 8;
    boolean perspective = true;

    PlainLighting light(double x, double y, double z, double r, double g, double b, double a, double bb) {
        lights.add(new double[] {x, y, z, r, g, b, a, bb});
        return this;
    }

    /** The same lights in a Lights list, for the code under test. */
    Lights toLights() {
        Lights out = new Lights();
        for (double[] l : lights) {
            out.add(l[0], l[1], l[2], l[3], l[4], l[5], l[6], l[7]);
        }
        return out;
    }

    /** A Lighting prepared with the same state and every light. */
    Lighting toLighting() {
        Lighting lighting = new Lighting(toLights());
        lighting.prepare(ambient[0], ambient[1], ambient[2], ks, p, lights.size(), perspective);
        return lighting;
    }

    /** The unclamped I of SPEC at P with normal N and colour kd. */
    double[] unclamped(double[] point, double[] normal, double[] kd) {
        double[] colour = new double[3];
        for (int c = 0; c < 3; c++) {
            colour[c] = kd[c] * ambient[c];
        }
        double normalLength = length(normal);
        if (normalLength == 0) {
            return colour;
        }
        double[] n = scaled(normal, 1 / normalLength);
        double[] v = perspective ? scaled(point, -1 / length(point)) : new double[] {0, 0, 1};
        for (double[] light : lights) {
            double[] toLight = {light[0] - point[0], light[1] - point[1], light[2] - point[2]};
            double d = length(toLight);
            if (d == 0) {
                continue;
            }
            double[] l = scaled(toLight, 1 / d);
            double nl = dot(n, l);
            if (nl <= 0) {
                continue;
            }
            double[] reflected = {2 * nl * n[0] - l[0], 2 * nl * n[1] - l[1], 2 * nl * n[2] - l[2]};
            double highlight = p == 0 ? 1 : Math.pow(Math.max(0, dot(v, reflected)), p);
            double f = 1 / (light[6] + light[7] * d);
            for (int c = 0; c < 3; c++) {
                colour[c] += light[3 + c] * f * (kd[c] * nl + ks * highlight);
            }
        }
        return colour;
    }

    /**
     * How near P is to a light's horizon: the least |N . L| over the lights
     * (infinity with none, or with a zero normal). At N . L = 0 the formula
     * jumps (a light adds its specular term just above it and nothing at or
     * below it), so within rounding of 0 two exact evaluations may fall on
     * either side.
     */
    double nearestHorizon(double[] point, double[] normal) {
        double normalLength = length(normal);
        double nearest = Double.POSITIVE_INFINITY;
        if (normalLength == 0) {
            return nearest;
        }
        double[] n = scaled(normal, 1 / normalLength);
        for (double[] light : lights) {
            double[] toLight = {light[0] - point[0], light[1] - point[1], light[2] - point[2]};
            double d = length(toLight);
            if (d > 0) {
                nearest = Math.min(nearest, Math.abs(dot(n, scaled(toLight, 1 / d))));
            }
        }
        return nearest;
    }

    /** I clamped to [0, 1] per channel. */
    double[] colour(double[] point, double[] normal, double[] kd) {
        double[] colour = unclamped(point, normal, kd);
        for (int c = 0; c < 3; c++) {
            colour[c] = Math.min(1, Math.max(0, colour[c]));
        }
        return colour;
    }

    static double length(double[] v) {
        return Math.sqrt(dot(v, v));
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] scaled(double[] v, double s) {
        return new double[] {v[0] * s, v[1] * s, v[2] * s};
    }
}
