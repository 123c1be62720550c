package simpview.compare;

import java.awt.image.BufferedImage;
import java.nio.file.Path;

/**
 * A picture of a page of several square panels (the first assignment's four
 * 300x300 ones) beside simpview's page, panel by panel. The page is found
 * in the picture by its frames: a place where the one-pixel ring just outside
 * each panel is white while the panel's own outermost pixels are mostly dark
 * (a 750x750 page, or a window capture such as the course's, where the page
 * starts at (1, 31)). Shares are without slack: which pixels a line drawer
 * lights is what is being compared. With {@link Comparison.Metric#BLUR} each
 * panel of both pictures is blurred first ({@link Blur}), so that another
 * valid antialiasing (the handout allows any method for panel 4) is measured
 * by what the eye sees at 1:1. With {@link Comparison.Metric#FLIP} a pixel
 * is within when its FLIP value ({@link Flip}, of the two panels) is at most
 * {@link Comparison#FLIP_THRESHOLD}.
 */
public final class PanelGridComparison {

    /** A panel's top-left pixel and side, in page coordinates (rows down). */
    public record Panel(int left, int top, int size) {
    }

    /**
     * One panel's shares, 0 to 1: identical, and within the tolerance in every channel (with FLIP: at most its
     * threshold); and the mistake that changes the whole panel the same way, or null when none explains it.
     */
    public record PanelShares(double identical, double within, SystematicError systematic) {
    }

    private final int pageLeft;
    private final int pageTop;
    private final PanelShares[] shares;

    private PanelGridComparison(int pageLeft, int pageTop, PanelShares[] shares) {
        this.pageLeft = pageLeft;
        this.pageTop = pageTop;
        this.shares = shares;
    }

    /** Where the page's top-left pixel is in the picture. */
    public int pageLeft() {
        return pageLeft;
    }

    public int pageTop() {
        return pageTop;
    }

    /** Panel k's shares, k from 0. */
    public PanelShares shares(int k) {
        return shares[k];
    }

    /** Reads the picture, finds the page in it and compares each panel with simpview's page, pixel for pixel. */
    public static PanelGridComparison of(Path picture, BufferedImage ours, Panel[] panels, int tolerance)
            throws CompareException {
        return of(picture, ours, panels, tolerance, Comparison.Metric.EXACT);
    }

    /** The same, measured by {@code metric}. */
    public static PanelGridComparison of(Path picture, BufferedImage ours, Panel[] panels, int tolerance,
            Comparison.Metric metric) throws CompareException {
        return of(picture, ours, panels, tolerance, metric, Comparison.FLIP_THRESHOLD);
    }

    /** The same, with FLIP a pixel within at {@code flipThreshold} or less. */
    public static PanelGridComparison of(Path picture, BufferedImage ours, Panel[] panels, int tolerance,
            Comparison.Metric metric, double flipThreshold) throws CompareException {
        Cut cut = cut(picture, ours, panels);
        PanelShares[] shares = new PanelShares[panels.length];
        for (int k = 0; k < panels.length; k++) {
            Panel p = panels[k];
            int[] a = cut.ours()[k];
            int[] b = cut.theirs()[k];
            if (metric == Comparison.Metric.BLUR) {
                a = Blur.of(a, p.size());
                b = Blur.of(b, p.size());
            }
            long identical = 0;
            long within = 0;
            float[] flip = metric == Comparison.Metric.FLIP ? Flip.of(a, b, p.size(), p.size()) : null;
            for (int i = 0; i < a.length; i++) {
                int d = Rasters.distance(a[i], b[i]);
                identical += d == 0 ? 1 : 0;
                within += (flip == null ? d <= tolerance : flip[i] <= flipThreshold) ? 1 : 0;
            }
            double n = (double) p.size() * p.size();
            shares[k] = new PanelShares(identical / n, within / n,
                    SystematicError.find(cut.ours()[k], cut.theirs()[k], p.size(), tolerance));
        }
        return new PanelGridComparison(cut.pageLeft(), cut.pageTop(), shares);
    }

    /**
     * A picture's page found and cut into its panels, beside simpview's page cut the same way.
     *
     * @param pageLeft where the page's top-left pixel is in the picture
     * @param pageTop the same, its row
     * @param ours simpview's panels, each size x size pixels row by row from the top
     * @param theirs the picture's panels, the same
     */
    public record Cut(int pageLeft, int pageTop, int[][] ours, int[][] theirs) {
    }

    /** Reads the picture, finds the page in it and cuts both pages into their panels. */
    public static Cut cut(Path picture, BufferedImage ours, Panel[] panels) throws CompareException {
        PngCodec.Pixels theirs = Picture.readPixels(picture);
        return cut(theirs.rgb(), theirs.alpha(), theirs.width(), theirs.height(), picture.toString(), ours, panels);
    }

    /** The same for a picture already read (for its 650x650 panel, which it may not really have). */
    public static Cut cut(Picture theirs, BufferedImage ours, Panel[] panels) throws CompareException {
        return cut(theirs.rgb(), theirs.alpha(), theirs.width(), theirs.height(), theirs.name(), ours, panels);
    }

    /**
     * Whether the picture holds a page of these panels, each framed by a white ring (a page of the
     * first assignment's, which a search for one 650x650 panel can take for one). Cheap: most places
     * fail at their first sample.
     */
    public static boolean holds(Picture theirs, int page, Panel[] panels) {
        try {
            find(theirs.rgb(), theirs.width(), theirs.height(), page, panels, theirs.name());
            return true;
        } catch (CompareException e) {
            return false;
        }
    }

    private static Cut cut(int[] rgb, byte[] alpha, int width, int height, String name, BufferedImage ours,
            Panel[] panels) throws CompareException {
        int page = ours.getWidth();
        int[] at = find(rgb, width, height, page, panels, name);
        for (int k = 0; k < panels.length; k++) {
            Picture.requireOpaque(alpha, width, at[0] + panels[k].left(), at[1] + panels[k].top(), panels[k].size(),
                    name, "panel " + (k + 1));
        }
        int[] mine = Rasters.rgb(ours);
        int[][] a = new int[panels.length][];
        int[][] b = new int[panels.length][];
        for (int k = 0; k < panels.length; k++) {
            Panel p = panels[k];
            a[k] = cut(mine, page, p.left(), p.top(), p.size());
            b[k] = cut(rgb, width, at[0] + p.left(), at[1] + p.top(), p.size());
        }
        return new Cut(at[0], at[1], a, b);
    }

    /** The size x size pixels of {@code rgb} (rows of {@code width}) from (left, top), as one array. */
    private static int[] cut(int[] rgb, int width, int left, int top, int size) {
        int[] out = new int[size * size];
        for (int y = 0; y < size; y++) {
            System.arraycopy(rgb, (top + y) * width + left, out, y * size, size);
        }
        return out;
    }

    /** The first place (rows first, then columns) where every panel is framed; a clear error when there is none. */
    static int[] find(int[] rgb, int width, int height, int page, Panel[] panels, String name) throws CompareException {
        for (int top = 0; top + page <= height; top++) {
            for (int left = 0; left + page <= width; left++) {
                if (framed(rgb, width, left, top, panels)) {
                    return new int[] {left, top};
                }
            }
        }
        throw new CompareException("no page of " + panels.length + " panels of " + panels[0].size() + "x"
                + panels[0].size() + " found in " + name + " (" + width + "x" + height + "): each panel needs a white "
                + "ring around it and a mostly dark edge");
    }

    private static boolean framed(int[] rgb, int width, int left, int top, Panel[] panels) {
        for (Panel p : panels) {
            int x0 = left + p.left();
            int y0 = top + p.top();
            int s = p.size();
            if (x0 < 1 || y0 < 1) {
                return false;
            }
            int dark = 0;
            int samples = 0;
            for (int i = 0; i < s; i += 5) {
                if (!white(rgb[(y0 - 1) * width + x0 + i]) || !white(rgb[(y0 + i) * width + x0 - 1])
                        || !white(rgb[(y0 + s) * width + x0 + i]) || !white(rgb[(y0 + i) * width + x0 + s])) {
                    return false;
                }
                dark += dark(rgb[y0 * width + x0 + i]) ? 1 : 0;
                dark += dark(rgb[(y0 + i) * width + x0]) ? 1 : 0;
                dark += dark(rgb[(y0 + s - 1) * width + x0 + i]) ? 1 : 0;
                dark += dark(rgb[(y0 + i) * width + x0 + s - 1]) ? 1 : 0;
                samples += 4;
            }
            if (2 * dark < samples) {
                return false;
            }
        }
        return true;
    }

    private static boolean white(int rgb) {
        return Rasters.distance(rgb, 0xFFFFFF) <= 16;
    }

    private static boolean dark(int rgb) {
        return Rasters.distance(rgb, 0) <= 64;
    }
}
