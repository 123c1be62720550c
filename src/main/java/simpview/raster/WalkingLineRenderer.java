package simpview.raster;

import static simpview.geometry.Vertex.B;
import static simpview.geometry.Vertex.G;
import static simpview.geometry.Vertex.R;
import static simpview.geometry.Vertex.X;
import static simpview.geometry.Vertex.Y;
import static simpview.geometry.Vertex.Z;

import simpview.geometry.Vertex;
import simpview.surface.Colors;
import simpview.surface.Drawable;

/**
 * A line drawn pixel by pixel along a {@link LineWalk}, each pixel written
 * whole (coverage 1): r, g, b and z are lerped per step from the walk's start
 * endpoint to its end, so each end pixel gets exactly its endpoint's colour
 * and depth, and a value both ends share is every pixel's. The walks differ, the writing is this one.
 *
 * <p>One instance reuses its scratch state and is not for use by two threads at once.
 */
public abstract sealed class WalkingLineRenderer implements LineRenderer
        permits DdaLineRenderer, BresenhamLineRenderer {

    private final LineWalk walk;
    /** Room for a line given as vertices, so that both entries share one path. */
    private final double[] ends = new double[2 * Vertex.NUMBERS];

    WalkingLineRenderer(LineWalk walk) {
        this.walk = walk;
    }

    @Override
    public final void drawLine(Vertex p, Vertex q, Drawable drawable) {
        p.writeTo(ends, 0);
        q.writeTo(ends, Vertex.NUMBERS);
        drawLine(ends, 0, Vertex.NUMBERS, drawable);
    }

    @Override
    public final void drawLine(double[] v, int from, int to, Drawable drawable) {
        if (!Vertex.isFinite(v, from) || !Vertex.isFinite(v, to)
                || !walk.start(v[from + X], v[from + Y], v[to + X], v[to + Y], drawable.width(), drawable.height())) {
            return;
        }
        int a = walk.reversed() ? to : from;
        int b = walk.reversed() ? from : to;
        // Colour is left out (black) where the drawable replaces it anyway.
        boolean shaded = drawable.usesColour();
        double az = v[a + Z];
        double bz = v[b + Z];
        double ar = v[a + R];
        double ag = v[a + G];
        double ab = v[a + B];
        double br = v[b + R];
        double bg = v[b + G];
        double bb = v[b + B];
        while (walk.next()) {
            double t = walk.t();
            double s = 1 - t;
            double z = lerp(az, bz, s, t);
            int argb = shaded
                    ? Colors.pack(lerp(ar, br, s, t), lerp(ag, bg, s, t), lerp(ab, bb, s, t))
                    : Colors.BLACK;
            drawable.setPixel(walk.x(), walk.y(), z, argb);
        }
    }

    /**
     * {@code s * a + t * b} (s = 1 - t), which gives each end exactly; but a
     * value the two ends share is kept as it is. The sum would miss it by a
     * last bit at some steps (-100 at both ends gave -100.00000000000001), and a
     * line at one depth, or of one colour, came out in two shades where the
     * depth cue or a channel falls on a rounding tie (127.5 at z = -100).
     * Public for the inspector, which works a line's pixel out by it.
     */
    public static double lerp(double a, double b, double s, double t) {
        return a == b ? a : s * a + t * b;
    }
}
