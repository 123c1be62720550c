package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.testing.CourseFiles;

/**
 * Mistakes of a renderer's colours, made from simpview's own pictures: each is told what it is, and none is told it
 * is another (a light's term left out is no edge a pixel off).
 */
class ColourMistakesTest {

    @TempDir
    Path dir;

    /** Each channel of the page's panel encoded as sRGB, as a renderer that converts linear colours to sRGB writes it. */
    private static BufferedImage encoded(BufferedImage page) {
        BufferedImage out = new BufferedImage(page.getWidth(), page.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                int c = page.getRGB(x, y);
                boolean panel = x >= 50 && x < 700 && y >= 50 && y < 700;
                out.setRGB(x, y, panel ? srgb(c >> 16 & 0xFF) << 16 | srgb(c >> 8 & 0xFF) << 8 | srgb(c & 0xFF) : c);
            }
        }
        return out;
    }

    private static int srgb(int level) {
        double c = level / 255.0;
        return (int) Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055));
    }

    @Test
    void pageFivePutThroughSrgbsGammaIsToldSo() throws Exception {
        Path picture = dir.resolve("page5.png");
        ImageIO.write(encoded(new PageRenderer().renderImage(5, PageContext.defaults())), "png", picture.toFile());
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "5");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nnote: your colours look put through sRGB's gamma: of the 144,034 pixels that "
                + "differ by more than 8/255, 100.00 % are simpview's colours encoded as sRGB (linear to sRGB"), run.out());
        // simpview's own page is told nothing of it
        Path right = dir.resolve("right.png");
        ImageIO.write(new PageRenderer().renderImage(5, PageContext.defaults()), "png", right.toFile());
        assertFalse(CliRun.of("compare", right.toString(), "--page", "5").out().contains("gamma"));
    }

    /**
     * The fourth assignment's page-c3 drawn without its ambient light: its dark side is a few levels darker, and along
     * its shading a neighbour's colour matches, but no edge moved. It was told "edges a pixel off ... the top-left
     * rule" (3.51 % of the panel).
     */
    @Test
    void aLitSceneWithoutItsAmbientLightIsNotToldItsEdgesAreAPixelOff() throws Exception {
        Path course = CourseFiles.require("course-simp-a4");
        Path scene = course.resolve("page-c3.simp");
        String text = Files.readString(scene);
        assertTrue(text.contains("ambient .05 .05 .05"), "page-c3.simp has changed: " + text);
        Path copy = dir.resolve("dark").resolve("page-c3.simp");
        Files.createDirectories(copy.getParent());
        Files.writeString(copy, text.replace("ambient .05 .05 .05", "ambient 0 0 0"));
        Files.copy(course.resolve("bowling.obj"), copy.resolveSibling("bowling.obj"));
        Path picture = dir.resolve("page-c3.png");
        CliRun render = CliRun.of("render", "--scene", copy.toString(), "--out", picture.toString());
        assertEquals(0, render.exitCode(), render.err());
        CliRun run = CliRun.of("compare", picture.toString(), "--scene", scene.toString());
        assertTrue(run.out().contains("\nlook:    x 204, y 216 differs most in patch 1: yours (0,0,0), simpview's (9,4,2)"),
                run.out());
        assertFalse(run.out().contains("edges a pixel off"), run.out());
        assertFalse(run.out().contains("top-left rule"), run.out());
    }

    /** Page 7 drawn with its depth cue's near and far colours swapped: near lines dark, far ones bright. */
    @Test
    void pageSevenWithItsDepthCueRunTheWrongWayIsToldSo() throws Exception {
        Path scene = CourseFiles.require("course-simp").resolve("page7.simp");
        Path picture = dir.resolve("page7.png");
        CliRun render = CliRun.of("render", "--scene", scene.toString(), "--near-color", "0,0,0", "--far-color",
                "1,1,1", "--out", picture.toString());
        assertEquals(0, render.exitCode(), render.err());
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "7", "--simp-dir", scene.getParent().toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nnote: your colours look simpview's turned end for end: of the 176,432 pixels "
                + "that differ by more than 8/255 and are drawn in both, 100.00 % have yours + simpview's = "
                + "(255,255,255) within 8/255, as a depth cue run the wrong way gives"), run.out());
        // page 6 named page 7, white lines on black where simpview's are, is not
        Path six = dir.resolve("six").resolve("page7.png");
        Files.createDirectories(six.getParent());
        CliRun drawn = CliRun.of("render", "--scene", scene.resolveSibling("page6.simp").toString(), "--out",
                six.toString());
        assertEquals(0, drawn.exitCode(), drawn.err());
        String other = CliRun.of("compare", six.toString(), "--page", "7", "--simp-dir",
                scene.getParent().toString()).out();
        assertFalse(other.contains("end for end"), other);
    }
}
