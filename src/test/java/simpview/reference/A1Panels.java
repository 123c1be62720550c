package simpview.reference;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import javax.imageio.ImageIO;
import simpview.pages.A1Layout;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;

/**
 * simpview's first-assignment pages beside the course's pictures of them
 * (reference/images/a1/pageN.png: window captures, the page's top-left pixel
 * at (1, 31) of the capture), panel by panel. Panels are packed 0xRRGGBB in
 * image order (row 0 at the top), 300x300.
 */
final class A1Panels {

    static final int N = A1Layout.PANEL;
    /** Where the page's top-left pixel is in the course's captures. */
    static final int CAPTURE_LEFT = 1;
    static final int CAPTURE_TOP = 31;

    private A1Panels() {
    }

    static BufferedImage coursePicture(Path shared, int page) throws IOException {
        return ImageIO.read(shared.resolve("reference/images/a1/page" + page + ".png").toFile());
    }

    static BufferedImage ourPage(int page, A1Rule rule) {
        PageCanvas canvas = new PageCanvas();
        try {
            Assignment1.page(page).draw(canvas, PageContext.defaults().withA1Rule(rule));
        } catch (SceneException e) {
            throw new AssertionError("the first assignment's pages read no files", e);
        }
        return canvas.snapshot();
    }

    /** Panel k (1..4) of a page whose top-left pixel is at (left, top) of the image. */
    static int[] panel(BufferedImage image, int left, int top, int k) {
        int[] out = new int[N * N];
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                out[y * N + x] = image.getRGB(left + A1Layout.left(k) + x, top + A1Layout.top(k) + y) & 0xFFFFFF;
            }
        }
        return out;
    }

    static int[] ourPanel(BufferedImage page, int k) {
        return panel(page, 0, 0, k);
    }

    static int[] coursePanel(BufferedImage capture, int k) {
        return panel(capture, CAPTURE_LEFT, CAPTURE_TOP, k);
    }

    /** The share in [0, 1] of pixels whose colours are within `tolerance` per channel. */
    static double share(int[] ours, int[] theirs, int tolerance) {
        int agreeing = 0;
        for (int i = 0; i < ours.length; i++) {
            agreeing += PanelAgreement.close(ours[i], theirs[i], tolerance) ? 1 : 0;
        }
        return agreeing / (double) ours.length;
    }

    /** The share in [0, 1] of pixels that are black in both or in neither: the same geometry. */
    static double sameGeometry(int[] ours, int[] theirs) {
        int agreeing = 0;
        for (int i = 0; i < ours.length; i++) {
            agreeing += (ours[i] == 0) == (theirs[i] == 0) ? 1 : 0;
        }
        return agreeing / (double) ours.length;
    }

    /**
     * simpview's page | the course's page | a heat map of the four panels:
     * grey where identical (dark where both are black), blue within 8/255,
     * red beyond. Only for the docs: these are not page pixels.
     */
    static BufferedImage beside(BufferedImage ours, BufferedImage capture) {
        int size = PageCanvas.SIZE;
        BufferedImage out = new BufferedImage(3 * size, size, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                int a = ours.getRGB(x, y) & 0xFFFFFF;
                int b = capture.getRGB(CAPTURE_LEFT + x, CAPTURE_TOP + y) & 0xFFFFFF;
                out.setRGB(x, y, a);
                out.setRGB(size + x, y, b);
                int heat;
                if (A1Layout.panelAt(x, y) == 0) {
                    heat = 0xFFFFFF;
                } else if (a == b) {
                    heat = a == 0 ? 0x202020 : 0x808080;
                } else if (PanelAgreement.close(a, b, 8)) {
                    heat = 0x3050FF;
                } else {
                    heat = 0xFF2020;
                }
                out.setRGB(2 * size + x, y, heat);
            }
        }
        return out;
    }

    /**
     * Prints every page's panel shares under both rules: identical, within
     * 8/255, same geometry; with a folder, writes the pages there (SPEC's rule
     * as a1-pageN.png, the course's as a1-pageN-course.png where it draws the
     * page otherwise).
     */
    public static void main(String[] args) throws IOException {
        Path shared = Path.of(args.length > 0 ? args[0] : "../shared");
        for (A1Rule rule : A1Rule.values()) {
            for (int page = 1; page <= Assignment1.COUNT; page++) {
                BufferedImage ours = ourPage(page, rule);
                BufferedImage theirs = coursePicture(shared, page);
                boolean differs = rule == A1Rule.SPEC || !Arrays.equals(
                        ours.getRGB(0, 0, ours.getWidth(), ours.getHeight(), null, 0, ours.getWidth()),
                        ourPage(page, A1Rule.SPEC).getRGB(0, 0, ours.getWidth(), ours.getHeight(), null, 0, ours.getWidth()));
                if (args.length > 1 && differs) {
                    String name = "a1-page" + page + (rule == A1Rule.SPEC ? "" : "-" + rule.key()) + ".png";
                    ImageIO.write(beside(ours, theirs), "png", Path.of(args[1], name).toFile());
                }
                StringBuilder line = new StringBuilder(rule.key() + " page " + page + ":");
                for (int k = 1; k <= 4; k++) {
                    int[] a = ourPanel(ours, k);
                    int[] b = coursePanel(theirs, k);
                    line.append(String.format(Locale.ROOT, "  panel %d %.2f / %.2f / %.2f", k, 100 * share(a, b, 0),
                            100 * share(a, b, 8), 100 * sameGeometry(a, b)));
                }
                System.out.println(line);
            }
        }
    }
}
