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
 * The DDA line: from the pixel holding one endpoint to the pixel holding the
 * other, one pixel per step along the major axis, both ends included. The
 * minor coordinate is the rounded lerp between the two end pixels, so the
 * line is 8-connected in every octant; colour and z are lerped with the same
 * parameter, so each end pixel gets exactly its endpoint's colour and depth.
 *
 * <p>Only the steps whose major coordinate lies on the drawable are visited:
 * a line a billion pixels long costs no more than one across the panel.
 * One instance reuses its scratch state and is not for use by two threads at once.
 */
public final class DdaLineRenderer implements LineRenderer {

    /** Room for a line given as vertices, so that both entries share one path. */
    private final double[] ends = new double[2 * Vertex.NUMBERS];

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
        double px = v[from + X];
        double py = v[from + Y];
        double pz = v[from + Z];
        double qx = v[to + X];
        double qy = v[to + Y];
        double qz = v[to + Z];
        // Pixel indices as doubles: endpoints may lie far beyond int range.
        double x0 = Math.floor(px);
        double y0 = Math.floor(py);
        double x1 = Math.floor(qx);
        double y1 = Math.floor(qy);
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        double major0 = xMajor ? x0 : y0;
        double major1 = xMajor ? x1 : y1;
        double minor0 = xMajor ? y0 : x0;
        double minor1 = xMajor ? y1 : x1;
        int majorLimit = xMajor ? drawable.width() : drawable.height();
        int minorLimit = xMajor ? drawable.height() : drawable.width();

        // Visit only the major coordinates on the drawable, with an int counter:
        // a double counter stops counting past 2^53 and would never end.
        double lo = Math.max(Math.min(major0, major1), 0);
        double hi = Math.min(Math.max(major0, major1), majorLimit - 1);
        if (lo > hi) {
            return;
        }
        int step = major1 >= major0 ? 1 : -1;
        int first = (int) (step > 0 ? lo : hi);
        int count = (int) (hi - lo) + 1;
        // Halves keep end - start finite for any finite ends; scaling by a
        // power of two is exact, so t and the minor lerp are the same bits as
        // the unscaled (m - major0) / (major1 - major0).
        double halfStart = 0.5 * major0;
        double halfSpan = 0.5 * major1 - 0.5 * major0;
        double halfMinor0 = 0.5 * minor0;
        double halfMinorSpan = 0.5 * minor1 - 0.5 * minor0;
        // Colour is left out (black) where the drawable replaces it anyway.
        boolean shaded = drawable.usesColour();
        double pr = v[from + R];
        double pg = v[from + G];
        double pb = v[from + B];
        double qr = v[to + R];
        double qg = v[to + G];
        double qb = v[to + B];
        for (int n = 0, major = first; n < count; n++, major += step) {
            double t = halfSpan == 0 ? 0 : (0.5 * major - halfStart) / halfSpan;
            double s = 1 - t;
            double minor = Math.floor(2 * (halfMinor0 + halfMinorSpan * t) + 0.5);
            if (minor < 0 || minor >= minorLimit) {
                continue;
            }
            int x = xMajor ? major : (int) minor;
            int y = xMajor ? (int) minor : major;
            double z = s * pz + t * qz;
            int argb = shaded ? Colors.pack(s * pr + t * qr, s * pg + t * qg, s * pb + t * qb) : Colors.BLACK;
            drawable.setPixel(x, y, z, argb);
        }
    }
}
