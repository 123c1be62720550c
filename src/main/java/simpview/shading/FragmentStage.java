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
        int row = y * width;
        int start = Math.max(from, 0);
        int end = Math.min(to, width);
        boolean wrote = false;
        for (int x = start; x < end; x++) {
            int k = x - from;
            double inv = 1 / (q0 + k * dq);
            double z = (v0[Z] + k * dv[Z]) * inv;
            if (!(z > depth[row + x])) {
                continue;
            }
            depth[row + x] = z;
            wrote = true;
            double r = (v0[R] + k * dv[R]) * inv;
            double g = (v0[G] + k * dv[G]) * inv;
            double b = (v0[B] + k * dv[B]) * inv;
            if (shader != null) {
                shader.shade((v0[PX] + k * dv[PX]) * inv, (v0[PY] + k * dv[PY]) * inv, z,
                        (v0[NX] + k * dv[NX]) * inv, (v0[NY] + k * dv[NY]) * inv, (v0[NZ] + k * dv[NZ]) * inv,
                        r, g, b, lit);
            } else {
                lit[0] = r;
                lit[1] = g;
                lit[2] = b;
            }
            panel.setPixel(x, y, z, fogged(z));
        }
        if (wrote) {
            zbuffer.written();
        }
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
