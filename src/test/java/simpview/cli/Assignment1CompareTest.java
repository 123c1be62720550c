package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
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
import simpview.pages.A1Layout;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.testing.CourseFiles;

/** {@code compare --assignment 1}: the page found in a picture, and shares panel by panel. */
class Assignment1CompareTest {

    @TempDir
    Path dir;

    /**
     * A page that fails points to one pixel and to the inspect command that explains it, in page coordinates; that
     * command runs, and check names the same compare command once for the picture. Panel 1 of page 1 gets a grey
     * 40x40 square in its empty bottom-left corner (every pixel 20/255 off, more than 1 % of the panel) with one
     * white pixel at panel (10, 12): that pixel differs most. Panel 1's bottom-left pixel is page (50, 400) (SPEC
     * Part 3), so the pixel is page (60, 412).
     */
    @Test
    void aFailingPageNamesThePixelToLookAtAndHowToInspectIt() throws Exception {
        Path page = dir.resolve("a1-page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "1", "--a1-rule", "course", "--out",
                page.toString()).exitCode());
        BufferedImage mine = ImageIO.read(page.toFile());
        int left = 50;
        int bottomRow = 749 - 400; // the image row of panel 1's bottom row
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 40; x++) {
                mine.setRGB(left + x, bottomRow - y, 0x141414);
            }
        }
        mine.setRGB(left + 10, bottomRow - 12, 0xFFFFFF);
        Path subs = Files.createDirectories(dir.resolve("mine"));
        Path wrong = subs.resolve("a1-page1.png");
        ImageIO.write(mine, "png", wrong.toFile());
        CliRun run = CliRun.of("compare", wrong.toString(), "--assignment", "1", "--page", "1", "--a1-rule", "course");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("look:    panel 1 (DDA) x 10, y 12 (page x 60, y 412) differs most in patch 1: "
                + "yours (255,255,255), simpview's (0,0,0)"), run.out());
        String next = "simpview inspect --assignment 1 --page 1 --a1-rule course --at 60,412";
        assertTrue(run.out().contains("\nnext:    " + next + "\n"), run.out());
        CliRun inspect = CliRun.of(next.substring("simpview ".length()).split(" "));
        assertEquals(ExitCode.OK, inspect.exitCode(), inspect.err());
        assertTrue(inspect.out().contains("panel 1 (DDA), panel pixel (10, 12)"), inspect.out());

        CliRun check = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "1", "--a1-rule", "course");
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out());
        String compare = "simpview compare " + wrong + " --assignment 1 --page 1 --a1-rule course --diff a1-page1-diff.png";
        assertEquals(1, check.out().lines().filter(l -> l.startsWith("next: ")).count(), check.out());
        assertTrue(check.out().contains("\nnext: " + compare + "\n"), check.out());
    }

    /**
     * Pages 3 to 5 drawn from random numbers of one's own (here simpview's of another seed, as a student's
     * renderer draws its own) fail, and are told why and how to draw simpview's; page 4 with simpview's triangles in
     * other colours (each lit pixel's channels turned by 128) is told its colours are not simpview's. A page drawn
     * from simpview's numbers with a mistake, or left empty, is not told so.
     */
    @Test
    void aPageOfOnesOwnRandomNumbersIsToldToDrawSimpviews() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("own"));
        for (int p = 3; p <= 5; p++) {
            Path page = subs.resolve("a1-page" + p + ".png");
            assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", String.valueOf(p), "--seed", "6",
                    "--out", page.toString()).exitCode());
            CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", String.valueOf(p));
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
            String what = p == 3 ? "lines" : "random triangles";
            assertTrue(run.out().contains("hint: your " + what + " are not simpview's, which it draws at random from "
                    + "seed 361: "), run.out());
            assertTrue(run.out().contains("simpview render --assignment 1 --page " + p + " --seed 361 --primitives a1-page"
                    + p + "-primitives.txt lists"), run.out());
        }
        CliRun same = CliRun.of("compare", subs.resolve("a1-page3.png").toString(), "--assignment", "1", "--page", "3",
                "--seed", "6");
        assertEquals(ExitCode.OK, same.exitCode(), same.out());
        CliRun check = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "3-5");
        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out());
        assertEquals(3, check.out().lines().filter(l -> l.startsWith("hint: ")).count(), check.out());
        assertTrue(check.out().contains("hint: a1-page3.png (A1 page 3 (seed 361)): your lines are not simpview's"),
                check.out());

        Path four = dir.resolve("a1-page4.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "4", "--out", four.toString()).exitCode());
        BufferedImage recoloured = ImageIO.read(four.toFile());
        BufferedImage empty = ImageIO.read(four.toFile());
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                int rgb = recoloured.getRGB(x, y) & 0xFFFFFF;
                if (rgb != 0 && rgb != 0xFFFFFF) {
                    recoloured.setRGB(x, y, rgb ^ 0x808080);
                    empty.setRGB(x, y, 0);
                }
            }
        }
        Path colours = dir.resolve("colours.png");
        ImageIO.write(recoloured, "png", colours.toFile());
        CliRun other = CliRun.of("compare", colours.toString(), "--assignment", "1", "--page", "4");
        assertTrue(other.out().contains("hint: your colours are not simpview's, which it draws at random from seed 361: "
                + "your triangles of panels 1 and 2 fill simpview's pixels, but of the pixels both fill, 0.00 % at most "
                + "have simpview's colour within 8/255."), other.out());
        Path blank = dir.resolve("blank.png");
        ImageIO.write(empty, "png", blank.toFile());
        CliRun none = CliRun.of("compare", blank.toString(), "--assignment", "1", "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, none.exitCode(), none.out());
        assertFalse(none.out().contains("which it draws at random"), none.out());
    }

    /**
     * Page 4 drawn with simpview's triangles and colours by a renderer that turns every colour one way (each
     * channel halved, or put through a gamma of 2.2) fails in every panel, but its colours keep simpview's order:
     * it is not told its colours are random ones of its own, nor to draw simpview's.
     */
    @Test
    void coloursTurnedOneWayAreNotCalledRandom() throws Exception {
        Path four = dir.resolve("a1-page4.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "4", "--out", four.toString()).exitCode());
        BufferedImage halved = ImageIO.read(four.toFile());
        BufferedImage gamma = ImageIO.read(four.toFile());
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                int rgb = halved.getRGB(x, y) & 0xFFFFFF;
                if (rgb != 0 && rgb != 0xFFFFFF) {
                    halved.setRGB(x, y, rgb >> 1 & 0x7F7F7F);
                    int turned = 0;
                    for (int shift = 0; shift <= 16; shift += 8) {
                        double c = (rgb >> shift & 0xFF) / 255.0;
                        turned |= (int) Math.round(255 * Math.pow(c, 1 / 2.2)) << shift;
                    }
                    gamma.setRGB(x, y, turned);
                }
            }
        }
        for (BufferedImage turned : new BufferedImage[] {halved, gamma}) {
            Path picture = dir.resolve("turned.png");
            ImageIO.write(turned, "png", picture.toFile());
            CliRun run = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "4");
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
            assertTrue(run.out().contains("FAIL: "), run.out());
            assertFalse(run.out().contains("which it draws at random"), run.out());
        }
    }

    /**
     * Page 4 saved in greyscale fails, and is told, once for its panels, that it has no colour where simpview's
     * panels have, as a batch and check tell it of each panel.
     */
    @Test
    void aPageSavedInGreyscaleIsToldItHasNoColourOnceForItsPanels() throws Exception {
        Path four = dir.resolve("a1-page4.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "4", "--out", four.toString()).exitCode());
        BufferedImage grey = new BufferedImage(750, 750, BufferedImage.TYPE_BYTE_GRAY);
        grey.createGraphics().drawImage(ImageIO.read(four.toFile()), 0, 0, null);
        Path picture = dir.resolve("grey.png");
        ImageIO.write(grey, "png", picture.toFile());
        CliRun run = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().matches("(?s).*\nnote: panels? [-0-9, and]+: your picture has no colour: every pixel of "
                + "its panel is a shade of grey, where simpview's panel is coloured; .*"), run.out());
        assertEquals(1, run.out().split("no colour", -1).length - 1, "said once: " + run.out());
        assertFalse(run.out().contains("which it draws at random"), "not another draw's colours: " + run.out());
        Path folder = dir.resolve("mine");
        Files.createDirectories(folder);
        Files.copy(picture, folder.resolve("a1-page4.png"));
        CliRun check = CliRun.of("check", folder.toString(), "--assignment", "1", "--pages", "4");
        assertTrue(check.out().contains("your picture has no colour"), check.out());
        assertFalse(check.out().contains("which it draws at random"), "not another draw's colours: " + check.out());
    }

    /**
     * Simpview's own pages 3 and 4 saved as JPEGs fail without slack (a JPEG's black beside a line or an edge is
     * not 0 0 0), but they are drawn from simpview's random numbers, and are not told they are drawn from others.
     */
    @Test
    void aRightPageSavedAsJpegIsNotCalledRandom() throws Exception {
        for (int p = 3; p <= 4; p++) {
            Path png = dir.resolve("a1-page" + p + ".png");
            assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", String.valueOf(p), "--out",
                    png.toString()).exitCode());
            Path jpeg = dir.resolve("a1-page" + p + ".jpg");
            ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality(0.95f);
            try (ImageOutputStream stream = ImageIO.createImageOutputStream(jpeg.toFile())) {
                writer.setOutput(stream);
                writer.write(null, new IIOImage(ImageIO.read(png.toFile()), null, null), param);
            } finally {
                writer.dispose();
            }
            CliRun run = CliRun.of("compare", jpeg.toString(), "--assignment", "1", "--page", String.valueOf(p));
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
            assertTrue(run.out().contains("FAIL: every panel must reach"), run.out() + run.err());
            assertFalse(run.out().contains("which it draws at random"), run.out());
        }
    }

    /**
     * Page 3 saved as a JPEG at ImageIO's default quality (0.75): its compression leaves the white rings around
     * the panels off white, so no page is found, and the student is told that the JPEG is why, not only which ring
     * pixel is not white; alone and in check.
     */
    @Test
    void aPageNotFoundInAJpegSaysToSaveItAsPng() throws Exception {
        Path png = dir.resolve("a1-page3.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "3", "--out", png.toString())
                .exitCode());
        Path st = dir.resolve("st");
        Files.createDirectories(st);
        Path jpeg = st.resolve("a1-page3.jpg");
        assertTrue(ImageIO.write(ImageIO.read(png.toFile()), "jpeg", jpeg.toFile()));
        String advice = "it holds a JPEG, whose lossy compression changes the white around each panel: save the page "
                + "as PNG";

        CliRun one = CliRun.of("compare", jpeg.toString(), "--assignment", "1", "--page", "3");
        assertTrue(one.err().contains("no page of 4 panels of 300x300 found in ") && one.err().contains(advice),
                one.out() + one.err());
        CliRun check = CliRun.of("check", st.toString(), "--assignment", "1", "--pages", "3");
        assertTrue(check.out().contains(advice), check.out());
    }

    /**
     * Lines a pixel short or long pass (a hundred pixels of 90,000) and are said. Page 2's lines, in the panel's
     * frame y up (y = 299 - the handout's): (20, 219 - p) to (150, 149 - p) and (160 + p, 29) to (240 + p, 259),
     * p = 0..50. In panel 1 (DDA) each line's second end is left black: (150, 149 - p) and (240 + p, 259), each
     * on no other line. In panel 2 (Bresenham) the first set's lines run one pixel on: at x = 151 the line is at
     * y = 149 - p - 70/130, which rounds to 148 - p, black in simpview's panel.
     */
    @Test
    void linesAPixelShortOrLongAreSaid() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("ends"));
        Path page = subs.resolve("a1-page2.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "2", "--out", page.toString()).exitCode());
        BufferedImage mine = ImageIO.read(page.toFile());
        for (int p = 0; p <= 50; p++) {
            mine.setRGB(50 + 150, 349 - (149 - p), 0); // panel 1: image row of panel y is 349 - y
            mine.setRGB(50 + 240 + p, 349 - 259, 0);
            mine.setRGB(400 + 151, 349 - (148 - p), 0xFFFFFF); // panel 2
        }
        ImageIO.write(mine, "png", page.toFile());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "2");
        assertEquals(ExitCode.OK, run.exitCode(), run.out());
        assertTrue(run.out().contains("hint: panel 1: your lines stop a pixel short: 102 of the 102 pixels that differ "
                + "are ends of simpview's lines that yours leaves black (line 1's end (150, 149))."), run.out());
        assertTrue(run.out().contains("hint: panel 2: your lines run a pixel long: 51 of the 51 pixels that differ are "
                + "one step past the end of a line of simpview's, lit in yours and black in simpview's ((151, 148) past "
                + "line 1's end (150, 149))."), run.out());
        assertFalse(run.out().contains("hint: panel 3"), run.out());
        CliRun check = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "2");
        assertTrue(check.out().contains("hint: a1-page2.png (A1 page 2 panel 1 (DDA)): your lines stop a pixel short"),
                check.out());
        assertTrue(check.err().contains("panel 1 looks to stop a pixel short of its lines' ends; "
                + "panel 2 looks to run a pixel past its lines' ends"), check.err());
    }

    /**
     * An antialiased panel blended in linear light is told its levels on and beside a line and what they look
     * like. SPEC Part 3: a pixel is a disc of radius r = sqrt(2)/2, the line a slab of width 1; on the line the
     * disc loses two caps at distance 1/2, cap(h) = r^2 acos(h / r) - h sqrt(r^2 - h^2), so its coverage is
     * 1 - 2 cap(1/2) / (pi r^2); one pixel beside it, cap(1/2) / (pi r^2). The picture is simpview's page 1 with
     * panel 4's every level v made sRGB's encoding of v / 255, as a white line blended over black in linear light
     * gives.
     */
    @Test
    void anAntialiasedPanelOfAnotherWeightingIsToldItsLevels() throws Exception {
        double r = Math.sqrt(2) / 2;
        double cap = r * r * Math.acos(0.5 / r) - 0.5 * Math.sqrt(r * r - 0.25);
        int on = (int) Math.floor(255 * (1 - 2 * cap / (Math.PI * r * r)) + 0.5);
        int beside = (int) Math.floor(255 * (cap / (Math.PI * r * r)) + 0.5);
        assertEquals(209, on);
        assertEquals(23, beside);
        Path page = dir.resolve("a1-page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "1", "--out", page.toString()).exitCode());
        CliRun own = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "1");
        assertFalse(own.out().contains("hint:"), own.out());
        BufferedImage mine = ImageIO.read(page.toFile());
        for (int y = 400; y < 700; y++) { // panel 4: image rows 400 to 699, columns 400 to 699
            for (int x = 400; x < 700; x++) {
                mine.setRGB(x, y, grey(srgb((mine.getRGB(x, y) & 0xFF) / 255.0)));
            }
        }
        Path gamma = dir.resolve("gamma.png");
        ImageIO.write(mine, "png", gamma.toFile());
        CliRun run = CliRun.of("compare", gamma.toString(), "--assignment", "1", "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        Matcher hint = Pattern.compile("hint: panel 4: where one line alone reaches a pixel, your antialiased levels are "
                + "([0-9]+) on the line and ([0-9]+) one pixel beside it, simpview's ([0-9]+) and ([0-9]+) \\(")
                .matcher(run.out());
        assertTrue(hint.find(), run.out());
        // medians of pixels within 0.1 of distance 0 and 1: simpview's near SPEC's levels there, the picture's their sRGB
        int oursOn = Integer.parseInt(hint.group(3));
        int oursBeside = Integer.parseInt(hint.group(4));
        assertTrue(Math.abs(oursOn - on) <= 3 && Math.abs(oursBeside - beside) <= 3, hint.group());
        assertEquals(srgb(oursOn / 255.0), Integer.parseInt(hint.group(1)), hint.group());
        assertEquals(srgb(oursBeside / 255.0), Integer.parseInt(hint.group(2)), hint.group());
        assertTrue(run.out().contains("; yours look like the coverage put through sRGB's gamma"), run.out());
    }

    /**
     * The antialiased panels of pages 2 and 3 are measured too. Page 2's white lines lie a pixel apart, so no pixel
     * on a line is reached by it alone: its level there is measured where one other line reaches too, that line's
     * share taken out, and its panel blended in
     * linear light (each level v made sRGB's encoding of v / 255, as white lines blended over black in linear light
     * give) is told so. Page 3's lines are coloured: each channel encoded so (a picture put through a gamma at its
     * end), a level is measured as a share of its line's brightest channel, and the picture's are above simpview's
     * on the line and beside it.
     */
    @Test
    void theAntialiasedPanelsOfPagesTwoAndThreeAreMeasured() throws Exception {
        for (int p = 2; p <= 3; p++) {
            Path page = dir.resolve("a1-page" + p + ".png");
            assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", String.valueOf(p), "--out",
                    page.toString()).exitCode());
            BufferedImage mine = ImageIO.read(page.toFile());
            for (int y = 400; y < 700; y++) { // panel 4: image rows 400 to 699, columns 400 to 699
                for (int x = 400; x < 700; x++) {
                    int rgb = mine.getRGB(x, y);
                    mine.setRGB(x, y, srgb((rgb >> 16 & 0xFF) / 255.0) << 16 | srgb((rgb >> 8 & 0xFF) / 255.0) << 8
                            | srgb((rgb & 0xFF) / 255.0));
                }
            }
            ImageIO.write(mine, "png", page.toFile());
            CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", String.valueOf(p));
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
            String hint = p == 2 ? "hint: panel 4: where your white lines overlap, your antialiased levels are "
                    + "([0-9]+) on the line and ([0-9]+) one pixel beside it, simpview's "
                    + "([0-9]+) and ([0-9]+) \\("
                    : "hint: panel 4: where one line alone reaches a pixel, your antialiased levels \\(as shares of "
                    + "each line's brightest channel, out of 255\\) are ([0-9]+) on the line and ([0-9]+) one pixel "
                    + "beside it, simpview's ([0-9]+) and ([0-9]+) \\(";
            Matcher levels = Pattern.compile(hint).matcher(run.out());
            assertTrue(levels.find(), run.out());
            int oursOn = Integer.parseInt(levels.group(3));
            int oursBeside = Integer.parseInt(levels.group(4));
            assertTrue(Math.abs(oursOn - 209) <= 3 && Math.abs(oursBeside - 23) <= 3, levels.group());
            assertTrue(Integer.parseInt(levels.group(1)) > oursOn + 8, levels.group());
            assertTrue(Integer.parseInt(levels.group(2)) > oursBeside + 8, levels.group());
            // brighter on the line and beside it: not a full pixel on the line, which leaves the pixel beside it dark
            assertFalse(run.out().contains("a full pixel on the line"), run.out());
            if (p == 2) { // beside a line, at the lines' edge, one line alone: its level is the gamma's
                assertTrue(Math.abs(srgb(oursBeside / 255.0) - Integer.parseInt(levels.group(2))) <= 3, levels.group());
                assertTrue(run.out().contains("; yours look like the coverage put through sRGB's gamma"), run.out());
            }
        }
    }

    /** sRGB's encoding of a linear level c, as a byte. */
    private static int srgb(double c) {
        double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
        return (int) Math.floor(255 * encoded + 0.5);
    }

    private static int grey(int level) {
        return level << 16 | level << 8 | level;
    }

    @Test
    void ourOwnPageAgreesEverywhere() {
        Path page = dir.resolve("a1-page3.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "3", "--seed", "5", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "3", "--seed", "5");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(run.out().contains("page:    top-left at x 0, y 0"), run.out());
        assertTrue(run.out().contains("2 Bresenham                             100.00 %     100.00 %"), run.out());
        // Another seed's lines do not agree.
        CliRun other = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "3", "--seed", "6");
        assertEquals(ExitCode.SCENE_ERROR, other.exitCode());
        assertTrue(other.out().contains("FAIL"), other.out());
    }

    /** One pixel wrong of a panel's 90,000 reads 99.99 %, never a rounded-up 100.00 %, as every share is printed. */
    @Test
    void aPanelOnePixelOffIsNotSaidToBeWhole() throws Exception {
        Path page = dir.resolve("a1-page3.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "3", "--out", page.toString()).exitCode());
        BufferedImage mine = ImageIO.read(page.toFile());
        int x = A1Layout.left(2) + 7;
        int y = A1Layout.top(2) + 9;
        mine.setRGB(x, y, mine.getRGB(x, y) ^ 0xFFFFFF);
        Path off = dir.resolve("off.png");
        ImageIO.write(mine, "png", off.toFile());
        CliRun run = CliRun.of("compare", off.toString(), "--assignment", "1", "--page", "3");
        assertEquals(ExitCode.OK, run.exitCode(), run.out()); // 99.99 % of the panel is within: it passes
        assertTrue(run.out().contains("2 Bresenham                              99.99 %      99.99 %"), run.out());
        assertTrue(run.out().contains("1 DDA                                   100.00 %     100.00 %"), run.out());
    }

    /**
     * A page whose rows of panels are swapped: its panel 2 holds simpview's antialiased panel 4 and its panel 4
     * the Bresenham panel 2, and the hints say so rather than leave the student to think a drawer is wrong.
     */
    @Test
    void panelsInAnotherOrderAreNamed() throws Exception {
        Path page = dir.resolve("a1-page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "1", "--out", page.toString()).exitCode());
        BufferedImage ours = ImageIO.read(page.toFile());
        BufferedImage swapped = ImageIO.read(page.toFile());
        int n = A1Layout.PANEL;
        for (int k = 1; k <= 4; k++) {
            int from = k <= 2 ? k + 2 : k - 2; // 1 <- 3, 2 <- 4, 3 <- 1, 4 <- 2
            for (int y = 0; y < n; y++) {
                for (int x = 0; x < n; x++) {
                    swapped.setRGB(A1Layout.left(k) + x, A1Layout.top(k) + y,
                            ours.getRGB(A1Layout.left(from) + x, A1Layout.top(from) + y));
                }
            }
        }
        Path mine = dir.resolve("swapped.png");
        ImageIO.write(swapped, "png", mine.toFile());
        CliRun run = CliRun.of("compare", mine.toString(), "--assignment", "1", "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("hint: panel 2: your panel 2 holds what simpview draws in panel 4 (antialiased): "
                + "100.00 % of its pixels are within 8/255 of that panel's"), run.out());
        assertTrue(run.out().contains("hint: panel 4: your panel 4 holds what simpview draws in panel 2 (Bresenham): "
                + "100.00 %"), run.out());
        // The same in a batch's table, for a teacher.
        Path folder = dir.resolve("subs");
        Files.createDirectories(folder.resolve("ann"));
        ImageIO.write(swapped, "png", folder.resolve("ann/a1-page1.png").toFile());
        Path out = dir.resolve("out");
        CliRun batch = CliRun.of("compare", "--dir", folder.toString(), "--assignment", "1", "--pages", "1",
                "--out-dir", out.toString());
        String table = Files.readString(out.resolve("compare.csv"));
        assertTrue(table.contains("looks like simpview's panel 4 (antialiased)"), table);
        assertTrue(table.contains("looks like simpview's panel 2 (Bresenham)"), table);
        assertEquals(ExitCode.SCENE_ERROR, batch.exitCode(), batch.err());
    }

    /**
     * A page drawn with row = y is upside down as a whole: each panel then holds another panel's picture
     * turned over. One hint says so for the page, in compare and in check; and a page drawn by SPEC's rule,
     * compared by the course's, gets none (its Bresenham panel is nearer simpview's DDA panel, which says
     * nothing of where it went wrong).
     */
    @Test
    void aPageUpsideDownIsNamedAsAWhole() throws Exception {
        for (int number : new int[] {1, 4}) {
            Path page = dir.resolve("p" + number + ".png");
            assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", String.valueOf(number),
                    "--out", page.toString()).exitCode());
            BufferedImage ours = ImageIO.read(page.toFile());
            BufferedImage over = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < 750; y++) {
                for (int x = 0; x < 750; x++) {
                    over.setRGB(x, y, ours.getRGB(x, 749 - y));
                }
            }
            Path folder = dir.resolve("sub" + number);
            Files.createDirectories(folder);
            Path mine = folder.resolve("page" + number + ".png");
            ImageIO.write(over, "png", mine.toFile());
            CliRun run = CliRun.of("compare", mine.toString(), "--assignment", "1", "--page", String.valueOf(number));
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
            assertTrue(run.out().contains("\nhint: your page is simpview's upside down: so turned back, 100.00 % of the"
                    + " pixels it then matches are within 8/255"), run.out());
            assertTrue(run.out().contains("the course's y up from the page's bottom-left pixel, so the pixel of y is"
                    + " row 749 - y"), run.out());
            assertEquals(1, run.out().split("hint:", -1).length - 1, "one hint for the page: " + run.out());
            CliRun check = CliRun.of("check", folder.toString());
            assertTrue(check.out().matches("(?s).*\nhint: page" + number + "\\.png \\(A1 page " + number
                    + "( \\(seed 361\\))?\\): your page is simpview's upside down.*"), check.out());
            assertEquals(1, check.out().split("hint:", -1).length - 1, "one hint for the page: " + check.out());
            assertTrue(check.err().contains("looks like simpview's whole page upside down"), check.err());
        }
        // Page 2 transposed: its panels 1 to 3 are alike, so each panel's own hint explains it as well as the
        // page's; the tie goes to the page, one hint.
        Path two = dir.resolve("p2.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "2", "--out", two.toString())
                .exitCode());
        BufferedImage page2 = ImageIO.read(two.toFile());
        BufferedImage across = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                across.setRGB(x, y, page2.getRGB(y, x));
            }
        }
        Path transposed = dir.resolve("transposed2.png");
        ImageIO.write(across, "png", transposed.toFile());
        CliRun turned = CliRun.of("compare", transposed.toString(), "--assignment", "1", "--page", "2");
        assertTrue(turned.out().contains("\nhint: your page is simpview's transposed (x and y swapped)"), turned.out());
        assertEquals(1, turned.out().split("hint:", -1).length - 1, "one hint for the page: " + turned.out());
        Path spec = dir.resolve("spec1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "1", "--out", spec.toString())
                .exitCode());
        CliRun byCourse = CliRun.of("compare", spec.toString(), "--assignment", "1", "--page", "1", "--a1-rule",
                "course");
        assertEquals(ExitCode.SCENE_ERROR, byCourse.exitCode(), "the Bresenham panels differ: " + byCourse.out());
        assertFalse(byCourse.out().contains("hint:"), byCourse.out());
    }

    @Test
    void thePolygonPagesNameEachPanelsScene() {
        Path page = dir.resolve("a1-page5.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "5", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "5");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        int k = 0;
        for (String scene : new String[] {"starburst", "mesh", "perturbed mesh", "random triangles"}) {
            k++;
            String line = k + " " + scene;
            assertTrue(run.out().lines().anyMatch(l -> l.startsWith(line + "  ") && l.endsWith("100.00 %     100.00 %")),
                    run.out());
        }
    }

    /**
     * A panel passes with 900 of its pixels wrong: a 20x20 block left black on page 5's random triangles (400
     * pixels, seed 7) passes at 99.55 %, and is said in a note naming the panel, as a page of the eight pages'
     * is, by compare and by check alike.
     */
    @Test
    void aPanelThatPassesWithASolidPatchIsSaidToMissAShape() throws Exception {
        BufferedImage mine = Assignment1.render(5, PageContext.defaults().withSeed(7));
        for (int y = 0; y < 20; y++) {
            for (int x = 0; x < 20; x++) {
                mine.setRGB(A1Layout.left(4) + 100 + x, A1Layout.top(4) + 179 + y, 0);
            }
        }
        Path page = dir.resolve("a1-page5.png");
        ImageIO.write(mine, "png", page.toFile());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "5", "--seed", "7");
        assertEquals(ExitCode.OK, run.exitCode(), run.out());
        assertTrue(run.out().contains("4 random triangles                       99.55 %      99.55 %"), run.out());
        assertTrue(run.out().contains("\nnote: panel 4 (random triangles): it passes, but a patch of 400 pixels differs "
                + "(x 100-119, y 101-120 (20x20): 400 pixels): more than an edge, so a shape may be missing"), run.out());
        assertEquals(1, run.out().lines().filter(l -> l.startsWith("note:")).count(), "the other panels are whole");

        CliRun check = CliRun.of("check", dir.toString(), "--assignment", "1", "--pages", "5", "--seed", "7");
        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertTrue(check.out().contains("note: a1-page5.png (A1 page 5 (seed 7) panel 4): it passes, "
                + "but a patch of 400 pixels differs"), check.out());
    }

    @Test
    void theCoursesCaptureIsFoundAndJudgedPanelByPanel() {
        Path picture = CourseFiles.require("reference/images/a1/page2.png");
        CliRun run = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "2");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(run.out().contains("page:    top-left at x 1, y 31"), run.out());
        assertTrue(run.out().contains("4 antialiased                           100.00 %     100.00 %"), run.out());
        // SPEC's integer Bresenham is not the course's program's: its panels 2 and 3 fall short.
        String page1 = CourseFiles.require("reference/images/a1/page1.png").toString();
        CliRun bySpec = CliRun.of("compare", page1, "--assignment", "1", "--page", "1");
        assertTrue(bySpec.out().contains("2 Bresenham                              96.61 %      96.61 %"), bySpec.out());
        assertEquals(ExitCode.SCENE_ERROR, bySpec.exitCode(), bySpec.out());
        CliRun starburst = CliRun.of("compare", page1, "--assignment", "1", "--page", "1", "--a1-rule", "course");
        assertTrue(starburst.out().contains("Starburst, by the course's pictures' rule"), starburst.out());
        assertTrue(starburst.out().contains("2 Bresenham                              99.97 %      99.97 %"), starburst.out());
        assertEquals(ExitCode.OK, starburst.exitCode(), "every panel reaches 99 % within 8/255");
        for (CliRun course : new CliRun[] {run, bySpec, starburst}) {
            assertFalse(course.out().contains("hint:"), "no move, turn or swap explains a course's panel: " + course.out());
            assertFalse(course.out().contains("note:"), "the course's panels differ in thin patches only: " + course.out());
        }
        // the course's pages of random lines and polygons are drawn from other numbers: none is taken for a fill
        // without the top-left rule, floored ends or a drawer wrong in some octants
        for (int p = 3; p <= 5; p++) {
            String course = CourseFiles.require("reference/images/a1/page" + p + ".png").toString();
            for (String rule : new String[] {"spec", "course"}) {
                CliRun random = CliRun.of("compare", course, "--assignment", "1", "--page", String.valueOf(p),
                        "--a1-rule", rule);
                assertEquals(ExitCode.SCENE_ERROR, random.exitCode(), random.out());
                for (String other : new String[] {"top-left rule", "look floored", "in some directions only"}) {
                    assertFalse(random.out().contains(other), random.out());
                }
            }
        }
        CliRun wrong = CliRun.of("compare", page1, "--assignment", "1", "--page", "1", "--a1-rule", "mine");
        assertEquals(ExitCode.USAGE_ERROR, wrong.exitCode());
        assertTrue(wrong.err().contains("--a1-rule must be spec or course, not mine"), wrong.err());
    }

    /**
     * --metric blur measures the blurred panels. On the course's page 1 the
     * antialiased panel's share within 8/255 goes down (99.02 to 98.75 %):
     * the blur spreads each differing pixel over its neighbours rather than
     * forgiving the course's antialiasing (docs/grading.md).
     */
    @Test
    void theBlurMetricMeasuresTheBlurredPanels() {
        String picture = CourseFiles.require("reference/images/a1/page1.png").toString();
        CliRun exact = CliRun.of("compare", picture, "--assignment", "1", "--page", "1");
        CliRun blur = CliRun.of("compare", picture, "--assignment", "1", "--page", "1", "--metric", "blur");
        assertTrue(blur.out().contains("metric:  both pictures' panels blurred (3x3) before they are compared"), blur.out());
        assertTrue(exact.out().contains("4 antialiased                            98.64 %      99.02 %"), exact.out());
        assertTrue(blur.out().contains("4 antialiased                            92.94 %      98.75 %"), blur.out());
        String self = dir.resolve("a1-page2.png").toString();
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "2", "--out", self).exitCode());
        CliRun same = CliRun.of("compare", self, "--assignment", "1", "--page", "2", "--metric", "blur");
        assertEquals(ExitCode.OK, same.exitCode(), same.out() + same.err());
        assertTrue(same.out().contains("4 antialiased                           100.00 %     100.00 %"), same.out());
    }

    @Test
    void aPictureWithoutTheFourPanelsIsRefusedClearly() {
        Path page = dir.resolve("page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "1", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains("no page of 4 panels of 300x300 found in " + page), run.err());
        assertTrue(run.err().contains("it holds one 650x650 panel, as a page of the eight pages does: compare it with one "
                + "of those (--page N without --assignment 1)"), run.err());
        assertEquals(ExitCode.USAGE_ERROR, CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "6").exitCode());
    }

    /** The page drawn into a picture of {@code width} x {@code height} with its top-left at (left, top), white around. */
    private static BufferedImage placed(BufferedImage page, int width, int height, int left, int top) {
        BufferedImage picture = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = picture.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        g.drawImage(page, left, top, null);
        g.dispose();
        return picture;
    }

    /** The page scaled to {@code side} x {@code side}, as a screen or a viewer saves it. */
    private static BufferedImage scaled(BufferedImage page, int side) {
        BufferedImage picture = new BufferedImage(side, side, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = picture.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        g.drawImage(page, 0, 0, side, side, null);
        g.dispose();
        return picture;
    }

    private CliRun compared(String name, BufferedImage picture) throws Exception {
        Path file = dir.resolve(name);
        ImageIO.write(picture, "png", file.toFile());
        return CliRun.of("compare", file.toString(), "--assignment", "1", "--page", "1");
    }

    /**
     * A page drawn a pixel off in its picture, or cut a pixel short, still has the white rings around its panels: it
     * is found and compared, and the page line says where it runs past the picture.
     */
    @Test
    void aPageAPixelOffOrCutShortIsFoundAndSaidSo() throws Exception {
        BufferedImage page = Assignment1.render(1, PageContext.defaults());
        CliRun off = compared("off.png", placed(page, 750, 750, 1, 1));
        assertEquals(ExitCode.OK, off.exitCode(), off.out() + off.err());
        assertTrue(off.out().contains("page:    top-left at x 1, y 1 of the picture, counted from its top-left; the page "
                + "runs past the picture's right edge by 1 px and bottom edge by 1 px (its margins are cut there; its "
                + "panels are whole)"), off.out());
        CliRun narrow = compared("narrow.png", placed(page, 749, 750, -1, 0));
        assertEquals(ExitCode.OK, narrow.exitCode(), narrow.out() + narrow.err());
        assertTrue(narrow.out().contains("top-left at x -1, y 0 of the picture, counted from its top-left; the page runs "
                + "past the picture's left edge by 1 px ("), narrow.out());
        CliRun whole = compared("whole.png", page);
        assertTrue(whole.out().contains("page:    top-left at x 0, y 0 of the picture, counted from its top-left\n"),
                "a page the picture holds whole runs past nothing: " + whole.out());
    }

    /** A picture without the page is told what it holds instead, as far as simpview can tell. */
    @Test
    void aPictureWithoutThePageIsToldWhatItHoldsInstead() throws Exception {
        BufferedImage page = Assignment1.render(1, PageContext.defaults());
        CliRun small = compared("small.png", scaled(page, 700));
        assertEquals(ExitCode.SCENE_ERROR, small.exitCode());
        assertTrue(small.err().contains("(700x700): it is smaller than a page (750x750); it has the shape of a 750x750 "
                + "page, scaled by 0.933: save the picture at its own size (1:1, no scaling)"), small.err());
        CliRun hiDpi = compared("hidpi.png", scaled(page, 1500));
        assertTrue(hiDpi.err().contains("(1500x1500): each panel needs a white ring around it and a mostly dark edge; it "
                + "has the shape of a 750x750 page, scaled by 2.00: save the picture at its own size"), hiDpi.err());
        BufferedImage blank = Assignment1.render(1, PageContext.defaults());
        Graphics2D g = blank.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(A1Layout.left(4), A1Layout.top(4), A1Layout.PANEL, A1Layout.PANEL);
        g.dispose();
        CliRun white = compared("white.png", blank);
        assertTrue(white.err().contains("(750x750): panels 1-3 are framed with the page's top-left at x 0, y 0 of "
                + "the picture, but not panel 4 (x 400-699, y 400-699 of the picture): its outermost pixels are mostly "
                + "light"), white.err());
        BufferedImage wide = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        Graphics2D w = wide.createGraphics();
        w.setColor(Color.WHITE);
        w.fillRect(0, 0, 750, 750);
        w.setColor(Color.BLACK);
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            w.fillRect(A1Layout.left(k), A1Layout.top(k), A1Layout.PANEL + 1, A1Layout.PANEL + 1); // 301 wide
        }
        w.dispose();
        CliRun big = compared("big.png", wide);
        assertTrue(big.err().contains("(750x750): no panel is framed where a 750x750 page has them; panel 1 (x 50-349, "
                + "y 50-349 of the picture): the ring of pixels just outside it is not white (at x 50, y 350: rgb 0 0 0)"),
                big.err());
        for (CliRun four : new CliRun[] {white, big}) {
            assertFalse(four.err().contains("650x650"), "a page of four panels is not one panel: " + four.err());
        }
        for (CliRun run : new CliRun[] {small, hiDpi, white, big}) {
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
            assertTrue(run.err().startsWith("simpview compare: no page of 4 panels of 300x300 found in "), run.err());
            assertFalse(run.showsStackTrace(), run.err());
        }
    }

    /**
     * A panel that fails lists its largest differing patches in panel coordinates, as the eight pages' compare does;
     * --diff writes ours | theirs | heat map, each the whole page.
     */
    @Test
    void aFailingPanelListsWhereItDiffersAndDiffWritesTheThreePages() throws Exception {
        BufferedImage spoiled = Assignment1.render(1, PageContext.defaults());
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 40; x++) {
                spoiled.setRGB(A1Layout.left(2) + 100 + x, A1Layout.top(2) + 100 + y, 0xFF00FF);
            }
        }
        Path picture = dir.resolve("spoiled.png");
        ImageIO.write(spoiled, "png", picture.toFile());
        Path diff = dir.resolve("diff.png");
        CliRun run = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "1", "--diff", diff.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.out().contains("2 Bresenham                              98.22 %      98.22 %\n"
                + "3 alternating DDA / Bresenham           100.00 %     100.00 %\n"
                + "4 antialiased                           100.00 %     100.00 %\n"
                + "panel 2 (Bresenham): 1,600 pixels in 1 patch differ by more than 8/255\n"
                + "(panel pixels: origin bottom-left, x right, y up):\n"
                + "  1. x 100-139, y 160-199 (40x40): 1,600 pixels\n"
                + "FAIL: every panel must reach 99.00 % within 8/255 (no slack)\n"), run.out());
        assertTrue(run.out().contains("diff:    " + diff + " (ours | theirs | heat map, each the whole page, their panels "
                + "on white: grey identical, blue within 8/255, red beyond it)"), run.out());
        BufferedImage written = ImageIO.read(diff.toFile());
        assertEquals(3 * 750 + 2 * 10, written.getWidth());
        assertEquals(750, written.getHeight());
        int x = A1Layout.left(2) + 120;
        int y = A1Layout.top(2) + 120;
        assertEquals(Assignment1.render(1, PageContext.defaults()).getRGB(x, y) & 0xFFFFFF, written.getRGB(x, y) & 0xFFFFFF,
                "simpview's page");
        assertEquals(0xFF00FF, written.getRGB(760 + x, y) & 0xFFFFFF, "their page");
        int heat = written.getRGB(2 * 760 + x, y);
        assertTrue((heat >> 16 & 0xFF) >= 128 && (heat & 0xFFFF) == 0, "red in the heat map: " + Integer.toHexString(heat));
        assertEquals(0xFFFFFF, written.getRGB(2 * 760 + 10, 10) & 0xFFFFFF, "the heat map's page is white around its panels");
        assertEquals(0x808080, written.getRGB(755, 10) & 0xFFFFFF, "a grey gap");

        CliRun passing = CliRun.of("compare", CourseFiles.require("reference/images/a1/page2.png").toString(),
                "--assignment", "1", "--page", "2");
        assertFalse(passing.out().contains("patch"), "a page whose panels all pass lists no patches: " + passing.out());
        CliRun jpeg = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "1", "--diff", "d.jpg");
        assertEquals(ExitCode.USAGE_ERROR, jpeg.exitCode());
        CliRun itself = CliRun.of("compare", picture.toString(), "--assignment", "1", "--page", "1", "--diff",
                picture.toString());
        assertEquals(ExitCode.USAGE_ERROR, itself.exitCode(), "the picture compared is kept: " + itself.err());
    }

    /**
     * Without --assignment 1, a first-assignment page is not compared with one of the eight pages (whose 650x650
     * panel its two panels and gutter frame): it is told to add --assignment 1. So is --a1-rule alone.
     */
    @Test
    void aFirstAssignmentPageComparedWithoutAssignment1IsToldToAddIt() throws Exception {
        Path page = dir.resolve("a1-page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "1", "--out", page.toString()).exitCode());
        CliRun run = CliRun.of("compare", page.toString(), "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertEquals("simpview compare: " + page + " is a page of the first assignment (four 300x300 panels), not a page "
                + "with one 650x650 panel: add --assignment 1 to compare it panel by panel, e.g. simpview compare " + page
                + " --assignment 1 --page 1\n", run.err());
        assertEquals("", run.out(), "no comparison with the eight pages' page 1");
        // a seeded page's suggestion keeps the seed it was given: the same random page is compared
        CliRun seeded = CliRun.of("compare", page.toString(), "--page", "3", "--seed", "5");
        assertTrue(seeded.err().endsWith(" --assignment 1 --page 3 --seed 5\n"), seeded.err());
        CliRun seven = CliRun.of("compare", page.toString(), "--page", "7", "--simp-dir",
                CourseFiles.requireSimpDir().toString());
        assertTrue(seven.err().endsWith("--assignment 1 --page N (1 to 5)\n"), seven.err());
        // the course's window capture of its page 1 holds no 650x650 panel at all: told the same
        String capture = CourseFiles.require("reference/images/a1/page1.png").toString();
        CliRun course = CliRun.of("compare", capture, "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, course.exitCode());
        assertTrue(course.err().contains(" is a page of the first assignment (four 300x300 panels)"), course.err());
        // a gutter a viewer shows through is no 650x650 panel (it is not opaque), but the four panels are there
        BufferedImage clear = new BufferedImage(750, 750, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = clear.createGraphics();
        g.drawImage(Assignment1.render(1, PageContext.defaults()), 0, 0, null);
        g.dispose();
        for (int y = 0; y < 750; y++) {
            for (int x = 360; x < 390; x++) {
                clear.setRGB(x, y, 0x00FFFFFF);
            }
        }
        Path seeThrough = dir.resolve("clear.png");
        ImageIO.write(clear, "png", seeThrough.toFile());
        CliRun gutter = CliRun.of("compare", seeThrough.toString(), "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, gutter.exitCode());
        assertTrue(gutter.err().contains(" is a page of the first assignment (four 300x300 panels)"), gutter.err());
        assertEquals(ExitCode.OK, CliRun.of("compare", seeThrough.toString(), "--assignment", "1", "--page", "1").exitCode());
        CliRun rule = CliRun.of("compare", page.toString(), "--page", "1", "--a1-rule", "course");
        assertEquals(ExitCode.USAGE_ERROR, rule.exitCode());
        assertTrue(rule.err().contains("--a1-rule goes with --assignment 1"), rule.err());
        // one of the eight pages is compared as before
        Path eight = dir.resolve("page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "1", "--out", eight.toString()).exitCode());
        assertEquals(ExitCode.OK, CliRun.of("compare", eight.toString(), "--page", "1").exitCode());
    }

    /**
     * Options that other commands refuse, or that do nothing to the first assignment's pages, are usage errors with
     * --assignment 1, as render's rules have them.
     */
    @Test
    void optionsThatDoNothingToTheFirstAssignmentAreUsageErrors() throws Exception {
        Path page = dir.resolve("a1-page1.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "1", "--out", page.toString()).exitCode());
        Path folder = Files.createDirectories(dir.resolve("mine"));
        Files.copy(page, folder.resolve("a1-page1.png"));
        String one = page.toString();
        String out = dir.resolve("report").toString();
        Object[][] refused = {
            {new String[] {"compare", one, "--assignment", "1", "--page", "1", "--threads", "0"}, "--threads must be 1 to 64, not 0"},
            {new String[] {"compare", one, "--assignment", "1", "--page", "1", "--threads", "999"}, "--threads must be 1 to 64, not 999"},
            {new String[] {"compare", one, "--assignment", "1", "--page", "1", "--simp-dir", dir.toString()},
                "--simp-dir goes with assignment 2's pages: the first assignment's read no files"},
            {new String[] {"compare", one, "--assignment", "1", "--page", "1", "--deviation", "2"},
                "--deviation does not go with --assignment 1: the first assignment's panels are judged without slack"},
            {new String[] {"compare", "--dir", folder.toString(), "--assignment", "1", "--out-dir", out, "--simp-dir",
                dir.toString()}, "--simp-dir goes with assignment 2's pages"},
            {new String[] {"compare", "--dir", folder.toString(), "--assignment", "1", "--out-dir", out, "--deviation", "0"},
                "a rubric rule may give them one (\"deviation\")"},
            {new String[] {"check", folder.toString(), "--assignment", "1", "--simp-dir", dir.toString()},
                "--simp-dir goes with assignment 2's pages"},
            {new String[] {"check", folder.toString(), "--assignment", "1", "--deviation", "1"},
                "--deviation does not go with --assignment 1"}};
        for (Object[] each : refused) {
            String[] args = (String[]) each[0];
            CliRun run = CliRun.of(args);
            assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), String.join(" ", args) + "\n" + run.err());
            assertTrue(run.err().contains((String) each[1]), String.join(" ", args) + "\n" + run.err());
            assertFalse(run.showsStackTrace(), run.err());
        }
        assertEquals(ExitCode.OK, CliRun.of("compare", one, "--assignment", "1", "--page", "1", "--threads", "2").exitCode(),
                "a count in range is taken, as render takes it");
        Path rubric = Files.writeString(dir.resolve("compare.json"),
                "{\"pages\": [{\"match\": \"a1-*-panel4\", \"metric\": \"flip\"}]}");
        CliRun ruled = CliRun.of("compare", "--dir", folder.toString(), "--assignment", "1", "--pages", "1", "--out-dir", out,
                "--deviation", "0", "--rubric", rubric.toString());
        assertEquals(ExitCode.OK, ruled.exitCode(), "a rubric's rules take their deviation from it: " + ruled.err());
    }

    /**
     * A batch of the eight pages (--pages) grades those only: a1-page2.png is skipped, not taken for page 2 nor
     * graded as the first assignment's page, and the teacher is told that --assignment 1 grades those.
     */
    @Test
    void aBatchOfTheEightPagesSkipsAFirstAssignmentPage() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("subs"));
        assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", "2",
                "--out", subs.resolve("a1-page2.png").toString()).exitCode());
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-8", "--out-dir", dir.resolve("report").toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "--pages 1-8 asks for the eight pages: " + run.err());
        assertTrue(run.out().contains("| a1-page2.png |  |  |  |  |  |  |  |  | SKIPPED |  |  | a page of the first assignment by its "
                + "name, and --pages names the eight pages (--assignment 1 grades the first assignment's pages) |"),
                run.out());
        assertTrue(run.out().contains("1 picture: 0 pass, 0 fail, 0 could not be compared, 1 skipped; 8 pages "
                + "asked for without a picture"), run.out());
        assertTrue(run.err().contains("note: every picture is a page of the first assignment, but --pages names the "
                + "eight pages"), run.err());

        // a student's folder named like the first assignment, holding a page of the eight: that page, graded
        Path class_ = Files.createDirectories(dir.resolve("class"));
        for (String student : new String[] {"A1-Smith", "bob"}) {
            assertEquals(ExitCode.OK, CliRun.of("render", "--page", "1", "--out",
                    class_.resolve(student + "/page1.png").toString()).exitCode());
        }
        CliRun named = CliRun.of("compare", "--dir", class_.toString(), "--pages", "1", "--out-dir",
                dir.resolve("named").toString());
        assertEquals(ExitCode.OK, named.exitCode(), named.out() + named.err());
        assertTrue(named.out().contains("| A1-Smith/page1.png | 1 (seed 361) |"), named.out());
    }

    /**
     * Its name alone makes a picture a first-assignment page where --pages names the eight: an a1-page5.png of the
     * wrong size (it holds no four panels) is skipped as one, not taken for page 5 (an ERROR row, or a candidate
     * beside page5.png), by compare --dir and check alike.
     */
    @Test
    void aFirstAssignmentNameIsSkippedWhateverItHolds() throws Exception {
        Path ivy = Files.createDirectories(dir.resolve("class/ivy"));
        assertEquals(ExitCode.OK, CliRun.of("render", "--page", "5", "--out", ivy.resolve("page5.png").toString())
                .exitCode());
        BufferedImage wrongSize = new BufferedImage(700, 700, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = wrongSize.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 700, 700);
        g.dispose();
        ImageIO.write(wrongSize, "png", ivy.resolve("a1-page5.png").toFile());
        String skipped = "| ivy/a1-page5.png |  |  |  |  |  |  |  |  | SKIPPED |  |  | a page of the first assignment by its "
                + "name, and --pages names the eight pages (--assignment 1 grades the first assignment's pages) |";
        CliRun run = CliRun.of("compare", "--dir", dir.resolve("class").toString(), "--pages", "5", "--out-dir",
                dir.resolve("report").toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().contains(skipped), run.out());
        assertFalse(run.out().contains("no 650x650 panel found"), run.out());
        assertFalse(run.out().contains("not counted"), run.out());
        CliRun check = CliRun.of("check", ivy.toString(), "--pages", "5");
        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertFalse(check.out().contains("no 650x650 panel found"), check.out());
        assertFalse(check.out().contains("not counted"), check.out());
    }
}
