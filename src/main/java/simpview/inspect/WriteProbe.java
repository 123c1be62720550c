package simpview.inspect;

import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.Span;

/**
 * A decorator that tells the watch of every write reaching it at the one
 * inspected pixel, then passes every write on unchanged. Placed at several
 * points of the depth-cued chain (before the scissor, after it, after the
 * z-buffer, after the depth cue), it shows how far each write got.
 */
final class WriteProbe extends DrawableDecorator {

    /** Where in the chain a probe stands. */
    enum Point { ATTEMPTED, IN_RANGE, PASSED_DEPTH, SHOWN }

    private final PixelWatch watch;
    private final Point point;
    private final int x;
    private final int y;

    WriteProbe(PixelWatch watch, Point point, Drawable delegate) {
        super(delegate);
        this.watch = watch;
        this.point = point;
        this.x = watch.x();
        this.y = watch.y();
    }

    @Override
    public void setPixel(int px, int py, double z, int argb) {
        if (px == x && py == y) {
            watch.reached(point, z, argb, null);
        } else if (point == Point.ATTEMPTED) {
            return;
        }
        delegate.setPixel(px, py, z, argb);
    }

    @Override
    public void fillSpan(Span s) {
        if (s.y == y && s.x0 <= x && x < s.x1) {
            int k = x - s.xBase;
            watch.reached(point, s.zAt(x), s.argbAt(x), new double[] {s.r + k * s.dr, s.g + k * s.dg, s.b + k * s.db});
        } else if (point == Point.ATTEMPTED) {
            return;
        }
        delegate.fillSpan(s);
    }
}
