package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * What {@code compare} tells a student of mistakes their own renderer's
 * picture shows, on panels made for each: the one pixel to look at first, a
 * background of another colour, edges a pixel off to one side.
 */
class StudentMistakesTest {

    private static final int N = Comparison.N;

    /** A panel of black with white 10x10 squares every 20 pixels: many edges. */
    private static int[] squares(int grow) {
        int[] panel = new int[N * N];
        for (int row = 0; row < N; row++) {
            for (int x = 0; x < N; x++) {
                boolean in = row % 20 >= 5 && row % 20 < 15 && x % 20 >= 5 && x % 20 < 15 + grow;
                panel[row * N + x] = in ? 0xFFFFFF : 0x000000;
            }
        }
        return panel;
    }

    private static String report(int[] ours, int[] theirs) throws CompareException {
        BufferedImage image = new BufferedImage(N, N, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, N, N, theirs, 0, N);
        Picture picture = Picture.of(image, "mine.png");
        return ComparisonReport.of(picture, "PAGE", Comparison.of(ours, picture.panel()), Comparison.DEFAULT_TOLERANCE,
                ComparisonReport.DEFAULT_MINIMUM).text();
    }

    @Test
    void squaresOnePixelWiderToTheRightAreToldTheirEdgesLieAPixelRight() throws Exception {
        String text = report(squares(0), squares(1));
        assertTrue(text.contains("PASS: "), text);
        assertTrue(text.contains("\nnote: 2.46 % of the panel differs by more than 8/255 as it stands but matches with"
                + " slack (yellow in the heat map): edges a pixel off."), text);
        assertTrue(text.contains("to its left (not its right) at 100.00 %, to its right (not its left) at 0.00 %"), text);
        assertTrue(text.contains(": your edges lie a pixel to the right of simpview's. Check which pixels"), text);
    }

    @Test
    void squaresOnePixelNarrowerAreToldTheirEdgesLieAPixelLeft() throws Exception {
        String text = report(squares(1), squares(0));
        assertTrue(text.contains(": your edges lie a pixel to the left of simpview's. Check"), text);
    }

    /** The same squares, all moved a pixel: the hint names the move, and no note of edges says it again. */
    @Test
    void aWholePanelMovedIsTheHintsNotANoteOfEdges() throws Exception {
        int[] moved = new int[N * N];
        int[] ours = squares(0);
        for (int i = 0; i < moved.length; i++) {
            moved[i] = i % N == 0 ? 0 : ours[i - 1];
        }
        String text = report(ours, moved);
        assertTrue(text.contains("hint: your panel is simpview's moved 1 px right"), text);
        assertFalse(text.contains("edges a pixel off"), text);
        // moved 3 pixels it fails: the hint says why, and no pixel of it is pointed to
        for (int i = 0; i < moved.length; i++) {
            moved[i] = i % N < 3 ? 0 : ours[i - 3];
        }
        String failing = report(ours, moved);
        assertTrue(failing.contains("FAIL: "), failing);
        assertTrue(failing.contains("hint: your panel is simpview's moved 3 px right"), failing);
        assertFalse(failing.contains("look:"), failing);
    }

    @Test
    void aBackgroundOfAnotherColourIsSaidWithWhatWasMeasured() throws Exception {
        int[] ours = squares(0);
        int[] theirs = ours.clone();
        for (int i = 0; i < theirs.length; i++) {
            theirs[i] = theirs[i] == 0 ? 0x191919 : theirs[i];
        }
        String text = report(ours, theirs);
        assertTrue(text.contains("FAIL: "), text);
        assertTrue(text.contains("\nnote: where simpview's panel is (0,0,0), its most common colour (75.00 % of the"
                + " panel: the background, where nothing is drawn), yours is (25,25,25) at 100.00 % of those pixels; the"
                + " rest of the panel is within 8/255 at 100.00 %, exactly: is the colour your panel is cleared to the"
                + " course's, (0,0,0)?\n"), text);
        // the same panel with its squares wrong as well is told so: the rest is not within
        for (int i = 0; i < theirs.length; i++) {
            theirs[i] = theirs[i] == 0xFFFFFF ? 0x808080 : theirs[i];
        }
        assertTrue(report(ours, theirs).contains("the rest of the panel is within 8/255 at 0.00 %, exactly"));
    }

    /** A background that differs here and there, as a mistake in the drawing leaves it, is no background's. */
    @Test
    void aPatchOnTheBackgroundIsNoBackgroundOfAnotherColour() throws Exception {
        int[] ours = squares(0);
        int[] theirs = ours.clone();
        for (int row = 100; row < 300; row++) {
            for (int x = 100; x < 300; x++) {
                theirs[row * N + x] = 0x191919;
            }
        }
        String text = report(ours, theirs);
        assertTrue(text.contains("FAIL: "), text);
        assertFalse(text.contains("most common colour"), text);
    }

    /**
     * A failing picture is pointed to the pixel that differs most in its largest patch, in panel coordinates, with
     * both colours and which way the patch differs; a picture that passes with no solid patch is not.
     */
    @Test
    void aFailingPictureIsPointedToThePixelThatDiffersMostInItsLargestPatch() throws Exception {
        int[] ours = new int[N * N];
        Arrays.fill(ours, 0x404040);
        int[] theirs = ours.clone();
        for (int row = 100; row < 180; row++) {
            for (int x = 200; x < 280; x++) {
                theirs[row * N + x] = 0x707070;
            }
        }
        theirs[150 * N + 230] = 0xA05040;
        theirs[10 * N + 10] = 0x000000; // a patch of one pixel elsewhere, darker
        String text = report(ours, theirs);
        assertTrue(text.contains("FAIL: "), text);
        assertTrue(text.contains("\nlook:    x 230, y 499 differs most in patch 1: yours (160,80,64), simpview's"
                + " (64,64,64); of the patch's 6,400 pixels that differ, yours is brighter at 100.00 % and darker at"
                + " 0.00 %\n"), text);
        int[] passing = ours.clone();
        passing[10 * N + 10] = 0x000000;
        assertFalse(report(ours, passing).contains("look:"), report(ours, passing));
    }
}
