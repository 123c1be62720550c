package simpview.raster;

import static simpview.geometry.Vertex.B;
import static simpview.geometry.Vertex.G;
import static simpview.geometry.Vertex.R;
import static simpview.geometry.Vertex.X;
import static simpview.geometry.Vertex.Y;
import static simpview.geometry.Vertex.Z;

import java.util.Arrays;
import simpview.geometry.Vertex;
import simpview.surface.Colors;
import simpview.surface.CoverageDrawable;
import simpview.surface.Drawable;

/**
 * The first assignment's antialiased line (SPEC Part 3, the handout's
 * method): the line is a slab of width 1 centred on the segment between the
 * rounded endpoints; a pixel is a disc of radius {@link #RADIUS} = sqrt(2)/2
 * at its centre (the integer pixel coordinates, as the DDA's rounding has
 * them), and its coverage is the share of the disc inside the slab. Pixels
 * are taken along the segment and half a pixel past each end; each is written
 * once, blending {@code c * colour + (1 - c) * old} through a
 * {@link CoverageDrawable}. Colour and z are lerped along the segment.
 *
 * <p>One instance reuses its scratch state and is not for use by two threads at once.
 */
public final class AntialiasedLineRenderer implements LineRenderer {

    /** The pixel's disc: the one that barely contains the pixel's square. */
    public static final double RADIUS = Math.sqrt(2) / 2;
    /** The slab's half width. */
    public static final double HALF_WIDTH = 0.5;
    /** How far past each end of the segment pixels are taken, along it. */
    public static final double PAST_END = 0.5;

    private static final double DISC = Math.PI * RADIUS * RADIUS;
    private static final double PER_DISC = 1 / DISC;
    private static final double PER_RADIUS = 1 / RADIUS;
    /** No pixel whose centre is farther than this from the segment's line is touched. */
    private static final double REACH = HALF_WIDTH + RADIUS;

    /** Lines up to this reach (in numerator units, about 1.2 x their length) remember their coverages. */
    private static final int REMEMBERED = 4096;

    private final double[] ends = new double[2 * Vertex.NUMBERS];
    /** A line's coverages by the numerator of their distance; -1 where not yet worked out. */
    private final double[] byNumerator = new double[REMEMBERED + 1];
    private Drawable wrapped;
    private CoverageDrawable blend;

    /**
     * The share of a pixel's disc inside the slab, for a pixel centre at
     * {@code distance} from the segment's line: one minus the two caps of
     * the disc beyond the slab's edges, over the disc's area. In [0, 1].
     */
    public static double coverage(double distance) {
        double d = Math.abs(distance);
        double c = 1 - (cap(HALF_WIDTH - d) + cap(HALF_WIDTH + d)) * PER_DISC;
        return c <= 0 ? 0 : Math.min(c, 1);
    }

    /**
     * The distance this drawer measures for pixel (x, y) of the line from (ax, ay) to (bx, by), its ends
     * already rounded: from the line through them, the pixel's centre at its integer coordinates; for a
     * one-pixel line (equal ends), |y - ay|, as a horizontal line of length 0. Its coverage is
     * {@link #coverage(double)} of it, for a pixel not past the ends' reach.
     */
    public static double distance(double x, double y, double ax, double ay, double bx, double by) {
        double length = Math.hypot(bx - ax, by - ay);
        return length == 0 ? Math.abs(y - ay) : Math.abs((x - ax) * (by - ay) - (y - ay) * (bx - ax)) / length;
    }

    /**
     * The area of the disc beyond a line at signed distance h from its centre
     * (positive: the line does not reach the centre): the handout's pie wedge
     * and triangle, {@code r^2 theta - h sqrt(r^2 - h^2)} with cos theta = h / r
     * ({@link ArcCosine}: within a few units in the last place of Math.acos).
     */
    private static double cap(double h) {
        if (h >= RADIUS) {
            return 0;
        }
        if (h <= -RADIUS) {
            return DISC;
        }
        double cos = h * PER_RADIUS;
        double sin = ArcCosine.sine(cos);
        return RADIUS * RADIUS * ArcCosine.of(cos, sin) - h * RADIUS * sin;
    }

    @Override
    public void drawLine(Vertex p, Vertex q, Drawable drawable) {
        p.writeTo(ends, 0);
        q.writeTo(ends, Vertex.NUMBERS);
        drawLine(ends, 0, Vertex.NUMBERS, drawable);
    }

    @Override
    public void drawLine(double[] v, int from, int to, Drawable drawable) {
        if (!Vertex.isFinite(v, from) || !Vertex.isFinite(v, to)) {
            return;
        }
        CoverageDrawable target = blending(drawable);
        double ax = Math.floor(v[from + X] + 0.5);
        double ay = Math.floor(v[from + Y] + 0.5);
        double bx = Math.floor(v[to + X] + 0.5);
        double by = Math.floor(v[to + Y] + 0.5);
        double dx = bx - ax;
        double dy = by - ay;
        double length = Math.hypot(dx, dy);
        // A one-pixel line is a horizontal one of length 0.
        double ux = length == 0 ? 1 : dx / length;
        double uy = length == 0 ? 0 : dy / length;
        boolean xMajor = Math.abs(dx) >= Math.abs(dy);
        double major0 = xMajor ? Math.min(ax, bx) : Math.min(ay, by);
        double major1 = xMajor ? Math.max(ax, bx) : Math.max(ay, by);
        int majorLimit = xMajor ? drawable.width() : drawable.height();
        int minorLimit = xMajor ? drawable.height() : drawable.width();
        // Pixels past the ends reach at most PAST_END + REACH along the major axis.
        double lo = Math.max(major0 - 2, 0);
        double hi = Math.min(major1 + 2, majorLimit - 1);
        double slope = xMajor ? (dx == 0 ? 0 : dy / dx) : dx / dy;
        double majorA = xMajor ? ax : ay;
        double minorA = xMajor ? ay : ax;
        double pr = v[from + R];
        double pg = v[from + G];
        double pb = v[from + B];
        double pz = v[from + Z];
        double qr = v[to + R];
        double qg = v[to + G];
        double qb = v[to + B];
        double qz = v[to + Z];
        // A line of one colour is packed once (the lerp would give it again, or a last bit beside it).
        boolean oneColour = pr == qr && pg == qg && pb == qb;
        int colour = Colors.pack(pr, pg, pb);
        // A pixel at minor offset o from the line's minor coordinate at its
        // major one is o |u_major| from the line: only |o| < REACH / |u_major| can be touched.
        double minorReach = REACH / Math.abs(xMajor ? ux : uy);
        // A pixel's distance from the line is |ox dy - oy dx| / length, the numerator an integer
        // (integer ends, integer centres): the coverage depends on it alone, so each is worked out
        // once a line. A one-pixel line's distance is |oy|.
        double nx = length == 0 ? 1 : dx;
        double ny = length == 0 ? 0 : dy;
        double scale = length == 0 ? 1 : length;
        double reachNumerator = REACH * scale;
        boolean remember = reachNumerator < REMEMBERED;
        if (remember) {
            Arrays.fill(byNumerator, 0, (int) reachNumerator + 1, -1);
        }
        for (double m = lo; m <= hi; m++) {
            double centre = minorA + (m - majorA) * slope;
            double first = Math.max(Math.ceil(centre - minorReach), 0);
            double last = Math.min(Math.floor(centre + minorReach), minorLimit - 1);
            for (double n = first; n <= last; n++) {
                double px = xMajor ? m : n;
                double py = xMajor ? n : m;
                double ox = px - ax;
                double oy = py - ay;
                double s = ox * ux + oy * uy;
                if (s < -PAST_END || s > length + PAST_END) {
                    continue;
                }
                double numerator = Math.abs(ox * ny - oy * nx);
                if (numerator >= reachNumerator) {
                    continue;
                }
                double c;
                if (remember) {
                    int key = (int) numerator;
                    c = byNumerator[key];
                    if (c < 0) {
                        c = coverage(numerator / scale);
                        byNumerator[key] = c;
                    }
                } else {
                    c = coverage(numerator / scale);
                }
                if (c <= 0) {
                    continue;
                }
                double t = length == 0 ? 0 : Math.min(Math.max(s / length, 0), 1);
                double k = 1 - t;
                target.cover(c);
                target.setPixel((int) px, (int) py, k * pz + t * qz,
                        oneColour ? colour : Colors.pack(k * pr + t * qr, k * pg + t * qg, k * pb + t * qb));
            }
        }
        target.cover(1);
    }

    /** The drawable behind a coverage blend, made once per drawable. */
    private CoverageDrawable blending(Drawable drawable) {
        if (drawable instanceof CoverageDrawable ready) {
            return ready;
        }
        if (drawable != wrapped) {
            wrapped = drawable;
            blend = new CoverageDrawable(drawable);
        }
        return blend;
    }
}
