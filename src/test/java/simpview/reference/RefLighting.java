package simpview.reference;

import java.util.List;

/**
 * SPEC Part 2's lighting formula, once, in camera space with the eye at the
 * origin:
 * I = kd Ia + sum_i (Ii fi) (kd (N.Li) + ks max(0, V.Ri)^p), fi = 1/(Ai + Bi di),
 * a light adding nothing where {@code N.Li <= 0} or where it sits on the lit point.
 * The result is clamped to [0, 1] per channel.
 */
record RefLighting(double[] ambient, double ks, double exponent, List<Light> lights, boolean perspective) {

    /** A point light already in camera space. */
    record Light(double[] position, double[] intensity, double a, double b) {
    }

    /** The clamped colour at camera-space point p with normal n (any length; zero: ambient only) and colour kd. */
    double[] colour(double[] p, double[] n, double[] kd) {
        double[] out = new double[3];
        for (int ch = 0; ch < 3; ch++) {
            out[ch] = kd[ch] * ambient[ch];
        }
        double[] normal = RefMatrix.unit(n);
        double[] eye = perspective ? RefMatrix.unit(new double[] {-p[0], -p[1], -p[2]}) : new double[] {0, 0, 1};
        if (RefMatrix.length(normal) > 0) {
            for (Light light : lights) {
                addLight(light, p, normal, eye, kd, out);
            }
        }
        for (int ch = 0; ch < 3; ch++) {
            out[ch] = Math.max(0, Math.min(1, out[ch]));
        }
        return out;
    }

    private void addLight(Light light, double[] p, double[] n, double[] eye, double[] kd, double[] out) {
        double[] toLight = RefMatrix.minus(light.position(), p);
        double d = RefMatrix.length(toLight);
        if (d == 0) {
            return;
        }
        double[] l = RefMatrix.unit(toLight);
        double nl = RefMatrix.dot(n, l);
        if (nl <= 0) {
            return;
        }
        double[] r = {2 * nl * n[0] - l[0], 2 * nl * n[1] - l[1], 2 * nl * n[2] - l[2]};
        // A lit point at the eye has no eye direction: no specular term there.
        double specular = RefMatrix.length(eye) == 0 ? 0
                : ks * Math.pow(Math.max(0, RefMatrix.dot(eye, r)), exponent);
        double f = 1 / (light.a() + light.b() * d);
        for (int ch = 0; ch < 3; ch++) {
            out[ch] += light.intensity()[ch] * f * (kd[ch] * nl + specular);
        }
    }
}
