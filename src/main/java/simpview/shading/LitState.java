package simpview.shading;

import java.util.function.Supplier;
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
 * <p>As a {@link PointShader} it lights a point by {@link Lighting} with what
 * is in force now (ambient, ks and p, the lights so far, the view).
 */
public final class LitState implements PointShader {

    /** How filled polygons are shaded. */
    public enum ShadingMode { FLAT, GOURAUD, PHONG }

    private Camera camera = Camera.PARALLEL;
    private Matrix4 worldToCamera = Matrix4.identity();
    /** The window's turn of the view, after W; null when not turned. */
    private Matrix4 turn;
    private double ambientR;
    private double ambientG;
    private double ambientB;
    private double kdR = 1;
    private double kdG = 1;
    private double kdB = 1;
    private double ks = 0.3;
    private double p = 8;
    private Fog fog = Fog.NONE;
    private ShadingMode shading = ShadingMode.PHONG;
    private final Lights lights = new Lights();
    private final Lighting lighting = new Lighting(lights);
    /** Counts the changes to what lights a point: see {@link #lightingVersion}. */
    private int lightingVersion;
    /** The lighting last frozen ({@link #frozenShader}), and the version it was frozen at. */
    private Supplier<PointShader> frozen;
    private int frozenVersion;

    public Camera camera() {
        return camera;
    }

    public Matrix4 worldToCamera() {
        return worldToCamera;
    }

    /**
     * Turns the view by {@code turn} in camera space, after W (the window's
     * orbit), or not at all (null). Before any command: until a camera
     * command, W is the turn itself.
     */
    public void turnView(Matrix4 turn) {
        this.turn = turn;
        this.worldToCamera = turn == null ? Matrix4.identity() : turn;
    }

    /**
     * The camera command: W becomes {@code worldToCamera} (after the view's
     * turn, if any); lights given before it are taken to camera space.
     */
    public void setCamera(Camera camera, Matrix4 worldToCamera) {
        this.camera = camera;
        Matrix4 w = turn == null ? worldToCamera : turn.times(worldToCamera);
        // Lights so far stand where the W before this one (the turn, or the identity) took them.
        Matrix4 move = turn == null ? w : w.times(turn.inverse());
        this.worldToCamera = w;
        for (int i = 0; i < lights.count(); i++) {
            double x = lights.x(i);
            double y = lights.y(i);
            double z = lights.z(i);
            lights.moveTo(i, move.applyX(x, y, z), move.applyY(x, y, z), move.applyZ(x, y, z));
        }
        prepare();
    }

    public void setAmbient(double r, double g, double b) {
        ambientR = r;
        ambientG = g;
        ambientB = b;
        prepare();
    }

    /**
     * True when a light of an intensity above 0 is on (whatever it faces).
     * Negative numbers are errors at their command, so a sum tells.
     */
    public boolean anyLightOn() {
        for (int i = 0; i < lights.count(); i++) {
            if (lights.red(i) + lights.green(i) + lights.blue(i) > 0) {
                return true;
            }
        }
        return false;
    }

    /**
     * True when a light of an intensity above 0 stands in front of a face of
     * normal N at one of its n vertices ({@code points}, x y z at each
     * multiple of {@code stride}): N . (light - vertex) above 0 there. Every
     * point of the face, clipped or not, is a mean of its vertices, and
     * N . (light - P) is linear in P, so a light in front at no vertex is
     * in front nowhere on the face: by SPEC's formula it adds nothing to it,
     * neither diffuse nor specular.
     */
    public boolean lightInFront(double nx, double ny, double nz, double[] points, int stride, int n) {
        for (int i = 0; i < lights.count(); i++) {
            if (!(lights.red(i) + lights.green(i) + lights.blue(i) > 0)) {
                continue;
            }
            for (int k = 0; k < n; k++) {
                int o = k * stride;
                double toLight = nx * (lights.x(i) - points[o]) + ny * (lights.y(i) - points[o + 1])
                        + nz * (lights.z(i) - points[o + 2]);
                if (toLight > 0) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The surface colour; ks and p stay as they were. */
    public void setSurface(double r, double g, double b) {
        kdR = r;
        kdG = g;
        kdB = b;
    }

    /**
     * The surface colour, ks and p. The lighting changes only when ks or p
     * does (kd reaches a point as its own channel): a scene that gives each
     * of its objects a surface of the same ks and p keeps one lighting, so
     * its phong pixels are lit as one look ({@link #frozenShader}).
     */
    public void setSurface(double r, double g, double b, double specular, double exponent) {
        setSurface(r, g, b);
        if (Double.doubleToRawLongBits(specular) != Double.doubleToRawLongBits(ks)
                || Double.doubleToRawLongBits(exponent) != Double.doubleToRawLongBits(p)) {
            ks = specular;
            p = exponent;
            prepare();
        }
    }

    public void setFog(Fog f) {
        fog = f;
    }

    public void setShading(ShadingMode s) {
        shading = s;
    }

    /** A light at world position (x, y, z): taken to camera space by W now. */
    public void addLight(double x, double y, double z, double r, double g, double b, double a, double bAtt) {
        Matrix4 w = worldToCamera;
        lights.add(w.applyX(x, y, z), w.applyY(x, y, z), w.applyZ(x, y, z), r, g, b, a, bAtt);
        prepare();
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

    public double ambientR() {
        return ambientR;
    }

    public double ambientG() {
        return ambientG;
    }

    public double ambientB() {
        return ambientB;
    }

    /** The specular coefficient ks in force. */
    public double ks() {
        return ks;
    }

    /** The specular exponent p in force. */
    public double p() {
        return p;
    }

    /** The lights so far, in camera space (read only: the inspector's explanation). */
    public Lights lights() {
        return lights;
    }

    public Fog fog() {
        return fog;
    }

    public ShadingMode shading() {
        return shading;
    }

    @Override
    public int lightCount() {
        return lights.count();
    }

    @Override
    public void shade(double px, double py, double pz, double nx, double ny, double nz,
            double kr, double kg, double kb, double[] out) {
        lighting.shade(px, py, pz, nx, ny, nz, kr, kg, kb, out, 0);
    }

    @Override
    public void shade(LitPoints points) {
        lighting.shade(points);
    }

    @Override
    public boolean usesPoint() {
        return lighting.usesPoint();
    }

    @Override
    public boolean unlitAt(double px, double py, double pz, double nx, double ny, double nz) {
        return lighting.unlitAt(px, py, pz, nx, ny, nz);
    }

    /**
     * What lights a point now, as numbers, for a program that lights the
     * same scene elsewhere (the llvmpipe benchmark): ambient r, g, b, ks, p,
     * 1 for a perspective view (else 0), the number of lights, then per light
     * its camera-space x, y, z, intensity r, g, b and attenuation A, B.
     */
    public double[] lightingNumbers() {
        int n = lights.count();
        double[] v = new double[7 + 8 * n];
        v[0] = ambientR;
        v[1] = ambientG;
        v[2] = ambientB;
        v[3] = ks;
        v[4] = p;
        v[5] = camera.isPerspective() ? 1 : 0;
        v[6] = n;
        for (int i = 0; i < n; i++) {
            int o = 7 + 8 * i;
            v[o] = lights.x(i);
            v[o + 1] = lights.y(i);
            v[o + 2] = lights.z(i);
            v[o + 3] = lights.red(i);
            v[o + 4] = lights.green(i);
            v[o + 5] = lights.blue(i);
            v[o + 6] = lights.a(i);
            v[o + 7] = lights.b(i);
        }
        return v;
    }

    /** Changes whenever what {@link #shade} does changes: equal versions light every point alike. */
    public int lightingVersion() {
        return lightingVersion;
    }

    /**
     * What lights a point now (ambient, ks and p, the lights so far, the
     * view), kept apart from later changes to the state: each shader the
     * supplier makes lights as this state does now, to the bit, with scratch
     * of its own, so each drawing thread takes its own. The same supplier
     * while the lighting is unchanged ({@link #lightingVersion}).
     */
    public Supplier<PointShader> frozenShader() {
        if (frozen == null || frozenVersion != lightingVersion) {
            frozen = freeze();
            frozenVersion = lightingVersion;
        }
        return frozen;
    }

    private Supplier<PointShader> freeze() {
        Lights now = lights.copy();
        double ar = ambientR;
        double ag = ambientG;
        double ab = ambientB;
        double specular = ks;
        double exponent = p;
        boolean perspective = camera.isPerspective();
        return () -> {
            Lighting own = new Lighting(now);
            own.prepare(ar, ag, ab, specular, exponent, now.count(), perspective);
            return new PointShader() {
                @Override
                public void shade(double px, double py, double pz, double nx, double ny, double nz,
                        double kr, double kg, double kb, double[] out) {
                    own.shade(px, py, pz, nx, ny, nz, kr, kg, kb, out, 0);
                }

                @Override
                public void shade(LitPoints points) {
                    own.shade(points);
                }

                @Override
                public boolean usesPoint() {
                    return own.usesPoint();
                }

                @Override
                public int lightCount() {
                    return own.lightCount();
                }

                @Override
                public boolean unlitAt(double px, double py, double pz, double nx, double ny, double nz) {
                    return own.unlitAt(px, py, pz, nx, ny, nz);
                }
            };
        };
    }

    /** Lighting takes what is in force now: every change to the state is told to it here. */
    private void prepare() {
        lightingVersion++;
        lighting.prepare(ambientR, ambientG, ambientB, ks, p, lights.count(), camera.isPerspective());
    }
}
