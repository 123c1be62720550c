package simpview.window.instruments;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;
import simpview.surface.PageCanvas;

/**
 * The overdraw overlay: each panel pixel coloured by how many writes reached
 * its depth test ({@link simpview.inspect.Overdraw}), from black (none)
 * through blue, red and yellow to white (the most), with its scale in the
 * top margin: the colour ramp and the counts at its ends and middle. The
 * pixels and the scale's bar are written into the image's array from the
 * counts (each count's colour worked out once); the legend's text is drawn
 * with Java2D, as the window's other overlays' is.
 */
public final class OverdrawPicture {

    private OverdrawPicture() {
    }

    /** The picture of {@code counts} (row by row from the bottom), its legend in the top margin. */
    public static BufferedImage of(int[] counts) {
        return of(counts, "overdraw: writes that reached each pixel's depth test");
    }

    /** The same with another title above the scale (the depth-test failures). */
    public static BufferedImage of(int[] counts, String title) {
        int size = PageCanvas.SIZE;
        int panel = PageCanvas.PANEL;
        int margin = PageCanvas.MARGIN;
        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
        int max = 0;
        for (int c : counts) {
            max = Math.max(max, c);
        }
        // Each count's colour once, then the pixels written straight into the image's array.
        int[] colours = new int[max + 1];
        for (int c = 0; c <= max; c++) {
            colours[c] = heat(c, max);
        }
        int[] data = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        Arrays.fill(data, 0xFFFFFF);
        for (int y = 0; y < panel; y++) {
            int row = (margin + panel - 1 - y) * size + margin;
            int from = y * panel;
            for (int x = 0; x < panel; x++) {
                int c = counts[from + x];
                data[row + x] = c <= 0 ? 0 : colours[c];
            }
        }
        int barLeft = margin;
        int barWidth = panel;
        for (int i = 0; i < barWidth; i++) {
            int count = max == 0 ? 0 : Math.round((float) i * max / (barWidth - 1));
            int colour = colours[count];
            for (int y = 22; y < 32; y++) {
                data[y * size + barLeft + i] = colour;
            }
        }
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.setColor(Color.BLACK);
        g.drawString(title, margin, 16);
        g.drawString("0", barLeft, 46);
        String middle = String.valueOf(max / 2);
        g.drawString(middle, barLeft + barWidth / 2 - g.getFontMetrics().stringWidth(middle) / 2, 46);
        String most = max + (max == 1 ? " write" : " writes");
        g.drawString(most, barLeft + barWidth - g.getFontMetrics().stringWidth(most), 46);
        g.dispose();
        return image;
    }

    /** Black for 0; then blue, red, yellow, white as the count goes up to max. */
    static int heat(int count, int max) {
        if (count <= 0 || max <= 0) {
            return 0x000000;
        }
        double t = max == 1 ? 1 : (count - 1) / (double) (max - 1);
        double[][] stops = {{0.1, 0.2, 1}, {1, 0.1, 0.1}, {1, 0.9, 0.1}, {1, 1, 1}};
        double at = t * (stops.length - 1);
        int i = Math.min((int) at, stops.length - 2);
        double f = at - i;
        int r = (int) Math.round(255 * (stops[i][0] + (stops[i + 1][0] - stops[i][0]) * f));
        int gr = (int) Math.round(255 * (stops[i][1] + (stops[i + 1][1] - stops[i][1]) * f));
        int b = (int) Math.round(255 * (stops[i][2] + (stops[i + 1][2] - stops[i][2]) * f));
        return r << 16 | gr << 8 | b;
    }
}
