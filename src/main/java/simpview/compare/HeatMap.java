package simpview.compare;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;

/**
 * Pictures of a comparison. The heat map colours each panel pixel by how it
 * differs: identical pixels show our picture dimmed to a quarter, in grey (so
 * one sees where one is); pixels that differ but within the tolerance are dark
 * blue; pixels beyond it that match with one pixel of slack (an edge or a line
 * one pixel off) are yellow; pixels beyond the tolerance even with slack are
 * red, the brighter the larger the difference. With the FLIP metric, yellow
 * is a pixel beyond the tolerance that FLIP forgives, and red one above
 * FLIP's threshold, the brighter the larger its FLIP value.
 */
public final class HeatMap {

    public static final int IDENTICAL_DIM = 4;
    public static final int WITHIN = 0x0000A0;
    public static final int SLACK_ONLY = 0xD0D000;
    /** Gap between the three panels of a diff image, in mid grey. */
    public static final int GAP = 10;
    public static final int GAP_COLOUR = 0x808080;
    public static final int DIFF_WIDTH = 3 * Comparison.N + 2 * GAP;

    private HeatMap() {
    }

    /** The heat map's colour of panel pixel i. */
    public static int colour(Comparison c, int i, int tolerance) {
        int d = c.distance(i);
        if (d == 0) {
            int rgb = c.ours()[i];
            int grey = ((rgb >> 16 & 0xFF) + (rgb >> 8 & 0xFF) + (rgb & 0xFF)) / (3 * IDENTICAL_DIM);
            return grey << 16 | grey << 8 | grey;
        }
        if (c.metric() == Comparison.Metric.FLIP) {
            if (!c.fails(i, tolerance)) {
                return d <= tolerance ? WITHIN : SLACK_ONLY;
            }
            return (128 + (int) Math.round(c.flip(i) * 127)) << 16;
        }
        if (d <= tolerance) {
            return WITHIN;
        }
        int s = c.distanceWithSlack(i);
        if (s <= tolerance) {
            return SLACK_ONLY;
        }
        return (128 + s / 2) << 16;
    }

    /** The width of a diff image of panels of {@code size} pixels: three panels and two gaps. */
    public static int diffWidth(int size) {
        return 3 * size + 2 * GAP;
    }

    /** Writes the heat map into {@code into}, the panel's size squared, row by row from the top. */
    public static void fill(Comparison c, int tolerance, int[] into) {
        for (int i = 0; i < c.size() * c.size(); i++) {
            into[i] = colour(c, i, tolerance);
        }
    }

    /** Ours | theirs | heat map, each panel at 1:1, with a grey gap of 10 pixels between them. */
    public static BufferedImage diffImage(Comparison c, int tolerance) {
        BufferedImage image = new BufferedImage(diffWidth(c.size()), c.size(), BufferedImage.TYPE_INT_RGB);
        fillDiff(c, tolerance, ((DataBufferInt) image.getRaster().getDataBuffer()).getData());
        return image;
    }

    /** The diff image as PNG file bytes, made without ImageIO (fast to start, fast to deflate). */
    public static byte[] diffPng(Comparison c, int tolerance) {
        int[] pixels = new int[diffWidth(c.size()) * c.size()];
        fillDiff(c, tolerance, pixels);
        return PngCodec.encode(diffWidth(c.size()), c.size(), pixels);
    }

    /**
     * A page of panels compared one by one (the first assignment's four) as ours | theirs | heat map, each the whole
     * page at 1:1, white around the panels, with a grey gap of 10 pixels between them: panel k's comparison is drawn
     * at its place in all three (their picture's panels, not its margins, which are not compared). PNG file bytes.
     *
     * @param panels each panel's comparison, in the order of {@code places}
     * @param places where each panel is in the page, rows down
     * @param page the page's side in pixels
     */
    public static byte[] pageDiffPng(Comparison[] panels, PanelGridComparison.Panel[] places, int page, int tolerance) {
        int width = diffWidth(page);
        int[] out = new int[width * page];
        Arrays.fill(out, 0xFFFFFF);
        for (int y = 0; y < page; y++) {
            Arrays.fill(out, y * width + page, y * width + page + GAP, GAP_COLOUR);
            Arrays.fill(out, y * width + 2 * page + GAP, y * width + 2 * page + 2 * GAP, GAP_COLOUR);
        }
        for (int k = 0; k < panels.length; k++) {
            Comparison c = panels[k];
            int n = c.size();
            int[] heat = new int[n * n];
            fill(c, tolerance, heat);
            PanelGridComparison.Panel place = places[k];
            for (int y = 0; y < n; y++) {
                int row = (place.top() + y) * width + place.left();
                System.arraycopy(c.ours(), y * n, out, row, n);
                System.arraycopy(c.theirs(), y * n, out, row + page + GAP, n);
                System.arraycopy(heat, y * n, out, row + 2 * (page + GAP), n);
            }
        }
        return PngCodec.encode(width, page, out);
    }

    private static void fillDiff(Comparison c, int tolerance, int[] out) {
        int n = c.size();
        int width = diffWidth(n);
        int[] heat = new int[n * n];
        fill(c, tolerance, heat);
        for (int y = 0; y < n; y++) {
            int row = y * width;
            System.arraycopy(c.ours(), y * n, out, row, n);
            Arrays.fill(out, row + n, row + n + GAP, GAP_COLOUR);
            System.arraycopy(c.theirs(), y * n, out, row + n + GAP, n);
            Arrays.fill(out, row + 2 * n + GAP, row + 2 * n + 2 * GAP, GAP_COLOUR);
            System.arraycopy(heat, y * n, out, row + 2 * n + 2 * GAP, n);
        }
    }

    /** A 650x650 panel as a 750x750 page with white margins, for showing in place of a page. */
    public static BufferedImage asPage(int[] panel) {
        int size = PanelFinder.PAGE;
        int margin = PanelFinder.PAGE_MARGIN;
        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
        int[] out = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        Arrays.fill(out, 0xFFFFFF);
        for (int y = 0; y < Comparison.N; y++) {
            System.arraycopy(panel, y * Comparison.N, out, (margin + y) * size + margin, Comparison.N);
        }
        return image;
    }
}
