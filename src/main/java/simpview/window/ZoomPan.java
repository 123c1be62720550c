package simpview.window;

/**
 * Where the square page image sits in a viewport, and how large: a zoom
 * (screen pixels per image pixel) and the screen position of the image's
 * top-left corner. Pure arithmetic, no Swing; the view asks it and paints.
 *
 * <p>"Fit" follows the viewport: the largest integer zoom at which the whole
 * image fits (1:1 whenever it fits at all); when the whole image does not fit
 * at 1:1 but the panel inside its white margins does, the panel at 1:1 with
 * the margins cropped; else the fraction at which the panel fits, centred.
 * "Crop" ({@link #fitPanel()}) is the same fit made on the panel alone.
 * Zooming or panning leaves fit; {@link #fit()} goes back to it.
 * Integer zooms keep the origin on whole screen pixels, so every image pixel
 * is exactly {@code zoom} by {@code zoom} screen pixels.
 */
public final class ZoomPan {

    /** The largest zoom the wheel reaches. */
    public static final int MAX_ZOOM = 32;
    /** Wheel steps above 1:1. */
    private static final int[] STEPS = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32};
    /** At least this much of the image stays in view while panning, in screen pixels. */
    private static final int KEEP_VISIBLE = 48;

    private final int imageSize;
    /** The white margin around the panel, cropped when the whole image does not fit. */
    private final int margin;
    private int viewWidth;
    private int viewHeight;
    private boolean fitting = true;
    /** The fit is made on the panel alone (Crop), even when the whole image would fit. */
    private boolean panelOnly;
    private double zoom = 1;
    /** The image's top-left corner on screen, unrounded: zooming about a point keeps that point exactly. */
    private double exactX;
    private double exactY;

    /** A square image of {@code imageSize} whose panel lies {@code margin} pixels inside each edge. */
    public ZoomPan(int imageSize, int margin) {
        if (margin < 0 || 2 * margin >= imageSize) {
            throw new IllegalArgumentException("a margin of " + margin + " leaves no panel in " + imageSize);
        }
        this.imageSize = imageSize;
        this.margin = margin;
    }

    /** The viewport changed size; in fit mode the image follows it. */
    public void resize(int width, int height) {
        viewWidth = Math.max(1, width);
        viewHeight = Math.max(1, height);
        if (fitting) {
            zoom = fitZoom();
            centre();
        } else {
            clampOrigin();
        }
    }

    /** Back to fit: the largest integer zoom that shows the whole image, or less when even 1:1 does not fit. */
    public void fit() {
        fitting = true;
        panelOnly = false;
        zoom = fitZoom();
        centre();
    }

    /** Crop: the fit made on the panel alone, its white margins cut off (followed on resize like fit). */
    public void fitPanel() {
        fitting = true;
        panelOnly = true;
        zoom = fitZoom();
        centre();
    }

    /**
     * One image pixel per screen pixel, centred on what is in the middle of
     * the view now; when the whole image fits at 1:1, centred in the view.
     */
    public void actualSize() {
        zoomAbout(viewWidth / 2.0, viewHeight / 2.0, 1);
        if (imageSize <= viewWidth && imageSize <= viewHeight) {
            centre();
        }
    }

    /** The zoom at which the whole image fits the viewport: an integer when 1:1 fits, else a fraction. */
    public double fitZoom() {
        int room = Math.min(viewWidth, viewHeight);
        if (!panelOnly && room >= imageSize) {
            return Math.min(MAX_ZOOM, room / imageSize);
        }
        int panel = panelSize();
        if (room >= panel) {
            return Math.min(MAX_ZOOM, room / panel);
        }
        return (double) room / panel;
    }

    /** The side of the panel: the image without its margins. */
    public int panelSize() {
        return imageSize - 2 * margin;
    }

    /** Whether the fit shown cuts off the margins: the whole image does not fit at the fit's zoom, or Crop is on. */
    public boolean cropped() {
        return fitting && (panelOnly || imageSize * zoom > Math.min(viewWidth, viewHeight));
    }

    /** One wheel notch nearer ({@code notches < 0}) or farther, keeping the image point under (x, y) there. */
    public void wheel(double x, double y, int notches) {
        double next = zoom;
        for (int i = 0; i < Math.abs(notches); i++) {
            next = notches < 0 ? stepIn(next) : stepOut(next);
        }
        zoomAbout(x, y, next);
    }

    private double stepIn(double from) {
        for (int step : STEPS) {
            if (step > from + 1e-9) {
                return step;
            }
        }
        return MAX_ZOOM;
    }

    private double stepOut(double from) {
        double smallest = Math.min(1, fitZoom());
        for (int k = STEPS.length - 1; k >= 0; k--) {
            if (STEPS[k] < from - 1e-9 && STEPS[k] >= smallest) {
                return STEPS[k];
            }
        }
        return smallest;
    }

    /** Sets the zoom, keeping the image point under screen point (x, y) under it. */
    public void zoomAbout(double x, double y, double newZoom) {
        double imageX = (x - exactX) / zoom;
        double imageY = (y - exactY) / zoom;
        fitting = false;
        zoom = Math.max(Math.min(1, fitZoom()), Math.min(MAX_ZOOM, newZoom));
        exactX = x - imageX * zoom;
        exactY = y - imageY * zoom;
        clampOrigin();
    }

    /** Pans, when image pixel (ix, iy) is not wholly in view, so that it is in the middle of the view. */
    public void bringIntoView(int ix, int iy) {
        double left = screenX(ix);
        double top = screenY(iy);
        if (left >= 0 && top >= 0 && left + Math.max(zoom, 1) <= viewWidth && top + Math.max(zoom, 1) <= viewHeight) {
            return;
        }
        pan(viewWidth / 2.0 - (left + zoom / 2), viewHeight / 2.0 - (top + zoom / 2));
    }

    /** Moves the image by (dx, dy) screen pixels; some of it always stays in view. */
    public void pan(double dx, double dy) {
        fitting = false;
        exactX += dx;
        exactY += dy;
        clampOrigin();
    }

    private void centre() {
        if (cropped()) {
            double panel = panelSize() * zoom;
            // The origin is floored when shown: so that the panel's first column and row are not cut, take whole pixels here.
            // (1e-9: a panel that fills the view exactly must not start a pixel early by rounding.)
            exactX = Math.floor((viewWidth - panel) / 2.0 + 1e-9) - Math.floor(margin * zoom + 1e-9);
            exactY = Math.floor((viewHeight - panel) / 2.0 + 1e-9) - Math.floor(margin * zoom + 1e-9);
        } else {
            exactX = Math.floor((viewWidth - shownSize()) / 2.0);
            exactY = Math.floor((viewHeight - shownSize()) / 2.0);
        }
    }

    private void clampOrigin() {
        double size = shownSize();
        double keep = Math.min(KEEP_VISIBLE, size);
        exactX = Math.max(keep - size, Math.min(viewWidth - keep, exactX));
        exactY = Math.max(keep - size, Math.min(viewHeight - keep, exactY));
    }

    /** Width (and height) of the image on screen. */
    public double shownSize() {
        return imageSize * zoom;
    }

    public double zoom() {
        return zoom;
    }

    public boolean isIntegerZoom() {
        return zoom == Math.rint(zoom);
    }

    public boolean fitting() {
        return fitting;
    }

    /** The screen x of the image's left edge: a whole pixel, so that at an integer zoom pixel edges are exact. */
    public double originX() {
        return Math.floor(exactX);
    }

    public double originY() {
        return Math.floor(exactY);
    }

    /** The image column under screen x, or -1 when it is off the image. */
    public int imageX(double x) {
        return toImage(x, originX());
    }

    /** The image row under screen y, or -1 when it is off the image. */
    public int imageY(double y) {
        return toImage(y, originY());
    }

    private int toImage(double screen, double origin) {
        double at = Math.floor((screen - origin) / zoom);
        return at < 0 || at >= imageSize ? -1 : (int) at;
    }

    /** The screen coordinate where image column (or row) i begins, on the x axis. */
    public double screenX(double imageX) {
        return originX() + imageX * zoom;
    }

    public double screenY(double imageY) {
        return originY() + imageY * zoom;
    }

    /** Whether the image is shown smaller than 1:1 (each screen pixel then stands for more than one image pixel). */
    public boolean belowOneToOne() {
        return zoom < 1;
    }

    /**
     * "1:1", "8x", "1:1, margins cropped", or "below 1:1: 92 %, margins cropped, 1-px lines kept (...)",
     * saying how the smaller picture keeps its lines and how to see it at 1:1.
     */
    public String describe() {
        String crop = cropped() ? ", margins cropped" : "";
        if (!isIntegerZoom()) {
            return "below 1:1: " + Math.round(zoom * 100) + " %" + crop + ", 1-px lines kept (Z: 1:1, drag to scroll)";
        }
        int z = (int) zoom;
        return (z == 1 ? "1:1" : z + "x") + crop;
    }
}
