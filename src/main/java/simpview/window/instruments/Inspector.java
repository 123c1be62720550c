package simpview.window.instruments;

import simpview.pages.A1Marks;
import simpview.pages.A1Pixel;
import simpview.window.render.View;

import simpview.window.render.PageFacts;
import simpview.window.render.RenderedView;

import java.util.Locale;
import simpview.surface.PageCanvas;

/**
 * What the status line says about one pixel of the picture on screen: its
 * panel coordinates (x right, y up, from the panel's bottom-left pixel, as
 * the course counts), its colour in bytes and from 0 to 1, its depth in the
 * z-buffer, and which primitive drew it (file, line, command) or that none
 * did.
 */
public final class Inspector {

    private Inspector() {
    }

    /** Panel x of image column ix. */
    static int panelX(int ix) {
        return ix - PageCanvas.MARGIN;
    }

    /** Panel y of image row iy (y up). */
    static int panelY(int iy) {
        return PageCanvas.MARGIN + PageCanvas.PANEL - 1 - iy;
    }

    static boolean inPanel(int ix, int iy) {
        int x = panelX(ix);
        int y = panelY(iy);
        return x >= 0 && x < PageCanvas.PANEL && y >= 0 && y < PageCanvas.PANEL;
    }

    /** The status line for image pixel (ix, iy) of {@code view}, or null when it is off the image. */
    public static String describe(RenderedView view, int ix, int iy) {
        if (view == null || ix < 0 || iy < 0 || ix >= view.image().getWidth() || iy >= view.image().getHeight()) {
            return null;
        }
        int rgb = view.image().getRGB(ix, iy);
        String colour = colour(rgb);
        if (view.view() instanceof View.OfAssignment1Page page) {
            String facts = A1Pixel.describe(page.number(), view.seed(), view.a1Rule(), ix, iy);
            return facts == null ? "margin (image " + ix + ", " + iy + ") · " + colour
                    : facts.replaceFirst(" · ", " · " + colour + " · ");
        }
        if (!inPanel(ix, iy)) {
            return "margin (image " + ix + ", " + iy + ") · " + colour;
        }
        int x = panelX(ix);
        int y = panelY(iy);
        StringBuilder sb = new StringBuilder();
        sb.append("x ").append(x).append(", y ").append(y).append(" (image row ").append(iy).append(") · ").append(colour);
        PageFacts facts = view.facts();
        if (facts.depths() != null) {
            double z = facts.depths()[y * PageCanvas.PANEL + x];
            sb.append(" · ").append(!DepthPicture.untouched(z, facts.depthStart()) ? "depth " + number(z)
                    : facts.depthStart() == Double.NEGATIVE_INFINITY ? "depth untouched (no write)"
                    : "depth untouched (far plane, " + number(facts.depthStart()) + ")");
        }
        sb.append(" · ").append(drawnBy(facts, y * PageCanvas.PANEL + x));
        return sb.toString();
    }

    /** "rgb 255 128 0": a colour's bytes. */
    public static String rgb(int rgb) {
        return "rgb " + ((rgb >> 16) & 0xFF) + " " + ((rgb >> 8) & 0xFF) + " " + (rgb & 0xFF);
    }

    /** "rgb 255 128 0 = (1.000, 0.502, 0.000)". */
    static String colour(int rgb) {
        int r = (rgb >> 16) & 0xFF;
        int g = (rgb >> 8) & 0xFF;
        int b = rgb & 0xFF;
        return String.format(Locale.ROOT, "rgb %d %d %d = (%.3f, %.3f, %.3f)", r, g, b, r / 255.0, g / 255.0, b / 255.0);
    }

    private static String drawnBy(PageFacts facts, int index) {
        if (facts.owners() == null) {
            return "drawn by: not recorded here";
        }
        int owner = facts.owners()[index];
        if (owner < 0) {
            return "background (no primitive drew it)";
        }
        String order = "drawn by primitive " + (owner + 1) + " of " + facts.primitives().size();
        return owner < facts.primitives().size()
                ? order + ": " + facts.primitives().describe(owner)
                : "drawn by primitive " + (owner + 1);
    }

    /** A depth as the z-buffer holds it, to 4 decimals, without trailing zeros. */
    public static String number(double z) {
        String s = String.format(Locale.ROOT, "%.4f", z);
        s = s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
        return s.equals("-0") ? "0" : s;
    }

    /** The primitive (0, 1, ...) that drew image pixel (ix, iy) of the view, or -1 for none or not recorded. */
    public static int ownerAt(RenderedView view, int ix, int iy) {
        if (view == null || view.facts().owners() == null || !inPanel(ix, iy)) {
            return -1;
        }
        return view.facts().owners()[panelY(iy) * PageCanvas.PANEL + panelX(ix)];
    }

    /**
     * The projected outline, in image coordinates, of the primitive that drew
     * image pixel (ix, iy): what the magnifier draws over the pixels so the
     * top-left rule and the DDA steps can be seen; null when none did.
     */
    public static double[] outlineAt(RenderedView view, int ix, int iy) {
        if (view == null || view.facts().owners() == null || !inPanel(ix, iy)) {
            return null;
        }
        int owner = view.facts().owners()[panelY(iy) * PageCanvas.PANEL + panelX(ix)];
        return owner < 0 || owner >= view.facts().primitives().size()
                ? null : toImage(view.facts().primitives().outline(owner));
    }

    /**
     * On a first-assignment page, what the magnifier draws over the pixels at
     * image pixel (ix, iy): the line that last wrote it as given and between
     * its rounded ends, or its triangle as given; null elsewhere.
     */
    public static A1Marks marksAt(RenderedView view, int ix, int iy) {
        if (view == null || ix < 0 || iy < 0 || !(view.view() instanceof View.OfAssignment1Page page)) {
            return null;
        }
        return A1Pixel.marksAt(page.number(), view.seed(), view.a1Rule(), ix, iy);
    }

    /** Panel points (x, y up) as image points (x, y down): a pixel centre stays a pixel centre. */
    public static double[] toImage(double[] panelPoints) {
        if (panelPoints == null) {
            return null;
        }
        double[] image = panelPoints.clone();
        for (int k = 0; k + 1 < image.length; k += 2) {
            image[k] = PageCanvas.MARGIN + image[k];
            image[k + 1] = PageCanvas.MARGIN + PageCanvas.PANEL - image[k + 1];
        }
        return image;
    }
}
