package simpview.surface;

import simpview.geometry.Camera;

/**
 * Pixel clipping to the view volume: writes outside the drawable's bounds, or
 * nearer than the camera's near plane or farther than its far plane (z = 0
 * and z = -200 for Part 1's view), are dropped.
 */
public final class ScissorDrawable extends DrawableDecorator {

    // The bounds, read once: width() and height() would otherwise be a call
    // down the whole chain for every span.
    private final int width;
    private final int height;
    private final double near;
    private final double far;

    public ScissorDrawable(Camera camera, Drawable delegate) {
        super(delegate);
        near = camera.hither();
        far = camera.yon();
        width = delegate.width();
        height = delegate.height();
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    private boolean inDepth(double z) {
        return z <= near && z >= far;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        if (x >= 0 && x < width && y >= 0 && y < height && inDepth(z)) {
            delegate.setPixel(x, y, z, argb);
        }
    }

    /**
     * z is linear along the span and its evaluation is monotone in x, so the
     * pixels inside the depth range form one run: trim it from both ends.
     */
    @Override
    public void fillSpan(Span s) {
        if (s.y < 0 || s.y >= height) {
            return;
        }
        int x0 = s.x0;
        int x1 = s.x1;
        int from = Math.max(x0, 0);
        int to = Math.min(x1, width);
        while (from < to && !inDepth(s.zAt(from))) {
            from++;
        }
        while (to > from && !inDepth(s.zAt(to - 1))) {
            to--;
        }
        if (from < to) {
            s.x0 = from;
            s.x1 = to;
            delegate.fillSpan(s);
            s.x0 = x0;
            s.x1 = x1;
        }
    }
}
