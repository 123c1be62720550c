package simpview.window;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * The magnifier's detail, drawn over the picture from 8x (eight units, {@link ZoomPan#unit}) on: a line along
 * the left and top edge of every image pixel (one unit wide: a point of a desktop scaled by a whole number), and a dot at every pixel's
 * centre (light on dark pixels, dark on light ones), so that where a sample
 * falls can be seen. An overlay only: the image itself is never touched.
 */
public final class PixelGrid {

    /** The grid shows from this zoom on. */
    public static final int FROM_ZOOM = 8;
    /** The grid lines' colour: half-transparent grey, visible on black and on white. */
    public static final Color LINE = new Color(128, 128, 128, 160);
    private static final Color DOT_ON_DARK = new Color(255, 255, 255, 200);
    private static final Color DOT_ON_LIGHT = new Color(0, 0, 0, 200);

    private PixelGrid() {
    }

    public static boolean shows(ZoomPan zoomPan) {
        return zoomPan.isIntegerZoom() && zoomPan.zoom() >= FROM_ZOOM * zoomPan.unit();
    }

    /** Draws the grid over the image pixels that lie inside {@code clip} (screen coordinates). */
    public static void paint(Graphics2D g, ZoomPan zoomPan, BufferedImage image, Rectangle clip) {
        int zoom = (int) zoomPan.zoom();
        int[] cols = visible(zoomPan.originX(), zoom, clip.x, clip.x + clip.width, image.getWidth());
        int[] rows = visible(zoomPan.originY(), zoom, clip.y, clip.y + clip.height, image.getHeight());
        int left = (int) zoomPan.screenX(cols[0]);
        int top = (int) zoomPan.screenY(rows[0]);
        int right = (int) zoomPan.screenX(cols[1]);
        int bottom = (int) zoomPan.screenY(rows[1]);
        // A line is one unit wide, as the dots are so many units: a point of the desktop, as wide as it was before
        // the view was painted in device pixels (at 200 % two of them, not one).
        int line = zoomPan.unit();
        g.setColor(LINE);
        for (int i = cols[0]; i < cols[1]; i++) {
            g.fillRect((int) zoomPan.screenX(i), top, line, bottom - top);
        }
        for (int j = rows[0]; j < rows[1]; j++) {
            g.fillRect(left, (int) zoomPan.screenY(j), right - left, line);
        }
        int unit = zoomPan.unit();
        int dots = zoom >= 16 * unit ? 2 : 1;
        int dot = dots * unit;
        // The dot's place is counted in units too: in device pixels (zoom / 2 - dot / 2), a dot one unit wide at 8x
        // would sit a device pixel left of and above where it sat, and where it sits at 100 %.
        int inset = zoom % unit == 0 ? (zoom / unit / 2 - dots / 2) * unit : zoom / 2 - dot / 2;
        // The dots are written into a picture of the cells in view, copied over the page at once: a fill call a
        // dot took 15 ms a paint at 8x in a 1000x900 view on X11 (14,000 dots), 32 ms into a picture of Java2D's
        // own, and stalled the window at each step to 8x. Each dot lies inside its cell.
        int width = right - left;
        int height = bottom - top;
        if (width <= 0 || height <= 0) {
            return;
        }
        BufferedImage dotsPicture = new BufferedImage(width, height, BufferedImage.TYPE_INT_ARGB);
        int[] dotPixels = ((DataBufferInt) dotsPicture.getRaster().getDataBuffer()).getData();
        int onDark = DOT_ON_DARK.getRGB();
        int onLight = DOT_ON_LIGHT.getRGB();
        for (int j = rows[0]; j < rows[1]; j++) {
            int y = (int) zoomPan.screenY(j) + inset - top;
            for (int i = cols[0]; i < cols[1]; i++) {
                int x = (int) zoomPan.screenX(i) + inset - left;
                int argb = luminance(image.getRGB(i, j)) < 128 ? onDark : onLight;
                for (int row = y * width + x, end = row + dot * width; row < end; row += width) {
                    for (int k = row; k < row + dot; k++) {
                        dotPixels[k] = argb;
                    }
                }
            }
        }
        g.drawImage(dotsPicture, left, top, null);
    }

    /** The image columns (or rows) [from, to) that show between screen coordinates lo and hi. */
    private static int[] visible(double origin, int zoom, int lo, int hi, int size) {
        int from = (int) Math.max(0, Math.floor((lo - origin) / zoom));
        int to = (int) Math.min(size, Math.ceil((hi - origin) / zoom));
        return new int[] {from, Math.max(from, to)};
    }

    private static int luminance(int rgb) {
        return (299 * ((rgb >> 16) & 0xFF) + 587 * ((rgb >> 8) & 0xFF) + 114 * (rgb & 0xFF)) / 1000;
    }
}
