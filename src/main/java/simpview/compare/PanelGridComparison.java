package simpview.compare;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A picture of a page of several square panels (the first assignment's four
 * 300x300 ones) found and cut into its panels beside simpview's page, for
 * comparing panel by panel ({@link Comparison}, without slack: which pixels a
 * line drawer lights is what is being compared). The page is found in the
 * picture by its frames: a place where the one-pixel ring just outside each
 * panel is white while the panel's own outermost pixels are mostly dark (a
 * 750x750 page, or a window capture such as the course's, where the page
 * starts at (1, 31)); only the panels and their rings need be in the picture.
 * A picture without such a place is refused with what it holds instead.
 */
public final class PanelGridComparison {

    /** A panel's top-left pixel and side, in page coordinates (rows down). */
    public record Panel(int left, int top, int size) {
    }

    /**
     * A picture's page found and cut into its panels, beside simpview's page cut the same way.
     *
     * @param pageLeft where the page's top-left pixel is in the picture
     * @param pageTop the same, its row
     * @param ours simpview's panels, each size x size pixels row by row from the top
     * @param theirs the picture's panels, the same
     * @param width the picture's width
     * @param height its height
     * @param page the page's side
     * @param format the format the picture's bytes were decoded as ({@link Picture#format}); null for one in memory
     */
    public record Cut(int pageLeft, int pageTop, int[][] ours, int[][] theirs, int width, int height, int page,
            PictureFormat format) {

        /**
         * Where the page is in the picture: "top-left at x 1, y 31 of the picture, counted from its top-left", and
         * when the page runs past the picture's edges, by how much ({@link #runsPast}).
         */
        public String describe() {
            String past = runsPast();
            return "top-left at x " + pageLeft + ", y " + pageTop + " of the picture, counted from its top-left"
                    + (past.isEmpty() ? "" : "; " + past);
        }

        /**
         * When the page runs past the picture's edges (drawn a pixel off in it, or cut a pixel short), by how much:
         * "the page runs past the picture's right edge by 1 px (...)"; else "".
         */
        public String runsPast() {
            List<String> past = new ArrayList<>();
            addPast(past, -pageLeft, "left");
            addPast(past, pageLeft + page - width, "right");
            addPast(past, -pageTop, "top");
            addPast(past, pageTop + page - height, "bottom");
            return past.isEmpty() ? "" : "the page runs past the picture's " + Sentence.listed(past)
                    + " (its margins are cut there; its panels are whole)";
        }

        private static void addPast(List<String> past, int pixels, String edge) {
            if (pixels > 0) {
                past.add(edge + " edge by " + pixels + " px");
            }
        }
    }

    /** Reads the picture, finds the page in it and cuts both pages into their panels. */
    public static Cut cut(Path picture, BufferedImage ours, Panel[] panels) throws CompareException {
        PngCodec.Pixels theirs = Picture.readPixels(picture);
        return cut(theirs.rgb(), theirs.alpha(), theirs.width(), theirs.height(), picture.toString(), ours, panels,
                theirs.format());
    }

    /** The same for a picture already read (for its 650x650 panel, which it may not really have). */
    public static Cut cut(Picture theirs, BufferedImage ours, Panel[] panels) throws CompareException {
        return cut(theirs.rgb(), theirs.alpha(), theirs.width(), theirs.height(), theirs.name(), ours, panels,
                theirs.format());
    }

    /**
     * Whether the picture holds a page of these panels, each framed by a white ring (a page of the
     * first assignment's, which a search for one 650x650 panel can take for one). Cheap: most places
     * fail at their first sample.
     */
    public static boolean holds(Picture theirs, Panel[] panels) {
        return place(theirs.rgb(), theirs.width(), theirs.height(), panels) != null;
    }

    /**
     * Whether the picture file holds a page of these panels: false too when it cannot be read (the caller has
     * said why already).
     */
    public static boolean holds(Path picture, Panel[] panels) {
        try {
            PngCodec.Pixels pixels = Picture.readPixels(picture);
            return place(pixels.rgb(), pixels.width(), pixels.height(), panels) != null;
        } catch (CompareException e) {
            return false;
        }
    }

    private static Cut cut(int[] rgb, byte[] alpha, int width, int height, String name, BufferedImage ours,
            Panel[] panels, PictureFormat format) throws CompareException {
        int page = ours.getWidth();
        int[] at;
        try {
            at = find(rgb, width, height, page, panels, name);
        } catch (CompareException e) {
            if (format != PictureFormat.JPEG) {
                throw e;
            }
            // the rings are looked for within 16/255 of white: a JPEG's ringing beside the panels' edges is more
            throw new CompareException(e.getMessage() + "; it holds a JPEG, whose lossy compression changes the "
                    + "white around each panel: save the page as PNG and compare again", e);
        }
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
        return new Cut(at[0], at[1], a, b, width, height, page, format);
    }

    /** simpview's page cut into its panels, as {@link Cut#ours} holds them: another page to lay a picture's panels on. */
    public static int[][] panels(BufferedImage page, Panel[] panels) {
        int[] rgb = Rasters.rgb(page);
        int[][] cut = new int[panels.length][];
        for (int k = 0; k < panels.length; k++) {
            cut[k] = cut(rgb, page.getWidth(), panels[k].left(), panels[k].top(), panels[k].size());
        }
        return cut;
    }

    /** The size x size pixels of {@code rgb} (rows of {@code width}) from (left, top), as one array. */
    private static int[] cut(int[] rgb, int width, int left, int top, int size) {
        int[] out = new int[size * size];
        for (int y = 0; y < size; y++) {
            System.arraycopy(rgb, (top + y) * width + left, out, y * size, size);
        }
        return out;
    }

    /**
     * The first place (rows first, then columns) where every panel is framed; a clear error, saying what was found
     * instead, when there is none. Only the panels and the rings around them need be in the picture: a page drawn a
     * pixel off in its picture, or cut a pixel short, still has its margins' inner edges.
     */
    static int[] find(int[] rgb, int width, int height, int page, Panel[] panels, String name) throws CompareException {
        int[] place = place(rgb, width, height, panels);
        if (place != null) {
            return place;
        }
        throw new CompareException("no page of " + panels.length + " panels of " + panels[0].size() + "x"
                + panels[0].size() + " found in " + name + " (" + width + "x" + height + "): "
                + notFound(rgb, width, height, page, panels));
    }

    /** The first place (rows first, then columns) where every panel is framed, or null. */
    private static int[] place(int[] rgb, int width, int height, Panel[] panels) {
        int need = 0;
        for (Panel p : panels) {
            need = Math.max(need, darkNeeded(p.size()));
        }
        if (fewerDark(rgb, need)) {
            return null; // some panel can be mostly dark nowhere: a white picture, say
        }
        Span span = Span.of(panels);
        for (int top = 1 - span.top(); top + span.bottom() < height; top++) {
            for (int left = 1 - span.left(); left + span.right() < width; left++) {
                if (framed(rgb, width, left, top, panels)) {
                    return new int[] {left, top};
                }
            }
        }
        return null;
    }

    /**
     * The page's columns and rows its panels and their rings take (relative to the page's top-left): the rings'
     * inner column is {@code left - 1}, their outer one {@code right}; rows the same.
     */
    private record Span(int left, int top, int right, int bottom) {

        static Span of(Panel[] panels) {
            int left = Integer.MAX_VALUE;
            int top = Integer.MAX_VALUE;
            int right = Integer.MIN_VALUE;
            int bottom = Integer.MIN_VALUE;
            for (Panel p : panels) {
                left = Math.min(left, p.left());
                top = Math.min(top, p.top());
                right = Math.max(right, p.left() + p.size());
                bottom = Math.max(bottom, p.top() + p.size());
            }
            return new Span(left, top, right, bottom);
        }
    }

    /**
     * What a picture without the page holds instead, as far as can be told: smaller than a page, a page's shape at
     * another size (saved scaled), or some of the panels framed where others are not, and why those are not.
     */
    private static String notFound(int[] rgb, int width, int height, int page, Panel[] panels) {
        String scaled = PanelFinder.scaled(width, height);
        if (width < page || height < page) {
            return "it is smaller than a page (" + page + "x" + page + ")" + scaled;
        }
        String rule = "each panel needs a white ring around it and a mostly dark edge";
        if (!scaled.isEmpty()) {
            return rule + scaled;
        }
        Span span = Span.of(panels);
        int most = 0;
        // a picture of a page's size is looked at where a page has its panels, when nothing better is found
        int[] best = width == page && height == page ? new int[] {0, 0} : null;
        int need = Integer.MAX_VALUE;
        for (Panel p : panels) {
            need = Math.min(need, darkNeeded(p.size()));
        }
        // where no panel can be mostly dark anywhere, none is framed anywhere: the search would find nothing
        int from = fewerDark(rgb, need) ? height : 1 - span.top();
        for (int top = from; top + span.bottom() < height; top++) {
            for (int left = 1 - span.left(); left + span.right() < width; left++) {
                int framed = 0;
                for (Panel p : panels) {
                    framed += problem(rgb, width, left + p.left(), top + p.top(), p.size()) == null ? 1 : 0;
                }
                if (framed > most) {
                    most = framed;
                    best = new int[] {left, top};
                }
            }
        }
        String eightPages = PanelFinder.holdsOnePanel(rgb, width, height) ? "; it holds one 650x650 panel, as a page of "
                + "the eight pages does: compare it with one of those (--page N without --assignment 1)" : "";
        if (best == null) {
            return rule + eightPages;
        }
        List<Integer> framed = new ArrayList<>();
        List<String> why = new ArrayList<>();
        for (int k = 0; k < panels.length; k++) {
            Panel p = panels[k];
            int x0 = best[0] + p.left();
            int y0 = best[1] + p.top();
            String problem = problem(rgb, width, x0, y0, p.size());
            if (problem == null) {
                framed.add(k + 1);
            } else {
                why.add("panel " + (k + 1) + " (x " + x0 + "-" + (x0 + p.size() - 1) + ", y " + y0 + "-"
                        + (y0 + p.size() - 1) + " of the picture): " + problem);
            }
        }
        if (framed.isEmpty()) {
            // the first panel says what is wrong; the others are most likely so for the same reason
            return "no panel is framed where a " + page + "x" + page + " page has them; " + why.get(0) + eightPages;
        }
        return PanelWords.panels(framed) + (framed.size() == 1 ? " is" : " are") + " framed with the page's top-left at x " + best[0] + ", y " + best[1] + " of the picture, but not "
                + String.join("; nor ", why) + eightPages;
    }

    /** "1", "1 and 3", "1, 3 and 4". */
    private static boolean framed(int[] rgb, int width, int left, int top, Panel[] panels) {
        for (Panel p : panels) {
            int x0 = left + p.left();
            int y0 = top + p.top();
            if (ringBreak(rgb, width, x0, y0, p.size()) >= 0 || !mostlyDark(rgb, width, x0, y0, p.size())) {
                return false;
            }
        }
        return true;
    }

    /**
     * Why the square of side {@code s} at (x0, y0) is not a framed panel, or null when it is: the one-pixel ring
     * just outside it white, its own outermost pixels mostly dark. The ring must lie in the picture.
     */
    private static String problem(int[] rgb, int width, int x0, int y0, int s) {
        int at = ringBreak(rgb, width, x0, y0, s);
        if (at >= 0) {
            int colour = rgb[at];
            return "the ring of pixels just outside it is not white (at x " + at % width + ", y " + at / width + ": rgb "
                    + (colour >> 16 & 0xFF) + " " + (colour >> 8 & 0xFF) + " " + (colour & 0xFF) + ")";
        }
        return mostlyDark(rgb, width, x0, y0, s) ? null
                : "its outermost pixels are mostly light, where a panel's are mostly dark (black where nothing is drawn)";
    }

    /**
     * The first pixel (its index in {@code rgb}) of the ring just outside the square of side {@code s} at (x0, y0)
     * that is not white, sampling every fifth along each side; -1 when all are white. Most places of a search fail
     * at their first sample.
     */
    private static int ringBreak(int[] rgb, int width, int x0, int y0, int s) {
        for (int i = 0; i < s; i += 5) {
            int above = (y0 - 1) * width + x0 + i;
            int before = (y0 + i) * width + x0 - 1;
            int below = (y0 + s) * width + x0 + i;
            int after = (y0 + i) * width + x0 + s;
            if (!white(rgb[above])) {
                return above;
            }
            if (!white(rgb[before])) {
                return before;
            }
            if (!white(rgb[below])) {
                return below;
            }
            if (!white(rgb[after])) {
                return after;
            }
        }
        return -1;
    }

    /** Whether the square's own outermost pixels, sampled every fifth, are at least half dark. */
    private static boolean mostlyDark(int[] rgb, int width, int x0, int y0, int s) {
        int dark = 0;
        int samples = 0;
        for (int i = 0; i < s; i += 5) {
            dark += dark(rgb[y0 * width + x0 + i]) ? 1 : 0;
            dark += dark(rgb[(y0 + i) * width + x0]) ? 1 : 0;
            dark += dark(rgb[(y0 + s - 1) * width + x0 + i]) ? 1 : 0;
            dark += dark(rgb[(y0 + i) * width + x0 + s - 1]) ? 1 : 0;
            samples += 4;
        }
        return 2 * dark >= samples;
    }

    /**
     * The fewest dark pixels a picture must have for a square of side {@code s} to be mostly dark anywhere in it
     * ({@link #mostlyDark}): half its samples, and a pixel is sampled at most once by each of the four sides.
     */
    private static int darkNeeded(int s) {
        int samples = 4 * ((s + 4) / 5);
        return (samples + 7) / 8;
    }

    /** Whether the picture has fewer than {@code count} dark pixels, counted only as far as that. */
    private static boolean fewerDark(int[] rgb, int count) {
        int dark = 0;
        for (int i = 0; i < rgb.length && dark < count; i++) {
            dark += dark(rgb[i]) ? 1 : 0;
        }
        return dark < count;
    }

    private static boolean white(int rgb) {
        return Rasters.distance(rgb, 0xFFFFFF) <= 16;
    }

    private static boolean dark(int rgb) {
        return Rasters.distance(rgb, 0) <= 64;
    }
}
