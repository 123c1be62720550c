package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.testing.CourseFiles;

/**
 * A line's (and a wire edge's) pixel drawn in the vertices' own colours,
 * explained: the ends' colours and t it prints, put through the sum it
 * says ((1 - t) start + t end, a shared channel as it is, times 255, rounded
 * half up), give the bytes the drawing put there, and so do its printed
 * levels. Lines every way (x- and y-major, walked from either end given) and
 * the course's own wire page.
 */
class OwnColourLineExplanationTest {

    @TempDir
    Path dir;

    private static final SceneLibrary LIBRARY = new SceneLibrary();
    private final PixelInspector inspector = new PixelInspector(LIBRARY, SceneMonitor.NONE);

    @Test
    void theArithmeticPrintedIsThePixelsBytes() throws Exception {
        Path scene = dir.resolve("lines.simp");
        Files.writeString(scene, String.join("\n",
                "line (-90, -80, -10, 1, 0, 0.2) (85, -60, -150, 0, 0.7, 1)",
                "line (70, 90, -20, 0.9, 0.9, 0.1) (-60, 20, -40, 0.1, 0.3, 0.8)",
                "line (-20, 95, -30, 0.3, 1, 0.5) (-5, -95, -60, 0.6, 0, 0)",
                "line (40, -90, -5, 0.25, 0.5, 0.75) (10, 80, -190, 0.75, 0.5, 0.25)",
                "wire",
                "polygon (20, 20, -50, 1, 0, 0) (90, 40, -60, 0, 1, 0) (40, 85, -70, 0, 0, 1)",
                ""));
        int checked = check(scene, 3);
        assertTrue(checked > 100, "too few line pixels checked: " + checked);
    }

    /**
     * The course's page 8: wire cubes, white at every vertex, so white at every pixel of their edges (every
     * eleventh pixel of every eleventh row: its filled cubes' pixels are replayed too, to learn they are filled).
     */
    @Test
    void theCoursesWireCubes() throws Exception {
        int checked = check(CourseFiles.requireSimpDir().resolve("page8.simp"), 11);
        assertTrue(checked > 20, "too few wire pixels checked: " + checked);
    }

    /** Checks every n-th drawn pixel of every n-th row that a line or wire edge drew; returns how many. */
    private int check(Path scene, int n) throws SceneException {
        InspectedScene inspected = InspectedScene.ownColours(scene);
        PageCanvas canvas = new PageCanvas();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(LIBRARY).withRules(inspected.rules())
                .withOwnColours(true), SceneMonitor.NONE);
        int checked = 0;
        for (int y = 0; y < PageCanvas.PANEL; y += n) {
            for (int x = 0; x < PageCanvas.PANEL; x += n) {
                int drawn = canvas.panel().getPixel(x, y);
                if ((drawn & 0xFFFFFF) == 0) {
                    continue;
                }
                Terms explained = inspector.inspect(inspected, x, y).explanation();
                String where = scene.getFileName() + " pixel (" + x + ", " + y + ")";
                assertNotNull(explained, where + ": drawn, but no write explained");
                if (explained.get("along") == null) {
                    // a filled triangle's pixel: its levels come from its span
                    continue;
                }
                checked++;
                checkSum(explained, drawn, where);
            }
        }
        return checked;
    }

    private static void checkSum(Terms explained, int drawn, String where) {
        int[] bytes = {drawn >>> 16 & 0xFF, drawn >>> 8 & 0xFF, drawn & 0xFF};
        Terms along = explained.terms("along");
        double t = along.number("t");
        assertTrue(t >= 0 && t <= 1, where + ": t " + t);
        double[] start = along.terms("start").vector("colour");
        double[] end = along.terms("end").vector("colour");
        double[] interpolated = explained.vector("interpolated");
        double[] levels = explained.vector("levels");
        int[] summed = new int[3];
        int[] rounded = new int[3];
        for (int c = 0; c < 3; c++) {
            double channel = start[c] == end[c] ? start[c] : (1 - t) * start[c] + t * end[c];
            assertEquals(channel, interpolated[c], 0, where + ": channel " + c + " is not the sum printed");
            summed[c] = (int) Math.max(0, Math.min(255, Math.floor(channel * 255 + 0.5)));
            rounded[c] = (int) Math.max(0, Math.min(255, Math.floor(levels[c] + 0.5)));
        }
        assertArrayEquals(bytes, summed, where + ": (1 - t) start + t end, rounded, is not the pixel");
        assertArrayEquals(bytes, rounded, where + ": the levels printed do not round to the pixel");
        assertArrayEquals(bytes, explained.bytes("final_rgb"), where + ": final_rgb");
        assertEquals(null, explained.get("note"), where + ": a note that the bytes differ");
    }
}
