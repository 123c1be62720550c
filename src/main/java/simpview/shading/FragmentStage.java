package simpview.shading;

import simpview.raster.FragmentSink;
import simpview.surface.Colors;
import simpview.surface.Drawable;
import simpview.surface.ZBuffer;

/**
 * The fragment stage of lit scenes, per pixel, in this order: resolve depth
 * (z = (z q) / q), test it against the z-buffer (strictly nearer wins, then
 * stored), resolve the attributes (a = (a q) / q: perspective-correct), shade
 * (phong only: the colour of the lit point; flat and gouraud colours arrive
 * already lit), fog on camera-space z, and write round(c * 255) once to the
 * panel. Hidden pixels stop at the depth test and cost no shading.
 *
 * <p>Channels, in the order the geometry stage lays them out:
 * {@link #Z}, {@link #R}, {@link #G}, {@link #B} for every primitive (R, G, B
 * the final unfogged colour, or kd under phong), and for phong also the
 * camera-space point's x and y ({@link #PX}, {@link #PY}; its z is Z) and the
 * normal ({@link #NX}, {@link #NY}, {@link #NZ}).
 *
 * <p>State set per primitive; the per-pixel loop allocates nothing.
 */
public final class FragmentStage implements FragmentSink {

    public static final int Z = 0;
    public static final int R = 1;
    public static final int G = 2;
    public static final int B = 3;
    public static final int PX = 4;
    public static final int PY = 5;
    public static final int NX = 6;
    public static final int NY = 7;
    public static final int NZ = 8;
    /** Channels of a primitive whose colour is known before rasterization. */
    public static final int COLOUR_CHANNELS = 4;
    /** Channels of a phong-shaded polygon. */
    public static final int PHONG_CHANNELS = 9;

    private final ZBuffer zbuffer;
    private final double[] depth;
    private final int width;
    private final int height;
    private final Drawable panel;
    private final double[] lit = new double[3];
    private PointShader shader;
    private Fog fog = Fog.NONE;

    /** Writes to {@code panel} (panel coordinates, y up), depth-tested against {@code zbuffer}. */
    public FragmentStage(ZBuffer zbuffer, Drawable panel) {
        if (zbuffer.width() != panel.width() || zbuffer.height() != panel.height()) {
            throw new IllegalArgumentException("z-buffer and panel differ in size");
        }
        this.zbuffer = zbuffer;
        this.depth = zbuffer.depths();
        this.width = zbuffer.width();
        this.height = zbuffer.height();
        this.panel = panel;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The next primitives carry their colour (flat, gouraud, wire, lines), fogged by {@code fog}. */
    public void colours(Fog fog) {
        this.shader = null;
        this.fog = fog;
    }

    /** The next primitives are phong-shaded by {@code shader} at every pixel, then fogged. */
    public void phong(PointShader shader, Fog fog) {
        this.shader = shader;
        this.fog = fog;
    }

    @Override
    public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
        if (y < 0 || y >= height) {
            return;
        }
        int start = Math.max(from, 0);
        int end = Math.min(to, width);
        boolean wrote = shader == null ? colourSpan(y, from, start, end, q0, dq, v0, dv)
                : phongSpan(y, from, start, end, q0, dq, v0, dv);
        if (wrote) {
            zbuffer.written();
        }
    }

    /*
     * The two span loops below do, per pixel, exactly what pixel() does, with
     * k = x - from: inv = 1 / (q0 + k dq), each channel (v0[c] + k dv[c]) * inv.
     * The starts and slopes are read into locals once per span (the stores to
     * depth[] could alias v0 and dv, so the compiler would read them again at
     * every pixel); the arithmetic, and so every bit, is the same.
     */

    /** A span whose colour is known (flat, gouraud, wire, lines); true when a pixel was written. */
    private boolean colourSpan(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        double z0 = v0[Z];
        double dz = dv[Z];
        double r0 = v0[R];
        double dr = dv[R];
        double g0 = v0[G];
        double dg = dv[G];
        double b0 = v0[B];
        double db = dv[B];
        int row = y * width;
        boolean wrote = false;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!(z > depth[row + x])) {
                continue;
            }
            depth[row + x] = z;
            wrote = true;
            lit[0] = (r0 + k * dr) * inv;
            lit[1] = (g0 + k * dg) * inv;
            lit[2] = (b0 + k * db) * inv;
            panel.setPixel(x, y, z, fogged(z));
        }
        return wrote;
    }

    /** A phong span: kd, P and N resolved at each visible pixel and lit there; true when a pixel was written. */
    private boolean phongSpan(int y, int from, int start, int end, double q0, double dq, double[] v0,
            double[] dv) {
        double z0 = v0[Z];
        double dz = dv[Z];
        double r0 = v0[R];
        double dr = dv[R];
        double g0 = v0[G];
        double dg = dv[G];
        double b0 = v0[B];
        double db = dv[B];
        double px0 = v0[PX];
        double dpx = dv[PX];
        double py0 = v0[PY];
        double dpy = dv[PY];
        double nx0 = v0[NX];
        double dnx = dv[NX];
        double ny0 = v0[NY];
        double dny = dv[NY];
        double nz0 = v0[NZ];
        double dnz = dv[NZ];
        PointShader s = shader;
        int row = y * width;
        boolean wrote = false;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (z0 + k * dz) * inv;
            if (!(z > depth[row + x])) {
                continue;
            }
            depth[row + x] = z;
            wrote = true;
            s.shade((px0 + k * dpx) * inv, (py0 + k * dpy) * inv, z,
                    (nx0 + k * dnx) * inv, (ny0 + k * dny) * inv, (nz0 + k * dnz) * inv,
                    (r0 + k * dr) * inv, (g0 + k * dg) * inv, (b0 + k * db) * inv, lit);
            panel.setPixel(x, y, z, fogged(z));
        }
        return wrote;
    }

    @Override
    public void pixel(int x, int y, double q, double[] v) {
        if (x < 0 || x >= width || y < 0 || y >= height) {
            return;
        }
        int i = y * width + x;
        double inv = 1 / q;
        double z = v[Z] * inv;
        if (!(z > depth[i])) {
            return;
        }
        depth[i] = z;
        zbuffer.written();
        double r = v[R] * inv;
        double g = v[G] * inv;
        double b = v[B] * inv;
        if (shader != null) {
            shader.shade(v[PX] * inv, v[PY] * inv, z, v[NX] * inv, v[NY] * inv, v[NZ] * inv, r, g, b, lit);
        } else {
            lit[0] = r;
            lit[1] = g;
            lit[2] = b;
        }
        panel.setPixel(x, y, z, fogged(z));
    }

    /** The colour in {@link #lit}, fogged at depth z and packed: round(c * 255), once. */
    private int fogged(double z) {
        fog.apply(z, lit, 0);
        return Colors.pack(lit[0], lit[1], lit[2]);
    }
}
