package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * What docs/grading.md says of partial scoring and of JPEG, held against the program: the walk-through's
 * 0.26 points step by step from the numbers it gives, the formula's example of a page failing by its pixel
 * count alone, and a right page that fails once saved as JPEG.
 */
class GradingDocTest {

    @TempDir
    Path dir;

    private static String grading() throws Exception {
        return Files.readString(Path.of(System.getProperty("simpview.projectDir", ".")).resolve("docs/grading.md"))
                .replaceAll("\\s+", " ");
    }

    /** The walk-through's rule for pageC: 2 points, 99 % to pass, nothing at 95 %, at most 2,000 failing pixels. */
    private static final RubricRule PAGE_C = new RubricRule("pageC", 8, 1, 99, 2000, 2, 95, Comparison.Metric.EXACT,
            null, "after_published", Comparison.FLIP_THRESHOLD);

    /** A comparison with {@code failing} pixels beyond any slack (the share 1 - failing / 422,500). */
    private static Comparison failing(int failing) {
        int[] stripes = GradingFixtures.stripes(0);
        Comparison c = Comparison.of(stripes, GradingFixtures.spoiled(stripes, failing), 1, Comparison.Metric.EXACT);
        assertEquals(failing, c.failing(8));
        return c;
    }

    @Test
    void theWalkThroughsPartialScoreFollowsFromItsSteps() throws Exception {
        Matcher steps = Pattern.compile("\\(97\\.66 − 95\\) / \\(99 − 95\\) = (0\\.\\d+) .*? multiplied by 2,000 / 9,874 = "
                + "(0\\.\\d+), which makes (0\\.\\d+); times 2 points: (0\\.\\d+), rounded down to hundredths: (0\\.\\d+)\\.").matcher(grading());
        assertTrue(steps.find(), "the steps of bob's pageC score");
        double share = Double.parseDouble(steps.group(1));
        double allowed = Double.parseDouble(steps.group(2));
        double product = Double.parseDouble(steps.group(3));
        double points = Double.parseDouble(steps.group(4));
        double shown = Double.parseDouble(steps.group(5));
        assertEquals((97.66 - 95) / (99 - 95), share, 0.0005);
        assertEquals(2000.0 / 9874, allowed, 0.00005);
        assertEquals(share * 2000 / 9874, product, 0.00005, "each step from the one before");
        assertEquals(2 * product, points, 0.00005);
        assertEquals(Math.floor(points * 100) / 100, shown, 1e-9, "rounded down");
        assertEquals(PAGE_C.score(failing(9874), true), shown, 1e-9, "and the program's score of 9,874 failing pixels");
    }

    @Test
    void theFormulasExampleIsWhatThePageScores() throws Exception {
        String doc = grading();
        assertTrue(doc.contains("points × min(1, max(0, (share − zero) / (min_share − zero))) × allowed / failing"),
                "the formula as the code computes it");
        Matcher example = Pattern.compile("at 99\\.51 % with 2,040 failing pixels where 2,000 are allowed, a 2-point page "
                + "scores 2 × 1 × 2,000 / 2,040 = (\\d\\.\\d\\d)").matcher(doc);
        assertTrue(example.find(), "the capped example");
        Comparison c = failing(2040);
        assertEquals("99.51", Percent.number(c.verdictShare(8)));
        assertEquals(PAGE_C.score(c, true), Double.parseDouble(example.group(1)), 1e-9);
    }

    @Test
    void aRightPageSavedAsJpegCanFail() throws Exception {
        assertTrue(grading().contains("Hand in PNG, not JPEG."), "the warning");
        BufferedImage page = new PageRenderer().renderImage(2, PageContext.defaults());
        Path jpeg = dir.resolve("page2.jpg");
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
        param.setCompressionQuality(0.95f);
        try (ImageOutputStream out = ImageIO.createImageOutputStream(jpeg.toFile())) {
            writer.setOutput(out);
            writer.write(null, new IIOImage(page, null, null), param);
        } finally {
            writer.dispose();
        }
        Comparison c = Comparison.of(Picture.ofPage(page, "page2.png").panel(), Picture.read(jpeg).panel());
        assertEquals(1.0, Comparison.of(Picture.ofPage(page, "page2.png").panel(), Picture.ofPage(page, "page2.png").panel())
                .verdictShare(8), 1e-12, "the page itself");
        assertTrue(c.verdictShare(8) < 0.99, "Java's JPEG at quality 95: " + Percent.of(c.verdictShare(8)));
    }
}
