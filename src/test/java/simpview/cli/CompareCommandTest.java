package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.Picture;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.testing.Fifos;

/** {@code simpview compare IMAGE ...}: the report, the diff image and the exit codes. */
public class CompareCommandTest {

    @TempDir
    Path dir;

    private Path png(String name, BufferedImage image) throws Exception {
        Path file = dir.resolve(name);
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    /** The share printed in the report's row, e.g. "identical" → {exactly, with slack}, in percent. */
    static double[] printed(String report, String row) {
        Matcher m = Pattern.compile("(?m)^" + Pattern.quote(row) + "\\s+([0-9.]+) %\\s+([0-9.]+) %$").matcher(report);
        assertTrue(m.find(), "no row '" + row + "' in:\n" + report);
        return new double[] {Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2))};
    }

    /** A share as the report prints it: in percent, two decimals, rounded down. */
    static double asPrinted(double share) {
        return Math.floor(share * 10_000 + 1e-9) / 100;
    }

    @Test
    void aPageAgainstSimpviewsOwnRenderIsIdenticalAndPasses() throws Exception {
        Path mine = png("page3.png", page(3));
        CliRun run = CliRun.of("compare", mine.toString(), "--page", "3");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        for (String row : new String[] {"identical", "within 1/255", "within 8/255"}) {
            assertEquals(100.0, printed(run.out(), row)[0], row);
            assertEquals(100.0, printed(run.out(), row)[1], row);
        }
        assertTrue(run.out().contains("panel:   x 50-699, y 50-699"), run.out());
        assertTrue(run.out().contains("margins: white (140,000 pixels)"), run.out());
        assertTrue(run.out().contains("PASS: 100.00 % within 8/255 with slack (99.00 % needed)"), run.out());
        assertFalse(run.out().contains("hint:"), run.out());
    }

    /**
     * The verdict {@code compare} gives without --tolerance and --min is the
     * one a Java caller gets from the named defaults: a picture with a patch
     * of 1.5 % of the panel wrong fails by both, and the two reports are the
     * same text but for the words naming simpview's picture.
     */
    @Test
    void withoutOptionsTheVerdictIsTheNamedDefaultsOne() throws Exception {
        BufferedImage page = page(2);
        for (int y = 100; y < 200; y++) {
            for (int x = 100; x < 164; x++) {
                page.setRGB(x, y, 0x00FF00);
            }
        }
        Path mine = png("patched.png", page);
        CliRun run = CliRun.of("compare", mine.toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        Picture theirs = Picture.read(mine);
        Picture ours = Picture.ofPage(page(2), "simpview's page 2");
        ComparisonReport report = ComparisonReport.of(theirs, "PAGE",
                Comparison.of(ours.panel(), theirs.panel()),
                Comparison.DEFAULT_TOLERANCE, ComparisonReport.DEFAULT_MINIMUM);
        assertFalse(report.passes());
        String against = run.out().lines().findFirst().orElseThrow().replace(mine + " against simpview's ", "");
        assertEquals(run.out(), report.text().replace("simpview's PAGE", "simpview's " + against));
        assertTrue(run.out().contains("within 8/255 with slack (99.00 % needed)"), run.out());
    }

    /**
     * Colours truncated to a byte where SPEC rounds: every other pixel of
     * page 2 a level darker in each channel above 0. It passes within 1/255,
     * and is told why it is not identical; a panel off both ways is not.
     */
    @Test
    void coloursALevelDarkerAllTheSameWayAreToldOfTruncation() throws Exception {
        BufferedImage page = page(2);
        BufferedImage darker = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        darker.setData(page.getRaster());
        BufferedImage both = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        both.setData(page.getRaster());
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                if ((x + y) % 2 == 0) {
                    int rgb = page.getRGB(x, y);
                    int off = 0;
                    for (int shift = 0; shift <= 16; shift += 8) {
                        off |= ((rgb >> shift & 0xFF) > 0 ? 1 : 0) << shift;
                    }
                    darker.setRGB(x, y, rgb - off);
                    both.setRGB(x, y, x % 4 == 0 ? rgb - off : rgb + (~rgb & 0x010101 & 0x010101));
                }
            }
        }
        CliRun run = CliRun.of("compare", png("truncated.png", darker).toString(), "--page", "2");
        assertEquals(0, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nnote: every pixel that differs ("), run.out());
        assertTrue(run.out().contains(" of the panel) is one level darker than simpview's, in each channel that"
                + " differs, never brighter: a colour made a byte by truncation, (int) (c * 255), where SPEC rounds"), run.out());
        CliRun mixed = CliRun.of("compare", png("mixed.png", both).toString(), "--page", "2");
        assertFalse(mixed.out().contains("level darker"), mixed.out());
        assertFalse(mixed.out().contains("level brighter"), mixed.out());
    }

    /**
     * A scene of vertex colours drawn in them, as {@code render --own-colors}
     * draws it: compared with --own-colors it is simpview's picture to the
     * pixel; without, it is held against the depth-cued one, and fails.
     * compare had no --own-colors, so such a picture could not be checked.
     */
    @Test
    void aSceneInItsOwnColoursIsComparedInThem() throws Exception {
        Path scene = dir.resolve("blerp.simp");
        Files.writeString(scene, "polygon (-80, -80, -20, 1, 0, 0) (80, -80, -120, 0, 1, 0) (0, 80, -190, 0, 0, 1)\n");
        Path mine = dir.resolve("mine.png");
        CliRun render = CliRun.of("render", "--scene", scene.toString(), "--own-colors", "--out", mine.toString());
        assertEquals(0, render.exitCode(), render.err());
        CliRun own = CliRun.of("compare", mine.toString(), "--scene", scene.toString(), "--own-colors");
        assertEquals(0, own.exitCode(), own.err());
        assertTrue(own.out().contains("identical                 100.00 %"), own.out());
        CliRun cued = CliRun.of("compare", mine.toString(), "--scene", scene.toString());
        assertEquals(ExitCode.SCENE_ERROR, cued.exitCode(), cued.out());
        CliRun both = CliRun.of("compare", mine.toString(), "--scene", scene.toString(), "--own-colors",
                "--near-color", "0,1,0");
        assertEquals(ExitCode.USAGE_ERROR, both.exitCode(), both.out());
        assertTrue(both.err().contains("--own-colors draws without the depth cue"), both.err());
        CliRun page = CliRun.of("compare", mine.toString(), "--page", "4", "--own-colors");
        assertEquals(ExitCode.USAGE_ERROR, page.exitCode(), page.out());
        assertTrue(page.err().contains("--own-colors goes with --scene only"), page.err());
    }

    /**
     * A report of a scene compared in its own colours says so in its first line, and the warning of a scene's
     * colours that the depth cue hides names compare's --own-colors, not render's alone: a student's picture of
     * vertex colours, held against the depth-cued scene, failed with a word only of render.
     */
    @Test
    void aSceneComparedInItsOwnColoursIsSaidToBe() throws Exception {
        Path scene = dir.resolve("tinted.simp");
        Files.writeString(scene, "polygon (-80, -80, -20, 1, 0, 0) (80, -80, -120, 0, 1, 0) (0, 80, -190, 0, 0, 1)\n");
        Path mine = dir.resolve("tinted.png");
        assertEquals(0, CliRun.of("render", "--scene", scene.toString(), "--own-colors", "--out", mine.toString())
                .exitCode());
        CliRun own = CliRun.of("compare", mine.toString(), "--scene", scene.toString(), "--own-colors");
        assertTrue(own.out().startsWith(mine + " against simpview's scene tinted.simp in its vertices' own colours\n"),
                own.out());
        CliRun cued = CliRun.of("compare", mine.toString(), "--scene", scene.toString());
        assertTrue(cued.out().startsWith(mine + " against simpview's scene tinted.simp\n"), cued.out());
        assertTrue(cued.err().contains("--own-colors (render, compare, check, inspect), or C in the window, draws"
                + " them"), cued.err());
    }

    /** A panel turned upside down fails, and is told why: the course's y runs up, an image's rows down. */
    @Test
    void anUpsideDownPanelIsToldSo() throws Exception {
        BufferedImage page = page(2);
        BufferedImage over = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        over.setData(page.getRaster());
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                over.setRGB(x, y, page.getRGB(x, 749 - y));
            }
        }
        CliRun run = CliRun.of("compare", png("over.png", over).toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nhint: your panel is simpview's upside down: so turned back, 100.00 % of the "
                + "pixels it then matches are within 8/255, exactly (" + format(asPrinted(independentDirect(page, over, 8)))
                + " % of the panel as it stands). Check how you turn y"), run.out());
    }

    @Test
    void aShiftedPageIsLowOnIdenticalButFullWithSlack() throws Exception {
        BufferedImage page = page(1);
        BufferedImage shifted = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        shifted.setData(page.getRaster());
        for (int y = 51; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                shifted.setRGB(x, y, page.getRGB(x, y - 1));
            }
        }
        for (int x = 50; x < 700; x++) {
            shifted.setRGB(x, 50, 0);
        }
        CliRun run = CliRun.of("compare", png("shifted.png", shifted).toString(), "--page", "1");
        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        double[] identical = printed(run.out(), "identical");
        assertTrue(identical[0] < 99, "identical share " + identical[0]);
        assertEquals(100.0, identical[1]);
        assertEquals(100.0, printed(run.out(), "within 8/255")[1]);
        // One pixel down is a shift of the whole panel: with slack it all matches.
        assertEquals(asPrinted(independentDirect(page, shifted, 0)), identical[0]);
        // It passes, and is still a panel a row down: the hint says so, and how that comes about.
        assertTrue(run.out().contains("hint: your panel is simpview's moved 1 px down: so moved back, 100.00 % of the "
                + "pixels it then matches are within 8/255"), run.out());
        assertTrue(run.out().contains("row 650 - y puts everything a row down"), run.out());
        // without slack the verdict says so, and never speaks of slack it does not have
        CliRun none = CliRun.of("compare", png("shifted0.png", shifted).toString(), "--page", "1", "--deviation", "0");
        assertEquals(1, none.exitCode(), "a failing comparison: " + none.out() + none.err());
        assertTrue(none.out().contains("no slack"), none.out());
        assertFalse(none.out().contains("with slack"), none.out());
        assertTrue(none.out().contains("FAIL: "), none.out());
    }

    @Test
    void aPassingPageWithASolidPatchMissingGetsANote() throws Exception {
        BufferedImage page = page(3);
        CliRun same = CliRun.of("compare", png("same.png", page).toString(), "--page", "3");
        assertEquals(ExitCode.OK, same.exitCode(), same.out() + same.err());
        assertFalse(same.out().contains("note:"), same.out());
        BufferedImage spoiled = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        spoiled.setData(page.getRaster());
        for (int y = 100; y < 130; y++) {
            for (int x = 400; x < 430; x++) {
                spoiled.setRGB(x, y, 0xFF00FF);
            }
        }
        CliRun run = CliRun.of("compare", png("spoiled.png", spoiled).toString(), "--page", "3");
        assertEquals(ExitCode.OK, run.exitCode(), "900 pixels of 422,500 still pass: " + run.out());
        // image rows 100-129 are panel rows 599-570 (y up, the panel's top at image row 50)
        assertTrue(run.out().contains("note: it passes, but a patch of 900 pixels differs (x 350-379, y 570-599 (30x30)"),
                run.out());
    }

    /**
     * A right page saved as JPEG fails (its colours change near every edge): compare says JPEG is lossy, as check
     * does, for the eight pages and the first assignment's alike, so the student does not hunt for the fault in
     * their renderer. A PNG that fails is told nothing of its format.
     */
    @Test
    void aFailingJpegIsToldJpegIsLossy() throws Exception {
        Path jpeg = jpeg("page2.jpg", page(2));
        CliRun run = CliRun.of("compare", jpeg.toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nnote: JPEG is lossy: saving a page as JPEG changes its colours near every edge, "
                + "so even a right page can fail; save it as PNG and hand that in\n"), run.out());

        Path a1 = jpeg("a1-page3.jpg", Assignment1.render(3, PageContext.defaults()));
        CliRun first = CliRun.of("compare", a1.toString(), "--assignment", "1", "--page", "3");
        assertEquals(ExitCode.SCENE_ERROR, first.exitCode(), first.out());
        assertTrue(first.out().contains("\nnote: JPEG is lossy: "), first.out());

        CliRun png = CliRun.of("compare", png("page3.png", page(3)).toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, png.exitCode(), png.out());
        assertFalse(png.out().contains("lossy"), png.out());
    }

    /**
     * The note goes by the format the picture was decoded as, not its name: a JPEG named page2.png is told it holds
     * one, and PNG bytes named page3.jpg that fail are told nothing of JPEG.
     */
    @Test
    void theFormatNoteGoesByWhatTheFileHolds() throws Exception {
        Path named = dir.resolve("named-png.png");
        Files.move(jpeg("page2.jpg", page(2)), named);
        CliRun run = CliRun.of("compare", named.toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("\nnote: named-png.png holds a JPEG picture: JPEG is lossy: saving a page as JPEG "
                + "changes its colours near every edge, so even a right page can fail; save it as PNG and hand that "
                + "in\n"), run.out());

        Path a1 = dir.resolve("a1-page3.png");
        Files.move(jpeg("a1-page3.jpg", Assignment1.render(3, PageContext.defaults())), a1);
        CliRun first = CliRun.of("compare", a1.toString(), "--assignment", "1", "--page", "3");
        assertEquals(ExitCode.SCENE_ERROR, first.exitCode(), first.out());
        assertTrue(first.out().contains("\nnote: a1-page3.png holds a JPEG picture: JPEG is lossy: "), first.out());

        Path pngBytes = dir.resolve("page3.jpg");
        Files.move(png("wrong.png", page(3)), pngBytes);
        CliRun png = CliRun.of("compare", pngBytes.toString(), "--page", "2");
        assertEquals(ExitCode.SCENE_ERROR, png.exitCode(), png.out());
        assertFalse(png.out().contains("lossy") || png.out().contains("JPEG"), png.out());
    }

    /**
     * A JPEG that passes is not told its margins are NOT white for pixels a JPEG leaves near white: its margins get
     * the slack a JPEG gets where its panel is found. The same pixels in a PNG are not white, as ever.
     */
    @Test
    void aPassingJpegsNearWhiteMarginsAreWhiteWithinItsSlack() throws Exception {
        BufferedImage page = page(2);
        BufferedImage greyish = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        greyish.setData(page.getRaster());
        // one 8x8 block of the top margin, JPEG's own block, 16/255 off white: what a JPEG's noise can leave there
        for (int y = 8; y < 16; y++) {
            for (int x = 96; x < 104; x++) {
                greyish.setRGB(x, y, 0xEFEFEF);
            }
        }
        CliRun run = CliRun.of("compare", jpeg("page2.jpg", greyish).toString(), "--page", "2", "--min", "98");
        assertEquals(ExitCode.OK, run.exitCode(), run.out());
        assertFalse(run.out().contains("NOT white"), run.out());
        assertTrue(run.out().contains("\nmargins: white within a JPEG's slack ("), run.out());

        CliRun png = CliRun.of("compare", png("page2.png", greyish).toString(), "--page", "2");
        assertEquals(ExitCode.OK, png.exitCode(), png.out());
        assertTrue(png.out().contains("\nmargins: NOT white: 64 of 140,000 pixels off by more than the tolerance (up to "
                + "16/255), the first at x 96, y 8 of the picture\n"), png.out());
    }

    /**
     * The picture as JPEG at quality 95, as an image program saves it "at high quality": its margins stay white
     * enough for the panel to be found (at ImageIO's 75 they do not), and its colours still change near edges.
     */
    private Path jpeg(String name, BufferedImage image) throws Exception {
        Path file = dir.resolve(name);
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpg").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
        param.setCompressionQuality(0.95f);
        try (ImageOutputStream out = ImageIO.createImageOutputStream(file.toFile())) {
            writer.setOutput(out);
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
        return file;
    }

    @Test
    void oneChannelOffByTwoIsNeverIdenticalButAlwaysWithinEight() throws Exception {
        BufferedImage page = page(2);
        BufferedImage off = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        off.setData(page.getRaster());
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                int rgb = page.getRGB(x, y);
                int r = rgb >> 16 & 0xFF;
                off.setRGB(x, y, rgb & 0xFF00FFFF | (r >= 254 ? r - 2 : r + 2) << 16);
            }
        }
        Path file = png("off.png", off);
        CliRun run = CliRun.of("compare", file.toString(), "--page", "2");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertEquals(0.0, printed(run.out(), "identical")[0]);
        assertEquals(0.0, printed(run.out(), "within 1/255")[0]);
        assertEquals(100.0, printed(run.out(), "within 8/255")[0]);
        assertEquals(100.0, printed(run.out(), "within 8/255")[1]);
        // With slack a few pixels of a gradient find their shifted colour next door.
        assertTrue(printed(run.out(), "identical")[1] < 1, run.out());
        CliRun strict = CliRun.of("compare", file.toString(), "--page", "2", "--tolerance", "1");
        assertEquals(ExitCode.SCENE_ERROR, strict.exitCode(), "below --min with --tolerance 1");
        assertTrue(strict.out().contains("FAIL: "), strict.out());
        // With slack many pixels of a gradient find a colour within 1/255 next door, but far from all.
        assertTrue(printed(strict.out(), "within 1/255")[1] < 50, strict.out());
    }

    @Test
    void theMinimumDecidesTheExitCodeAndTheRegionsAreListed() throws Exception {
        BufferedImage page = page(3);
        // A 100x40 red patch at panel x 200-299, y 500-539 (y up): picture rows 700-1-539 .. 700-1-500.
        for (int y = 500; y < 540; y++) {
            for (int x = 200; x < 300; x++) {
                page.setRGB(50 + x, 699 - y, 0xFF0000);
            }
        }
        Path file = png("patched.png", page);
        CliRun pass = CliRun.of("compare", file.toString(), "--page", "3");
        assertEquals(ExitCode.OK, pass.exitCode(), "4,000 of 422,500 pixels off is above 99 %: " + pass.out());
        assertTrue(pass.out().contains("  1. x 200-299, y 500-539 (100x40): 4,000 pixels"), pass.out());
        assertTrue(pass.out().contains("4,000 pixels in 1 patch differ by more than 8/255 even with slack\n"), pass.out());
        CliRun fail = CliRun.of("compare", file.toString(), "--page", "3", "--min", "99.5%");
        assertEquals(ExitCode.SCENE_ERROR, fail.exitCode());
        assertTrue(fail.out().contains("FAIL: 99.05 % within 8/255 with slack (99.50 % needed)"), fail.out());
    }

    @Test
    void oneLonePixelOffIsOnePixelInOnePatch() throws Exception {
        BufferedImage page = page(3);
        page.setRGB(50 + 10, 699 - 20, 0xFF00FF);
        page.setRGB(50 + 600, 699 - 610, 0xFF00FF);
        CliRun one = CliRun.of("compare", png("one.png", page).toString(), "--page", "3");
        assertTrue(one.out().contains("2 pixels in 2 patches differ by more than 8/255 even with slack; the largest\n"),
                one.out());
        assertTrue(one.out().contains(". x 10-10, y 20-20 (1x1): 1 pixel\n"), one.out());
        page.setRGB(50 + 600, 699 - 610, page(3).getRGB(50 + 600, 699 - 610));
        CliRun alone = CliRun.of("compare", png("alone.png", page).toString(), "--page", "3");
        assertTrue(alone.out().contains("1 pixel in 1 patch differs by more than 8/255 even with slack\n"), alone.out());
    }

    @Test
    void theDiffImageIsOursTheirsAndTheHeatMapAtOneToOne() throws Exception {
        BufferedImage theirs = page(2);
        theirs.setRGB(60, 60, 0x00FF00);
        Path diff = dir.resolve("out/diff.png");
        CliRun run = CliRun.of("compare", png("mine.png", theirs).toString(), "--page", "2", "--diff", diff.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        BufferedImage written = ImageIO.read(diff.toFile());
        assertEquals(1970, written.getWidth());
        assertEquals(650, written.getHeight());
        BufferedImage ours = page(2);
        for (int y = 0; y < 650; y += 13) {
            for (int x = 0; x < 650; x += 7) {
                assertEquals(ours.getRGB(50 + x, 50 + y) & 0xFFFFFF, written.getRGB(x, y) & 0xFFFFFF);
                assertEquals(theirs.getRGB(50 + x, 50 + y) & 0xFFFFFF, written.getRGB(660 + x, y) & 0xFFFFFF);
            }
        }
        assertEquals(0xFF0000, written.getRGB(1320 + 10, 10) >> 16 << 16 & 0xFF0000, "the changed pixel is red");
    }

    @Test
    void aSceneIsDrawnAsRenderDrawsIt() throws Exception {
        Path scene = Files.writeString(dir.resolve("tri.simp"), "polygon (-50,-50,-10) (50,-50,-10) (0,50,-100)\n");
        Path rendered = dir.resolve("tri.png");
        assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scene.toString(), "--near-color", "0,1,0",
                "--out", rendered.toString()).exitCode());
        CliRun same = CliRun.of("compare", rendered.toString(), "--scene", scene.toString(), "--near-color", "0,1,0");
        assertEquals(ExitCode.OK, same.exitCode(), same.err());
        assertEquals(100.0, printed(same.out(), "identical")[0]);
        CliRun other = CliRun.of("compare", rendered.toString(), "--scene", scene.toString());
        assertEquals(ExitCode.SCENE_ERROR, other.exitCode(), "white, not green: " + other.out());
        assertTrue(other.out().contains("against simpview's scene tri.simp"), other.out());
    }

    @Test
    void badPicturesGetAClearMessageAndExitOne() throws Exception {
        Path missing = dir.resolve("nope.png");
        Path corrupt = Files.write(dir.resolve("corrupt.png"), truncatedPng());
        Path text = Files.writeString(dir.resolve("notes.png"), "not a picture at all\n");
        Path small = png("small.png", new BufferedImage(640, 480, BufferedImage.TYPE_INT_RGB));
        BufferedImage blank = new BufferedImage(900, 800, BufferedImage.TYPE_INT_RGB);
        Path noPanel = png("blank.png", blank);
        String[][] cases = {
            {missing.toString(), missing + ": no such file"},
            {corrupt.toString(), corrupt + ": cannot be read as a picture, it is damaged or cut short"},
            {text.toString(), text + " is not a picture simpview can read (PNG, JPEG, GIF or BMP)"},
            {small.toString(), small + " is 640x480: too small to hold the 650x650 panel"},
            {noPanel.toString(), "no 650x650 panel found in " + noPanel + " (900x800)"},
            {dir.toString(), dir + " is a folder, not a picture"}};
        for (String[] c : cases) {
            CliRun run = CliRun.of("compare", c[0], "--page", "1");
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), c[0]);
            assertTrue(run.err().startsWith("simpview compare: " + c[1]), run.err());
            assertFalse(run.showsStackTrace(), run.err());
            assertEquals("", run.out());
        }
    }

    @Test
    void aTransparentPageIsRefusedAndSaysWhy() throws Exception {
        BufferedImage page = page(4);
        BufferedImage clear = new BufferedImage(page.getWidth(), page.getHeight(), BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < page.getHeight(); y++) {
            for (int x = 0; x < page.getWidth(); x++) {
                clear.setRGB(x, y, page.getRGB(x, y) & 0xFFFFFF);
            }
        }
        Path file = png("page4.png", clear);
        CliRun run = CliRun.of("compare", file.toString(), "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertEquals("simpview compare: " + file + ": 422,500 of the panel's 422,500 pixels are not opaque (alpha below "
                + "255), and a viewer shows what lies behind them, not their colours: save the picture without "
                + "transparency", run.err().strip());
        assertEquals("", run.out());
    }

    private byte[] truncatedPng() throws Exception {
        byte[] whole = Files.readAllBytes(png("whole.png", page(1)));
        byte[] half = new byte[whole.length / 2];
        System.arraycopy(whole, 0, half, 0, half.length);
        return half;
    }

    @Test
    void usageErrorsExitTwo() throws Exception {
        Path mine = png("page1.png", page(1));
        String[][] cases = {
            {"compare", mine.toString(), "--page", "9"},
            {"compare", mine.toString(), "--page", "0"},
            {"compare", mine.toString()},
            {"compare", "--page", "1"},
            {"compare", mine.toString(), "--page", "1", "--scene", "x.simp"},
            {"compare", mine.toString(), "--page", "1", "--tolerance", "300"},
            {"compare", mine.toString(), "--page", "1", "--min", "101"},
            {"compare", mine.toString(), "--page", "1", "--near-color", "0,1,0"},
            {"compare", mine.toString(), "--scene", "x.simp", "--seed", "3"},
            {"compare", mine.toString(), "--page", "1", "--out-dir", "x"},
            {"compare", "--dir", dir.toString(), "--pages", "1-8"},
            {"compare", "--dir", dir.toString(), "--pages", "1-9", "--out-dir", "x"},
            {"compare", "--dir", dir.toString(), "--out-dir", "x"},
            {"compare", mine.toString(), "--dir", dir.toString(), "--pages", "1", "--out-dir", "x"}};
        for (String[] args : cases) {
            CliRun run = CliRun.of(args);
            assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), String.join(" ", args) + "\n" + run.err());
            assertTrue(run.err().contains("See 'simpview compare --help'"), run.err()); // issue 14: the problem and one line, not the whole help
            assertFalse(run.showsStackTrace(), run.err());
        }
        assertTrue(CliRun.of("compare", mine.toString(), "--page", "9").err().contains("--page must be 1 to 8, not 9"));
    }

    @Test
    void aSceneErrorIsReportedWithItsPlaceAndExitsOne() throws Exception {
        Path mine = png("page1.png", page(1));
        Path bad = Files.writeString(dir.resolve("bad.simp"), "rotate x 30\n");
        CliRun run = CliRun.of("compare", mine.toString(), "--scene", bad.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode());
        assertTrue(run.err().contains(bad + ":1:"), run.err());
        assertFalse(run.showsStackTrace(), run.err());
    }

    @Test
    void helpNamesTheSubcommand() {
        CliRun help = CliRun.of("compare", "--help");
        assertEquals(ExitCode.OK, help.exitCode());
        assertTrue(help.out().contains("--tolerance"), help.out());
        assertTrue(CliRun.of("--help").out().contains("compare"));
    }

    /** The share of identical (within {@code tolerance}) panel pixels, plain loops over two pages. */
    static double independentDirect(BufferedImage a, BufferedImage b, int tolerance) {
        long same = 0;
        for (int y = 50; y < 700; y++) {
            for (int x = 50; x < 700; x++) {
                int p = a.getRGB(x, y);
                int q = b.getRGB(x, y);
                boolean close = Math.abs((p >> 16 & 255) - (q >> 16 & 255)) <= tolerance
                        && Math.abs((p >> 8 & 255) - (q >> 8 & 255)) <= tolerance
                        && Math.abs((p & 255) - (q & 255)) <= tolerance;
                same += close ? 1 : 0;
            }
        }
        return same / 422_500.0;
    }

    static String format(double percent) {
        return String.format(Locale.ROOT, "%.2f", percent);
    }

    /** A compare that fails before writing its --diff (no picture to read) gives the reader of that FIFO the end. */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aCompareThatCannotReadItsPictureGivesTheReaderOfTheDiffsFifoTheEnd() throws Exception {
        Path fifo = Fifos.make(dir.resolve("diff.png"));
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        Path missing = fifo.resolveSibling("missing.png");
        CliRun run = CliRun.of("compare", missing.toString(), "--page", "2", "--diff", fifo.toString());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
        assertTrue(run.err().startsWith("simpview compare: "), run.err());
        assertArrayEquals(new byte[0], Fifos.read(read, fifo));
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
    }

    /** A line picocli cannot parse never reaches compare: the readers of the FIFOs --diff and --junit name see the end. */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aLineThatCannotBeParsedGivesTheReaderOfTheDiffsFifoTheEnd() throws Exception {
        Path fifo = Fifos.make(dir.resolve("diff.png"));
        Path mine = dir.resolve("mine.png");
        RenderCommandTest.endSeenAfterAUsageError(fifo, "compare", mine.toString(), "--page", "2", "--diff",
                fifo.toString(), "--tolerence", "3");
        Path junit = Fifos.make(dir.resolve("results.xml"));
        RenderCommandTest.endSeenAfterAUsageError(junit, "compare", "--dir", dir.toString(), "--junit",
                junit.toString(), "--pages", "one");
    }

    /**
     * A line picocli cannot parse releases the tables a batch writes in --out-dir and the web report's
     * index.html in --html's folder (the tables too, without --out-dir); check's --out-dir alike.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aLineThatCannotBeParsedGivesTheReadersOfTheFifosInItsFoldersTheEnd() throws Exception {
        Path pictures = Files.createDirectories(dir.resolve("handed-in"));
        Path out = Files.createDirectories(dir.resolve("results"));
        Path web = Files.createDirectories(dir.resolve("web"));
        Path table = Fifos.make(out.resolve("compare.md"));
        Path index = Fifos.make(web.resolve("index.html"));
        Path csv = Fifos.make(web.resolve("compare.csv"));
        RenderCommandTest.endSeenAfterAUsageError(table, "compare", "--dir", pictures.toString(), "--pages", "one",
                "--out-dir", out.toString(), "--html", web.toString());
        RenderCommandTest.endSeenAfterAUsageError(index, "compare", "--dir", pictures.toString(), "--pages", "1-8",
                "--html=" + web, "--tolerence", "3");
        RenderCommandTest.endSeenAfterAUsageError(csv, "compare", "--dir", pictures.toString(), "--pages", "1-8",
                "--html", web.toString(), "--tolerence", "3");
        Path checked = Fifos.make(out.resolve("compare.csv"));
        RenderCommandTest.endSeenAfterAUsageError(checked, "check", pictures.toString(), "--out-dir", out.toString(),
                "--sede", "3");
        RenderCommandTest.endSeenAfterAUsageError(checked, "check", pictures.toString(), "--out-dir", out.toString(),
                "--pages", "1-3", "--scene", dir.resolve("house.simp").toString());
    }

    /**
     * A run into the out folder of an earlier one names the diff images it did not write itself: the earlier run's
     * of a picture that passes now. They are left where they are.
     */
    @Test
    void anEarlierRunsDiffImagesAreNamedAndLeft() throws Exception {
        Path pictures = Files.createDirectories(dir.resolve("handed-in"));
        Path page2 = pictures.resolve("page2.png");
        for (String[] picture : new String[][] {{"1", "page1.png"}, {"1", "page2.png"}}) {
            CliRun drawn = CliRun.of("render", "--page", picture[0], "--out", pictures.resolve(picture[1]).toString());
            assertEquals(ExitCode.OK, drawn.exitCode(), drawn.err());
        }
        Path out = dir.resolve("results");
        String[] compare = {"compare", "--dir", pictures.toString(), "--pages", "1-2", "--diffs", "failing",
            "--out-dir", out.toString()};
        CliRun first = CliRun.of(compare);
        assertEquals(ExitCode.SCENE_ERROR, first.exitCode(), first.err());
        Path diff = out.resolve("diffs").resolve("page2-diff.png");
        assertTrue(Files.isRegularFile(diff), "page 2 fails: its diff image is written");
        assertFalse(first.err().contains("did not write"), first.err());

        CliRun drawn = CliRun.of("render", "--page", "2", "--out", page2.toString());
        assertEquals(ExitCode.OK, drawn.exitCode(), drawn.err());
        CliRun second = CliRun.of(compare);
        assertEquals(ExitCode.OK, second.exitCode(), second.err());
        assertTrue(second.err().contains("note: " + out.resolve("diffs") + " also holds 1 diff image this run did not "
                + "write (page2-diff.png): an earlier run's, which no row of this one links; they are left as they are"),
                second.err());
        assertTrue(Files.isRegularFile(diff), "left where it was");
    }

    /**
     * A batch that writes diff images of failing pictures only writes none for a picture that passes: the reader
     * of a FIFO where that diff image would go sees the end, whether the run passes or fails.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theFifoOfADiffImageNotWrittenGivesItsReaderTheEnd() throws Exception {
        Path pictures = Files.createDirectories(dir.resolve("handed-in"));
        CliRun drawn = CliRun.of("render", "--page", "1", "--out", pictures.resolve("page1.png").toString());
        assertEquals(ExitCode.OK, drawn.exitCode(), drawn.err());
        Path out = dir.resolve("results");
        Path fifo = Fifos.make(Files.createDirectories(out.resolve("diffs")).resolve("page1-diff.png"));
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        CliRun run = CliRun.of("compare", "--dir", pictures.toString(), "--pages", "1", "--diffs", "failing",
                "--out-dir", out.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertArrayEquals(new byte[0], Fifos.read(read, fifo));
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
        assertTrue(Files.isRegularFile(out.resolve("compare.md")), "the table is written");
    }
}
