package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;

import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Finding the 650x650 panel in pages, window captures and pictures that have none. */
class PanelFinderTest {

    /** A made-up window capture: grey chrome, a white area, and a page's panel at (left, top). */
    private static BufferedImage capture(BufferedImage page, int width, int height, int left, int top) {
        BufferedImage capture = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                boolean white = x >= left - 50 && x < left + 700 && y >= top - 50 && y < top + 700;
                capture.setRGB(x, y, white ? 0xFFFFFF : 0xE0E0E8 - (x + y) % 7);
            }
        }
        for (int y = 0; y < 650; y++) {
            for (int x = 0; x < 650; x++) {
                capture.setRGB(left + x, top + y, page.getRGB(50 + x, 50 + y));
            }
        }
        return capture;
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 3, 5})
    void findsThePanelOfACaptureAtAnOddPlace(int number) throws Exception {
        BufferedImage page = page(number);
        Picture found = Picture.of(capture(page, 900, 811, 73, 111), "capture");
        assertEquals(73, found.place().left());
        assertEquals(111, found.place().top());
        assertEquals(1.0, Comparison.of(Picture.ofPage(page, "page").panel(), found.panel()).share(0, false));
        assertTrue(found.margins(8).white(), found.margins(8).describe());
    }

    @Test
    void findsAPanelWhoseContentIsMostlyWhiteAndTouchesItsEdges() throws Exception {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                boolean panel = x >= 50 && x < 700 && y >= 50 && y < 700;
                // In the panel: white except a black band along the left and bottom edges and a grid.
                boolean dark = panel && (x < 60 || y > 690 || x % 50 == 0);
                page.setRGB(x, y, dark ? 0 : 0xFFFFFF);
            }
        }
        Picture found = Picture.of(capture(page, 820, 790, 60, 90), "white-ish");
        assertEquals(60, found.place().left());
        assertEquals(90, found.place().top());
    }

    @Test
    void aPageIsTakenWhereAPageHasItsPanel() throws Exception {
        Picture found = Picture.of(page(2), "page2.png");
        assertEquals(new PanelPlace(50, 50, "a 750x750 page"), found.place());
    }

    @Test
    void aPageWhosePanelIsElsewhereSaysSo() throws Exception {
        BufferedImage page = page(3);
        BufferedImage moved = capture(page, 750, 750, 52, 49);
        Picture found = Picture.of(moved, "moved.png");
        assertEquals(52, found.place().left());
        assertEquals(49, found.place().top());
        assertTrue(found.place().how().contains("not at x 50, y 50"), found.place().how());
    }

    @Test
    void aBarePanelIsTheWholePicture() throws Exception {
        BufferedImage bare = new BufferedImage(650, 650, BufferedImage.TYPE_INT_RGB);
        Picture found = Picture.of(bare, "bare.png");
        assertEquals(0, found.place().left());
        assertEquals(0, found.margins(8).checked());
        assertEquals("none in the picture", found.margins(8).describe());
    }

    @Test
    void refusesPicturesTooSmallToHoldAPanel() {
        CompareException e = assertThrows(CompareException.class,
                () -> Picture.of(new BufferedImage(649, 800, BufferedImage.TYPE_INT_RGB), "small.png"));
        assertEquals("small.png is 649x800: too small to hold the 650x650 panel (a page is 750x750)", e.getMessage());
    }

    @Test
    void refusesPicturesWithNoPanel() {
        BufferedImage white = new BufferedImage(800, 700, BufferedImage.TYPE_INT_RGB);
        BufferedImage noise = new BufferedImage(800, 700, BufferedImage.TYPE_INT_RGB);
        Random random = new Random(1);
        for (int y = 0; y < 700; y++) {
            for (int x = 0; x < 800; x++) {
                white.setRGB(x, y, 0xFFFFFF);
                noise.setRGB(x, y, random.nextInt(0x1000000));
            }
        }
        for (BufferedImage picture : new BufferedImage[] {white, noise}) {
            CompareException e = assertThrows(CompareException.class, () -> Picture.of(picture, "x.png"));
            assertTrue(e.getMessage().startsWith("no 650x650 panel found in x.png (800x700)"), e.getMessage());
        }
    }

    /**
     * A white 700x700 picture whose only other pixels are a 650x650 square's border at (20, 20), dark on 649 of its
     * 2,596 pixels, the 25 % a panel needs; and, when asked, the row above with just the 90 % of the square's width
     * white that a frame needs, dark elsewhere. The search's shortcuts skip a place only where its count falls short.
     */
    private static int[] framedAtTheEdge(int dark, boolean rowAboveAtItsLeast) {
        int size = 700;
        int[] rgb = new int[size * size];
        Arrays.fill(rgb, 0xFFFFFF);
        int left = 20;
        int top = 20;
        int right = left + 649;
        int bottom = top + 649;
        int[] sides = {dark - 3 * (dark / 4), dark / 4, dark / 4, dark / 4}; // top, bottom, left, right
        for (int i = 0; i < sides[0]; i++) {
            rgb[top * size + left + 4 * i] = 0x101010;
        }
        for (int i = 0; i < sides[1]; i++) {
            rgb[bottom * size + left + 2 + 4 * i] = 0x101010;
        }
        for (int i = 0; i < sides[2]; i++) {
            rgb[(top + 1 + 4 * i) * size + left] = 0x101010;
            rgb[(top + 3 + 4 * i) * size + right] = 0x101010;
        }
        if (rowAboveAtItsLeast) {
            for (int x = 0; x < size; x++) {
                boolean white = x >= left && x < left + 585; // 585 of 650: ceil(0.9 * 650)
                rgb[(top - 1) * size + x] = white ? 0xFFFFFF : 0x101010;
            }
        }
        return rgb;
    }

    @Test
    void aPanelWithJustEnoughDarkBorderAndWhiteFrameIsFoundAndWithOnePixelLessIsNot() throws Exception {
        for (boolean rowAbove : new boolean[] {false, true}) {
            PanelPlace found = PanelFinder.find(framedAtTheEdge(649, rowAbove), 700, 700, "edge.png");
            assertEquals(20, found.left());
            assertEquals(20, found.top());
        }
        assertEquals(null, PanelFinder.framedPanel(framedAtTheEdge(648, false), 700, 700));
        int[] rowShort = framedAtTheEdge(649, true);
        rowShort[19 * 700 + 20] = 0x101010; // 584 white above the square
        assertEquals(null, PanelFinder.framedPanel(rowShort, 700, 700));
    }

    @Test
    void aScaledPageIsRefusedAndCalledScaled() throws Exception {
        BufferedImage page = page(3);
        for (int size : new int[] {700, 1500}) {
            BufferedImage scaled = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = scaled.createGraphics();
            g.drawImage(page, 0, 0, size, size, null);
            g.dispose();
            CompareException e = assertThrows(CompareException.class, () -> Picture.of(scaled, "scaled.png"));
            assertTrue(e.getMessage().startsWith("no 650x650 panel found in scaled.png (" + size + "x" + size + ")"),
                    e.getMessage());
            assertTrue(e.getMessage().endsWith(size == 700
                    ? "it has the shape of a 750x750 page, scaled by 0.933: save the picture at its own size (1:1, no "
                    + "scaling)" : "it holds the panel scaled by 2.00: a 1300x1300 square at x 100, y 100 with white "
                    + "margins around it and a dark edge inside (a HiDPI screen, or a desktop at 125 % or 150 %, "
                    + "captures so); a scaled picture cannot be compared pixel for pixel: save the page itself "
                    + "(750x750), or capture the window with the display at 100 % (1:1, no scaling)"), e.getMessage());
        }
        assertEquals("", PanelFinder.scaled(800, 700), "not a page's shape");
    }

    /** The picture drawn {@code scale} times its size, each pixel's colour from the nearest or a smooth blend. */
    private static BufferedImage scaled(BufferedImage picture, double scale, boolean smooth) {
        int width = (int) Math.round(picture.getWidth() * scale);
        int height = (int) Math.round(picture.getHeight() * scale);
        BufferedImage scaled = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = scaled.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, smooth ? RenderingHints.VALUE_INTERPOLATION_BILINEAR
                : RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g.drawImage(picture, 0, 0, width, height, null);
        g.dispose();
        return scaled;
    }

    /**
     * A HiDPI capture of a window of another size than the course's 872x782 has no page's shape to go by: the panel
     * is found drawn at 2x (each pixel doubled), or at 1.5x by a smooth scaling, and the picture is told its scale.
     */
    @Test
    void aHiDpiCaptureOfAWindowOfAnotherSizeIsToldItsScale() throws Exception {
        BufferedImage capture = capture(page(3), 800, 760, 60, 85);
        CompareException doubled = assertThrows(CompareException.class,
                () -> Picture.of(scaled(capture, 2, false), "hidpi.png"));
        assertEquals("no 650x650 panel found in hidpi.png (1600x1520): looked for a square with white margins around "
                + "it and a dark edge inside; it holds the panel scaled by 2.00: a 1300x1300 square at x 120, y 170 "
                + "with white margins around it and a dark edge inside (a HiDPI screen, or a desktop at 125 % or "
                + "150 %, captures so); a scaled picture cannot be compared pixel for pixel: save the page itself "
                + "(750x750), or capture the window with the display at 100 % (1:1, no scaling)",
                doubled.getMessage());
        CompareException smooth = assertThrows(CompareException.class,
                () -> Picture.of(scaled(capture, 1.5, true), "desktop150.png"));
        assertTrue(smooth.getMessage().startsWith("no 650x650 panel found in desktop150.png (1200x1140): looked for a "
                + "square with white margins around it and a dark edge inside; it holds the panel scaled by 1.50: a "),
                smooth.getMessage());
    }

    /** A page saved at half size is smaller than the panel, and told it is the page at 0.5, not only too small. */
    @Test
    void aHalfSizePageIsToldItsScaleNotOnlyThatItIsTooSmall() throws Exception {
        CompareException e = assertThrows(CompareException.class,
                () -> Picture.of(scaled(page(3), 0.5, true), "half.png"));
        assertEquals("half.png is 375x375: too small to hold the 650x650 panel (a page is 750x750); it holds the panel "
                + "scaled by 0.500: a 325x325 square at x 25, y 25 with white margins around it and a dark edge "
                + "inside (a screenshot tool saving a smaller copy makes one so); a scaled picture cannot be compared "
                + "pixel for pixel: save the page itself (750x750), or capture the window with the display at 100 % "
                + "(1:1, no scaling)", e.getMessage());
    }

    /**
     * A picture that is no page, large or small, with a dark shape framed in white that is no panel at any scale (not
     * square), is told what it was told before: no panel, or too small, and no scale.
     */
    @Test
    void aPictureThatIsNoPageIsToldNoScale() {
        for (int scale : new int[] {1, 2}) {
            BufferedImage picture = new BufferedImage(500 * scale, 350 * scale, BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < picture.getHeight(); y++) {
                for (int x = 0; x < picture.getWidth(); x++) {
                    boolean dark = x >= 20 * scale && x < 420 * scale && y >= 20 * scale && y < 330 * scale;
                    picture.setRGB(x, y, dark ? 0x101010 : 0xFFFFFF);
                }
            }
            CompareException e = assertThrows(CompareException.class, () -> Picture.of(picture, "photo.png"));
            assertEquals(scale == 1 ? "photo.png is 500x350: too small to hold the 650x650 panel (a page is 750x750)"
                    : "no 650x650 panel found in photo.png (1000x700): looked for a square with white margins around it "
                    + "and a dark edge inside", e.getMessage());
        }
    }

    @Test
    void marginsThatAreNotWhiteAreCountedAndTheFirstIsNamed() throws Exception {
        BufferedImage page = page(1);
        page.setRGB(3, 7, 0x000000);
        page.setRGB(720, 720, 0xFEFEFE);
        Margins margins = Picture.of(page, "p.png").margins(8);
        assertEquals(140_000, margins.checked());
        assertEquals(2, margins.notWhite());
        assertEquals(1, margins.offByMore());
        assertEquals(3, margins.firstX());
        assertEquals(7, margins.firstY());
        assertTrue(margins.describe().startsWith("NOT white: 1 of 140,000 pixels"), margins.describe());
    }

    static Stream<String> coursePictures() {
        return Stream.of("a2/page1_mesh_wire.png", "a2/page2_mesh_filled.jpg", "a2/page3_zbuffer_triangles.png",
                "a2/page4_tomsPage4_green.png", "a2/page5_tomsPage5_red.png", "a2/page6.png", "a2/page7.png",
                "a2/page8.png", "a3/pageA.png", "a3/pageB.png", "a3/pageC.png", "a3/pageD.png", "a3/pageE.png",
                "a3/pageF.png", "a3/pageG.png", "a3/pageH.png", "a3/pageI.png", "a3/pageJ_tomsPageJ.png");
    }

    /** The course's own pictures are 872x782 window captures with the panel at x 51-700, y 81-730. */
    @ParameterizedTest
    @MethodSource("coursePictures")
    void findsThePanelInEachOfTheCoursesOwnPictures(String name) throws Exception {
        Path file = CourseFiles.require("reference/images/" + name);
        assertTrue(Files.isRegularFile(file));
        Picture picture = Picture.read(file);
        assertEquals(51, picture.place().left(), name);
        assertEquals(81, picture.place().top(), name);
        // JPEG rings near the panel's edge: its margins are off white by up to 32/255 there.
        assertTrue(picture.margins(name.endsWith(".jpg") ? 40 : 0).white(), name + ": " + picture.margins(0).describe());
    }
}
