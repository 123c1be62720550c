package simpview.reference;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;

/**
 * The course's own pictures of the A3 pages (872x782 window captures, the
 * panel at x 51-700, y 81-730) beside the reference's. As a program it
 * prints the shares of agreeing panel pixels and writes side-by-side
 * pictures (ours | the course's) for docs/course-pictures.md:
 * {@code CoursePictures SHARED_DIR OUT_DIR}.
 */
final class CoursePictures {

    static final int PANEL_LEFT = 51;
    static final int PANEL_TOP = 81;

    /** Scene name and the course's picture of it. */
    record Page(String scene, String picture) {
    }

    static final List<Page> PAGES = List.of(new Page("pageA", "pageA"), new Page("pageB", "pageB"),
            new Page("pageC", "pageC"), new Page("pageD", "pageD"), new Page("pageE", "pageE"),
            new Page("pageF", "pageF"), new Page("pageG", "pageG"), new Page("pageH", "pageH"),
            new Page("pageI", "pageI"), new Page("tomsPageJ", "pageJ_tomsPageJ"));

    private CoursePictures() {
    }

    static int[] coursePanel(Path shared, Page page) throws IOException {
        BufferedImage picture = ImageIO.read(shared.resolve("reference/images/a3/" + page.picture() + ".png").toFile());
        return PanelAgreement.panel(picture, PANEL_LEFT, PANEL_TOP);
    }

    static int[] ourPanel(Path shared, Page page) throws IOException {
        return PanelAgreement.pagePanel(ReferencePage.render(shared.resolve("course-simp-a3/" + page.scene() + ".simp")));
    }

    public static void main(String[] args) throws IOException {
        Path shared = Path.of(args[0]);
        Path out = Path.of(args[1]);
        Files.createDirectories(out);
        System.out.println("| page | within 8/255 | 8/255, 1 px slack | within 3/255 | 3/255, 1 px slack |");
        System.out.println("|---|---|---|---|---|");
        for (Page page : PAGES) {
            int[] ours = ourPanel(shared, page);
            int[] theirs = coursePanel(shared, page);
            System.out.printf(Locale.ROOT, "| %s | %.2f %% | %.2f %% | %.2f %% | %.2f %% |%n", page.scene(),
                    100 * PanelAgreement.share(ours, theirs, 8, false), 100 * PanelAgreement.share(ours, theirs, 8, true),
                    100 * PanelAgreement.share(ours, theirs, 3, false), 100 * PanelAgreement.share(ours, theirs, 3, true));
            ImageIO.write(sideBySide(ours, theirs), "png", out.resolve("a3-" + page.scene() + ".png").toFile());
            if (args.length > 2) {
                ImageIO.write(differences(ours, theirs), "png", out.resolve("a3-" + page.scene() + "-diff.png").toFile());
            }
        }
    }

    /** Ours on the left, the course's on the right, 10 white pixels between. */
    static BufferedImage sideBySide(int[] ours, int[] theirs) {
        int n = PanelAgreement.N;
        BufferedImage image = new BufferedImage(2 * n + 10, n, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < 2 * n + 10; x++) {
                int rgb = x < n ? ours[y * n + x] : x >= n + 10 ? theirs[y * n + x - n - 10] : 0xFFFFFF;
                image.setRGB(x, y, rgb);
            }
        }
        return image;
    }

    /** Where they disagree (8/255 with slack) in red over a dimmed copy of ours. */
    static BufferedImage differences(int[] ours, int[] theirs) {
        int n = PanelAgreement.N;
        boolean[] off = PanelAgreement.disagreeing(ours, theirs, 8, true);
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_INT_RGB);
        for (int i = 0; i < n * n; i++) {
            image.setRGB(i % n, i / n, off[i] ? 0xFF0000 : (ours[i] >> 2) & 0x3F3F3F);
        }
        return image;
    }
}
