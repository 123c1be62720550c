package simpview.surface;

/**
 * The panel inside the page margins, in panel coordinates: origin at the
 * panel's bottom-left pixel, y up. Moves each write to image coordinates;
 * writes outside the panel are dropped so they never touch the margins.
 */
public final class PanelDrawable extends DrawableDecorator {

    private final int left;
    private final int top;
    private final int size;

    /** A square panel of {@code size} pixels whose top-left pixel is (left, top) in the image. */
    public PanelDrawable(Drawable image, int left, int top, int size) {
        super(image);
        this.left = left;
        this.top = top;
        this.size = size;
    }

    @Override
    public int width() {
        return size;
    }

    @Override
    public int height() {
        return size;
    }

    private boolean inside(int x, int y) {
        return x >= 0 && x < size && y >= 0 && y < size;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        if (inside(x, y)) {
            delegate.setPixel(left + x, imageRow(y), z, argb);
        }
    }

    /** The part of the run inside the panel, moved to image coordinates in one call. */
    @Override
    public void setRun(int x, int y, int count, double[] depths, int[] colours, int at) {
        if (y < 0 || y >= size) {
            return;
        }
        int from = Math.max(x, 0);
        int to = Math.min(x + count, size);
        if (from < to) {
            delegate.setRun(left + from, imageRow(y), to - from, depths, colours, at + (from - x));
        }
    }

    @Override
    public int getPixel(int x, int y) {
        return inside(x, y) ? delegate.getPixel(left + x, imageRow(y)) : 0;
    }

    private int imageRow(int y) {
        return top + size - 1 - y;
    }

    @Override
    public void fillSpan(Span s) {
        if (s.y < 0 || s.y >= size) {
            return;
        }
        int y = s.y;
        int x0 = s.x0;
        int x1 = s.x1;
        int xBase = s.xBase;
        s.x0 = left + Math.max(x0, 0);
        s.x1 = left + Math.min(x1, size);
        s.xBase = left + xBase;
        s.y = imageRow(y);
        if (s.x0 < s.x1) {
            delegate.fillSpan(s);
        }
        s.y = y;
        s.x0 = x0;
        s.x1 = x1;
        s.xBase = xBase;
    }
}
