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
 *
 * <p>Screen pixels are the display's own (device) pixels. On a desktop
 * scaled by a whole number (200 %: each of its points two by two pixels),
 * that number is the {@linkplain #unit() unit}: the page at the desktop's
 * own size is one page pixel a point, and that is "1:1" here, what fit
 * starts from, Z and the wheel's steps (each a whole number of units). A
 * desktop scaled by a fraction (125 %, 150 %) has a unit of 1: the page is
 * shown a whole number of device pixels a page pixel, never 1.5, which would
 * draw some page pixels one device pixel wide and others two.
 */
public final class ZoomPan {

    /** The largest zoom the wheel reaches. */
    public static final int MAX_ZOOM = 32;
    /** Wheel steps above 1:1. */
    private static final int[] STEPS = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32};
    /** At least this much of the image stays in view while panning, in units (points of a desktop scaled by a whole number). */
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
    /** Device pixels a page pixel at the desktop's own size: its scale, a whole number, at least 1. */
    private int unit = 1;
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
        resize(width, height, 1);
    }

    /**
     * The viewport changed size, in device pixels, on a desktop whose unit (device pixels a page pixel at
     * its own size) is {@code deviceUnit}; in fit mode the image follows it.
     */
    public void resize(int width, int height, int deviceUnit) {
        if (deviceUnit != unit && !fitting) {
            zoom = Math.max(1, Math.round(zoom / unit)) * (double) deviceUnit;
        }
        unit = Math.max(1, deviceUnit);
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

    /**
     * Back to the fit last chosen: Fit, or Crop when Crop was chosen after it (a zoom or a pan since then leaves
     * that choice as it was). What a new page opens at.
     */
    public void refit() {
        fitting = true;
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

    /** Device pixels a page pixel at the desktop's own size (1:1): its scale as a whole number, at least 1. */
    public int unit() {
        return unit;
    }

    /**
     * One image pixel per screen pixel (per point of a desktop scaled by a
     * whole number), centred on what is in the middle of the view now; when
     * the whole image fits at 1:1, centred in the view.
     */
    public void actualSize() {
        zoomAbout(viewWidth / 2.0, viewHeight / 2.0, unit);
        if (imageSize * unit <= viewWidth && imageSize * unit <= viewHeight) {
            centre();
        }
    }

    /**
     * The zoom at which the whole image fits the viewport: an integer when 1:1 fits, else a fraction.
     * The whole image at 1:1 or more comes first; then the panel alone, larger than the whole image
     * would be; then the whole image at a smaller whole zoom (only where the unit is more than one device
     * pixel); then the panel below one device pixel a page pixel.
     */
    public double fitZoom() {
        int room = Math.min(viewWidth, viewHeight);
        int whole = panelOnly ? 0 : room / imageSize;
        if (whole >= unit) {
            return Math.min(maxZoom(), whole);
        }
        int panel = room / panelSize();
        if (panel > whole) {
            return Math.min(maxZoom(), panel);
        }
        if (whole >= 1) {
            return whole;
        }
        return (double) room / panelSize();
    }

    /** The largest zoom the wheel reaches: 32 units. */
    public int maxZoom() {
        return MAX_ZOOM * unit;
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
        if (from < 1 - 1e-9) {
            return 1;
        }
        for (int step : STEPS) {
            if (step * unit > from + 1e-9) {
                return step * unit;
            }
        }
        return maxZoom();
    }

    private double stepOut(double from) {
        double smallest = Math.min(1, fitZoom());
        for (int k = STEPS.length - 1; k >= 0; k--) {
            if (STEPS[k] * unit < from - 1e-9 && STEPS[k] * unit >= smallest) {
                return STEPS[k] * unit;
            }
        }
        return from > 1 + 1e-9 ? 1 : smallest;
    }

    /** Sets the zoom, keeping the image point under screen point (x, y) under it. */
    public void zoomAbout(double x, double y, double newZoom) {
        double imageX = (x - exactX) / zoom;
        double imageY = (y - exactY) / zoom;
        fitting = false;
        zoom = Math.max(Math.min(1, fitZoom()), Math.min(maxZoom(), newZoom));
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
            exactX = Math.floor((viewWidth - panel) / 2.0 / unit + 1e-9) * unit - Math.floor(margin * zoom + 1e-9);
            exactY = Math.floor((viewHeight - panel) / 2.0 / unit + 1e-9) * unit - Math.floor(margin * zoom + 1e-9);
        } else {
            exactX = Math.floor((viewWidth - shownSize()) / 2.0);
            exactY = Math.floor((viewHeight - shownSize()) / 2.0);
        }
    }

    private void clampOrigin() {
        double size = shownSize();
        double keep = Math.min(KEEP_VISIBLE * unit, size);
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

    /**
     * The screen x of the image's left edge: a whole pixel, so that at an integer zoom pixel edges are exact,
     * and a whole number of units, so that a point of the desktop (where the pointer is) lies in one page pixel.
     */
    public double originX() {
        return Math.floor(exactX / unit) * unit;
    }

    public double originY() {
        return Math.floor(exactY / unit) * unit;
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

    /**
     * Whether the image is shown smaller than 1:1, as {@link #describe} says "below 1:1": less than a unit a
     * page pixel (at 200 % also at one device pixel a page pixel, half the desktop's size).
     */
    public boolean belowOneToOne() {
        return zoom < unit;
    }

    /** Whether each device pixel stands for more than one image pixel: the picture is shrunk to be shown. */
    public boolean belowOneDevicePixel() {
        return zoom < 1;
    }

    /**
     * "1:1", "8x", "1:1, margins cropped", or "below 1:1: 92 %, margins cropped, 1-px lines kept (...)",
     * saying how the smaller picture keeps its lines and how to see it at 1:1.
     */
    public String describe() {
        String crop = cropped() ? ", margins cropped" : "";
        if (!isIntegerZoom()) {
            return "below 1:1: " + Math.round(zoom / unit * 100) + " %" + crop + ", 1-px lines kept (Z: 1:1, drag to scroll)";
        }
        int z = (int) zoom;
        if (z < unit) {
            return "below 1:1: " + Math.round(100.0 * z / unit) + " %" + crop + ", " + z + " screen pixel"
                    + (z == 1 ? "" : "s") + " a page pixel (Z: 1:1)";
        }
        if (z % unit != 0) {
            return z + " screen pixels a page pixel" + crop;
        }
        return (z == unit ? "1:1" : z / unit + "x") + crop;
    }
}
