package simpview.shading;

import java.util.Arrays;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;

/**
 * What a lit scene's commands set and its primitives are drawn with: the
 * camera and W (world to camera), ambient light, the surface (kd, ks, p),
 * fog, the shading mode and the lights so far. None of it is saved by
 * {@code { }}; it carries across files. A primitive is drawn with the state
 * at its command (scenes are drawn as they are read), lit by the lights
 * defined before it.
 *
 * <p>As a {@link PointShader} it evaluates SPEC's formula in camera space
 * with the eye at the origin:
 * <pre>
 * I = kd Ia + sum_i (Ii fi) (kd (N . Li) + ks max(0, V . Ri)^p),  fi = 1 / (Ai + Bi |light i - P|)
 * </pre>
 * clamped to [0, 1] per channel.
 */
public final class LitState implements PointShader {

    /** How filled polygons are shaded. */
    public enum Shading { FLAT, GOURAUD, PHONG }

    private Camera camera = Camera.PARALLEL;
    private Matrix4 worldToCamera = Matrix4.identity();
    private double ambientR;
    private double ambientG;
    private double ambientB;
    private double kdR = 1;
    private double kdG = 1;
    private double kdB = 1;
    private double ks = 0.3;
    private double p = 8;
    private Fog fog = Fog.NONE;
    private Shading shading = Shading.PHONG;
    private final Lights lights = new Lights();

    public Camera camera() {
        return camera;
    }

    public Matrix4 worldToCamera() {
        return worldToCamera;
    }

    /** The camera command: W becomes {@code worldToCamera}; lights given before it are taken to camera space. */
    public void setCamera(Camera camera, Matrix4 worldToCamera) {
        this.camera = camera;
        this.worldToCamera = worldToCamera;
        lights.transform(worldToCamera);
    }

    public void setAmbient(double r, double g, double b) {
        ambientR = r;
        ambientG = g;
        ambientB = b;
    }

    /** The surface colour; ks and p stay as they were. */
    public void setSurface(double r, double g, double b) {
        kdR = r;
        kdG = g;
        kdB = b;
    }

    public void setSurface(double r, double g, double b, double specular, double exponent) {
        setSurface(r, g, b);
        ks = specular;
        p = exponent;
    }

    public void setFog(Fog f) {
        fog = f;
    }

    public void setShading(Shading s) {
        shading = s;
    }

    /** A light at world position (x, y, z): taken to camera space by W now. */
    public void addLight(double x, double y, double z, double r, double g, double b, double a, double bAtt) {
        Matrix4 w = worldToCamera;
        lights.add(w.applyX(x, y, z), w.applyY(x, y, z), w.applyZ(x, y, z), r, g, b, a, bAtt);
    }

    public double kdR() {
        return kdR;
    }

    public double kdG() {
        return kdG;
    }

    public double kdB() {
        return kdB;
    }

    public Fog fog() {
        return fog;
    }

    public Shading shading() {
        return shading;
    }

    public int lightCount() {
        return lights.count();
    }

    @Override
    public void shade(double px, double py, double pz, double nx, double ny, double nz,
            double kr, double kg, double kb, double[] out) {
        double r = kr * ambientR;
        double g = kg * ambientG;
        double b = kb * ambientB;
        int n = lights.count();
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (n > 0 && length > 0 && Double.isFinite(length)) {
            nx /= length;
            ny /= length;
            nz /= length;
            // V: from P to the eye at the origin; the parallel view looks along -z everywhere.
            double vx = 0;
            double vy = 0;
            double vz = 1;
            if (camera.isPerspective()) {
                double d = Math.sqrt(px * px + py * py + pz * pz);
                if (d > 0) {
                    vx = -px / d;
                    vy = -py / d;
                    vz = -pz / d;
                }
            }
            double[] l = lights.data;
            for (int i = 0; i < n; i++) {
                int o = i * Lights.STRIDE;
                double lx = l[o] - px;
                double ly = l[o + 1] - py;
                double lz = l[o + 2] - pz;
                double d = Math.sqrt(lx * lx + ly * ly + lz * lz);
                if (!(d > 0) || !Double.isFinite(d)) {
                    continue; // a light at the lit point itself adds nothing
                }
                lx /= d;
                ly /= d;
                lz /= d;
                double nl = nx * lx + ny * ly + nz * lz;
                if (!(nl > 0)) {
                    continue; // from behind: no diffuse, no specular
                }
                double f = 1 / (l[o + 6] + l[o + 7] * d);
                if (!Double.isFinite(f)) {
                    continue;
                }
                double rx = 2 * nl * nx - lx;
                double ry = 2 * nl * ny - ly;
                double rz = 2 * nl * nz - lz;
                double vr = vx * rx + vy * ry + vz * rz;
                double spec = ks * (p == 0 ? 1 : vr > 0 ? Math.pow(vr, p) : 0);
                double wr = l[o + 3] * f;
                double wg = l[o + 4] * f;
                double wb = l[o + 5] * f;
                r += wr * (kr * nl + spec);
                g += wg * (kg * nl + spec);
                b += wb * (kb * nl + spec);
            }
        }
        out[0] = clamp(r);
        out[1] = clamp(g);
        out[2] = clamp(b);
    }

    /** To [0, 1]; NaN (an infinite light times a zero) becomes 0. */
    private static double clamp(double c) {
        return c > 0 ? Math.min(c, 1) : 0;
    }

    /** The lights, in camera space once W is known, 8 numbers each: x, y, z, r, g, b, A, B. */
    static final class Lights {
        static final int STRIDE = 8;
        private double[] data = new double[4 * STRIDE];
        private int count;

        void add(double x, double y, double z, double r, double g, double b, double a, double bAtt) {
            if ((count + 1) * STRIDE > data.length) {
                data = Arrays.copyOf(data, 2 * data.length);
            }
            int o = count * STRIDE;
            data[o] = x;
            data[o + 1] = y;
            data[o + 2] = z;
            data[o + 3] = r;
            data[o + 4] = g;
            data[o + 5] = b;
            data[o + 6] = a;
            data[o + 7] = bAtt;
            count++;
        }

        /** Takes every light's position by m (the camera command, for lights given before it). */
        void transform(Matrix4 m) {
            for (int i = 0; i < count; i++) {
                int o = i * STRIDE;
                double x = data[o];
                double y = data[o + 1];
                double z = data[o + 2];
                data[o] = m.applyX(x, y, z);
                data[o + 1] = m.applyY(x, y, z);
                data[o + 2] = m.applyZ(x, y, z);
            }
        }

        int count() {
            return count;
        }
    }
}
