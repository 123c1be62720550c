package simpview.render;

import simpview.geometry.Vertex;
import simpview.raster.Colors;
import simpview.raster.Drawable;

/**
 * The DDA line: from the pixel holding one endpoint to the pixel holding the
 * other, one pixel per step along the major axis, both ends included. The
 * minor coordinate is the rounded lerp between the two end pixels, so the
 * line is 8-connected in every octant; colour and z are lerped with the same
 * parameter, so each end pixel gets exactly its endpoint's colour and depth.
 *
 * <p>Only the steps whose major coordinate lies on the drawable are visited:
 * a line a billion pixels long costs no more than one across the panel.
 */
public final class DdaLineRenderer implements LineRenderer {

    @Override
    public void drawLine(Vertex p, Vertex q, Drawable drawable) {
        if (!p.isFinite() || !q.isFinite()) {
            return;
        }
        // Pixel indices as doubles: endpoints may lie far beyond int range.
        double x0 = Math.floor(p.x());
        double y0 = Math.floor(p.y());
        double x1 = Math.floor(q.x());
        double y1 = Math.floor(q.y());
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        double major0 = xMajor ? x0 : y0;
        double major1 = xMajor ? x1 : y1;
        double minor0 = xMajor ? y0 : x0;
        double minor1 = xMajor ? y1 : x1;
        int majorLimit = xMajor ? drawable.width() : drawable.height();
        int minorLimit = xMajor ? drawable.height() : drawable.width();

        double steps = Math.abs(major1 - major0);
        double direction = major1 >= major0 ? 1 : -1;
        // Steps k in [0, steps] whose major coordinate major0 + k * direction is on the drawable.
        double kFirst = direction > 0 ? -major0 : major0 - (majorLimit - 1);
        double kLast = direction > 0 ? (majorLimit - 1) - major0 : major0;
        kFirst = Math.max(kFirst, 0);
        kLast = Math.min(kLast, steps);

        for (double k = kFirst; k <= kLast; k++) {
            double t = steps == 0 ? 0 : k / steps;
            double s = 1 - t;
            double minor = Math.floor(minor0 + (minor1 - minor0) * t + 0.5);
            if (minor < 0 || minor >= minorLimit) {
                continue;
            }
            int major = (int) (major0 + k * direction);
            int x = xMajor ? major : (int) minor;
            int y = xMajor ? (int) minor : major;
            double z = s * p.z() + t * q.z();
            int argb = Colors.pack(s * p.r() + t * q.r(), s * p.g() + t * q.g(), s * p.b() + t * q.b());
            drawable.setPixel(x, y, z, argb);
        }
    }
}
