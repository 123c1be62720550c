package simpview.scene;

import simpview.scene.SceneException;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertFalse;
import simpview.testing.DrawnScenes;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.testing.ThreadCounts;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import simpview.scene.simp.SceneLibrary;

/** Lit scenes drawn end to end, checked against what the rules say by hand. */
class LitScenesTest {

    @TempDir
    Path dir;

    private Path write(String name, String... lines) throws IOException {
        Path file = dir.resolve(name + ".simp");
        Files.write(file, String.join("\n", lines).getBytes(StandardCharsets.UTF_8));
        return file;
    }

    private PageCanvas draw(String... lines) throws Exception {
        PageCanvas canvas = new PageCanvas();
        ScenePipeline.draw(write("s", lines), canvas, ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE);
        return canvas;
    }

    private SceneException failure(String... lines) throws Exception {
        Path file = write("bad", lines);
        return assertThrows(SceneException.class,
                () -> ScenePipeline.draw(file, new PageCanvas(), ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE));
    }

    /** A monitor that keeps every warning it is told in {@code warnings}. */
    private static SceneMonitor keeping(List<String> warnings) {
        return new SceneMonitor() {
            @Override
            public void warning(String message) {
                warnings.add(message);
            }
        };
    }

    /** The warnings of one drawing of {@code scene} on a fresh canvas, its files kept by {@code library}. */
    private static List<String> warningsOf(Path scene, SceneLibrary library)
            throws Exception {
        List<String> warnings = new ArrayList<>();
        ScenePipeline.draw(scene, new PageCanvas(), ScenePipeline.Options.lit(library), keeping(warnings));
        return warnings;
    }

    private static int[] rgb(PageCanvas canvas, int x, int y) {
        int p = canvas.panel().getPixel(x, y);
        return new int[] {p >> 16 & 0xFF, p >> 8 & 0xFF, p & 0xFF};
    }

    @Test
    void aRecedingQuadsColourMidpointIsWherePerspectivePutsIt() throws Exception {
        // A floor at y = -1 from z = -2 (red) to z = -10 (blue), seen from the origin.
        PageCanvas canvas = draw("ambient 1 1 1", "camera -1 -1 1 1 -1 -100",
                "polygon (-1, -1, -2, 1, 0, 0) (1, -1, -2, 1, 0, 0) (1, -1, -10, 0, 0, 1)",
                "polygon (-1, -1, -2, 1, 0, 0) (1, -1, -10, 0, 0, 1) (-1, -1, -10, 0, 0, 1)");
        int best = -1;
        int bestGap = 256;
        for (int row = 0; row < 650; row++) {
            int[] c = rgb(canvas, 325, row);
            if (c[0] + c[2] > 0 && Math.abs(c[0] - c[2]) < bestGap) {
                bestGap = Math.abs(c[0] - c[2]);
                best = row;
            }
        }
        // Half way in colour is half way in camera space: z = -6, y' = -1/6, panel y = (y' + 1) * 325.
        double perspective = (-1.0 / 6 + 1) * 325;
        double screenMidpoint = ((-0.5 + -0.1) / 2 + 1) * 325;
        assertTrue(Math.abs(best + 0.5 - perspective) <= 1.5, "colour midpoint at row " + best + ", expected "
                + perspective);
        assertTrue(Math.abs(best - screenMidpoint) > 30, "not at the screen midpoint " + screenMidpoint);
    }

    @Test
    void aWideWindowIsACentredBandOfItsAspect() throws Exception {
        // pageH's window: twice as wide as high, so a 650x325 band in the middle of the panel.
        PageCanvas canvas = draw("ambient 1 1 1", "camera -2 -1 2 1 -1 -100",
                "polygon (-1000, -1000, -10) (1000, -1000, -10) (0, 1000, -10)",
                "polygon (-1000, -1000, -10) (1000, 1000, -10) (-1000, 1000, -10)",
                "polygon (1000, -1000, -10) (1000, 1000, -10) (-1000, 1000, -10)");
        int lowest = 650;
        int highest = -1;
        for (int y = 0; y < 650; y++) {
            for (int x = 0; x < 650; x++) {
                if (rgb(canvas, x, y)[0] != 0) {
                    lowest = Math.min(lowest, y);
                    highest = Math.max(highest, y);
                }
            }
            if (y > 170 && y < 480) {
                assertEquals(255, rgb(canvas, 0, y)[0], "left column, row " + y);
                assertEquals(255, rgb(canvas, 649, y)[0], "right column, row " + y);
            }
        }
        // The band is y in [162.5, 487.5]: the rows whose centres are inside it, give or take its edges.
        assertTrue(lowest >= 162 && lowest <= 163, "lowest row " + lowest);
        assertTrue(highest >= 486 && highest <= 487, "highest row " + highest);
    }

    @Test
    void fogAtNearFarAndHalfWay() throws Exception {
        // Parallel view (no camera): red squares at z = -40, -100 and -160 in a blue fog from -50 to -150.
        PageCanvas canvas = draw("ambient 1 1 1", "surface 1 0 0", "depth -50 -150 0 0 1",
                "polygon (-90, -10, -40) (-70, -10, -40) (-70, 10, -40)",
                "polygon (-10, -10, -100) (10, -10, -100) (10, 10, -100)",
                "polygon (70, -10, -160) (90, -10, -160) (90, 10, -160)");
        int y = 325 - 10;
        assertEquals(List.of(255, 0, 0), list(rgb(canvas, (int) ((-72 + 100) * 3.25), y)), "nearer than near");
        assertEquals(List.of(128, 0, 128), list(rgb(canvas, (int) ((8 + 100) * 3.25), y)), "half way");
        assertEquals(List.of(0, 0, 255), list(rgb(canvas, (int) ((88 + 100) * 3.25), y)), "farther than far");
    }

    private static List<Integer> list(int[] c) {
        return List.of(c[0], c[1], c[2]);
    }

    @Test
    void withoutLightsAFilledPolygonIsKdTimesAmbient() throws Exception {
        PageCanvas canvas = draw("ambient 0.5 1 0.25", "surface 1 0.5 1",
                "polygon (-50, -50, -100) (50, -50, -100) (0, 50, -100)");
        assertEquals(List.of(128, 128, 64), list(rgb(canvas, 325, 325)));
    }

    /**
     * The z-buffer of a lit picture starts at -infinity (SPEC Part 2), not at
     * Part 1's far plane: a camera's view reaches as far as its yon plane, and
     * what lies beyond z = -200 there is drawn like the rest.
     */
    @Test
    void whatACameraSeesBeyondMinus200IsDrawn() throws Exception {
        for (int threads : ThreadCounts.ALL) {
            for (double z : new double[] {-150, -500, -999}) {
                Path scene = write("far", "camera -1 -1 1 1 -1 -1000", "ambient 1 1 1",
                        "polygon (" + 0.2 * z + ", " + 0.2 * z + ", " + z + ") (" + -0.2 * z + ", " + 0.2 * z + ", "
                                + z + ") (0, " + -0.2 * z + ", " + z + ")");
                PageCanvas canvas = new PageCanvas();
                try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                    canvas.drawWith(drawing);
                    ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE);
                }
                // The triangle covers x' and y' in [-0.2, 0.2] on the window: panel 260 to 390.
                String where = "a triangle at z = " + z + ", " + threads + " threads";
                assertEquals(List.of(255, 255, 255), list(rgb(canvas, 325, 300)), where);
                assertEquals(List.of(0, 0, 0), list(rgb(canvas, 250, 300)), "beside " + where);
            }
        }
    }

    @Test
    void wirePolygonsAndLinesCarryKdUnlit() throws Exception {
        PageCanvas canvas = draw("ambient 0 0 0", "surface 0 1 0", "wire",
                "polygon (-50, -50, -100) (50, -50, -100) (0, 50, -100)", "line (-80, 80, -100) (80, 80, -100)");
        assertEquals(List.of(0, 255, 0), list(rgb(canvas, 325, (int) (180 * 3.25))));
        // The triangle's bottom-left corner is at panel (162.5, 162.5): the lines' rounded end is (163, 163).
        assertEquals(List.of(0, 255, 0), list(rgb(canvas, 163, 163)));
    }

    @Test
    void aCameraInsideAClosedBoxSeesItsInside() throws Exception {
        Files.copy(Path.of("simp/cube.simp"), dir.resolve("cube.simp"));
        PageCanvas canvas = draw("ambient 1 1 1", "camera -1 -1 1 1 -0.1 -200",
                "{", "scale 20 20 20", "translate -0.5 -0.5 -0.5", "file \"cube\"", "}");
        int lit = 0;
        for (int y = 0; y < 650; y += 13) {
            for (int x = 0; x < 650; x += 13) {
                lit += rgb(canvas, x, y)[0] > 0 ? 1 : 0;
            }
        }
        assertEquals(50 * 50, lit, "every direction looks at a wall of the box");
    }

    /**
     * A vertex at x = 1e20, far beyond the right side: the clipped triangle is the shape the plane cuts, pixel
     * for pixel (those whose centres lie within 0.01 of an edge left aside): on the window plane z = -1 it is
     * (-0.5, -0.5), (1e19, -0.5), (0, 0.5), cut at x' = 1. Before, its crossing on the upper edge came out at
     * (0, 5, -10) again, and a diagonal from there to the lower right corner took away a quarter of it.
     */
    @Test
    void aVertexFarOutsideTheViewIsClippedToItsShape() throws Exception {
        PageCanvas canvas = draw("camera -1 -1 1 1 -0.1 -200", "ambient 1 1 1",
                "polygon (-5, -5, -10) (1e20, -5, -10) (0, 5, -10)");
        int compared = 0;
        for (int j = 0; j < 650; j++) {
            for (int i = 0; i < 650; i++) {
                double x = i + 0.5;
                double y = j + 0.5;
                // panel = (x' + 1) * 325: bottom y = 162.5, top y = 487.5 (the edge falls 1e-19 over the window),
                // left edge from (162.5, 162.5) to (325, 487.5)
                double[] margins = {y - 162.5, 487.5 - y, x - (162.5 + (y - 162.5) / 2)};
                boolean inside = true;
                boolean near = false;
                for (double m : margins) {
                    inside &= m > 0;
                    near |= Math.abs(m) < 0.01;
                }
                if (!near) {
                    compared++;
                    assertEquals(inside, rgb(canvas, i, j)[0] != 0, "pixel " + i + ", " + j);
                }
            }
        }
        assertTrue(compared > 650 * 640, "compared " + compared);
    }

    /**
     * Hither and yon are camera-space z values, below 0 in front of the eye. Given as distances in front of it,
     * as OpenGL's near and far are, or swapped, the error says what they most likely meant.
     */
    @Test
    void theCamerasPlanesGivenAsDistancesOrSwappedSayWhatWasMeant() throws Exception {
        assertEquals("the planes need 0 > hither > yon, found hither 0.1 and yon 100.0: they are z values, and the"
                + " camera looks down its -z axis, so what it sees has z below 0; as distances in front of it they are"
                + " hither -0.1 and yon -100", failure("camera -1 -1 1 1 0.1 100").problem());
        assertEquals("the planes need 0 > hither > yon, found hither -200.0 and yon -1.0: hither is the near plane"
                + " and yon the far one, further below 0: swap them", failure("camera -1 -1 1 1 -200 -1").problem());
        assertEquals("the planes need 0 > hither > yon, found hither -1.0 and yon -1.0",
                failure("camera -1 -1 1 1 -1 -1").problem());
    }

    /** The fog's near and far are camera-space z values too: given as distances, or swapped, the error says so. */
    @Test
    void theFogsPlanesGivenAsDistancesOrSwappedSayWhatWasMeant() throws Exception {
        assertEquals("fog needs near > far (camera-space z, far more negative), found near 0.0 and far 200.0: they are"
                + " z values, below 0 in front of the camera; as distances in front of it they are depth 0 -200",
                failure("depth 0 200 0 0 0").problem());
        assertEquals("fog needs near > far (camera-space z, far more negative), found near -50.0 and far -10.0: near"
                + " is the nearer z and far the one further below 0: swap them", failure("depth -50 -10 0 0 0").problem());
        assertEquals("fog needs near > far (camera-space z, far more negative), found near -10.0 and far -10.0",
                failure("depth -10 -10 0 0 0").problem());
    }

    @Test
    void theCameraIsCheckedAtItsLine() throws Exception {
        assertEquals("the planes need 0 > hither > yon, found hither 0.0 and yon -200.0: hither 0 is the eye itself,"
                + " where nothing can be projected; give it a small number below 0, such as -0.1",
                failure("camera -1 -1 1 1 0 -200").problem());
        assertTrue(failure("camera 1 -1 -1 1 -1 -200").problem().contains("xlow < xhigh"));
        // the caret under the number at fault: ylow, hither at 0 or above, else yon
        assertEquals(11, failure("camera -1 1 1 -1 -1 -200").column());
        assertEquals(18, failure("camera -1 -1 1 1 0 -200").column());
        assertEquals(23, failure("camera -1 -1 1 1 -100 -1").column());
        SceneException singular = failure("scale 1 0 1", "camera -1 -1 1 1 -1 -200");
        assertEquals(2, singular.line());
        assertTrue(singular.problem().contains("cannot be inverted"), singular.problem());
        // A CTM that is finite but whose inverse is not (1e-310 inverts to 1e310): an overflow, not a scale of 0.
        SceneException tiny = failure("scale 1e-310 1 1", "camera -1 -1 1 1 -1 -200");
        assertEquals(2, tiny.line());
        assertEquals("the CTM at the camera cannot be inverted: its inverse overflows (holds numbers beyond about"
                + " 1.8e308, a scale too near 0?), so there is no way from the world to the camera", tiny.problem());
        assertFalse(singular.problem().contains("overflows"), singular.problem());
        // A CTM that overflows itself is named at the transform that overflowed it, before the camera.
        SceneException huge = failure("scale 1e200 1e200 1e200", "scale 1e200 1e200 1e200", "camera -1 -1 1 1 -1 -10");
        assertEquals(2, huge.line());
        assertTrue(huge.problem().startsWith("the transform overflows"), huge.problem());
        SceneException second = failure("camera -1 -1 1 1 -1 -200", "camera -1 -1 1 1 -1 -200");
        assertEquals(2, second.line());
        assertTrue(second.problem().contains("the first is at bad.simp:1"), second.problem());
        SceneException late = failure("line (0 0 -5) (1 1 -5)", "camera -1 -1 1 1 -1 -200");
        assertEquals(2, late.line());
        assertTrue(late.problem().contains("bad.simp:1 drew one before it"), late.problem());
    }

    @Test
    void litNumbersAreChecked() throws Exception {
        assertTrue(failure("depth -100 -50 0 0 0").problem().contains("near > far"));
        assertTrue(failure("depth -50 -50 0 0 0").problem().contains("near > far"));
        assertTrue(failure("light 1 1 1 0 0").problem().contains("both 0"));
        assertTrue(failure("light 1 -1 1 1 0").problem().contains("may not be negative"));
        assertTrue(failure("ambient 0 0 -0.5").problem().contains("may not be negative"));
        assertTrue(failure("surface 1 1 1 0.3 -8").problem().contains("may not be negative"));
        SceneException e = failure("obj \"nothing\"");
        assertTrue(e.problem().startsWith("file not found: nothing.obj; looked for "), e.problem());
    }

    /**
     * Run from the scene's own folder (the usual case), a missing file gets
     * the words, the column and the hint it gets from anywhere else, with the
     * one place looked: it had been left to the opening, which named the file
     * as the top file's include, with no column and no hint.
     */
    @Test
    void aMissingFileInTheWorkingDirectoryGetsTheSameWords() throws Exception {
        ScenePipeline.Options here = ScenePipeline.Options.lit(new SceneLibrary())
                .withWorkingDir(dir);
        Path obj = write("obj", "camera -1 -1 1 1 -1 -100", "obj \"x.obj\"");
        SceneException e = assertThrows(SceneException.class,
                () -> ScenePipeline.draw(obj, new PageCanvas(), here, SceneMonitor.NONE));
        assertEquals(obj, e.file());
        assertEquals(2, e.line());
        assertEquals(5, e.column());
        assertEquals("file not found: x.obj.obj (.obj is added to the name for you); looked for "
                + dir.resolve("x.obj.obj").toAbsolutePath().normalize(), e.problem());
        Path simp = write("file", "file nothere");
        e = assertThrows(SceneException.class, () -> ScenePipeline.draw(simp, new PageCanvas(), here, SceneMonitor.NONE));
        assertEquals(6, e.column());
        assertEquals("file not found: nothere.simp; looked for " + dir.resolve("nothere.simp").toAbsolutePath().normalize(),
                e.problem());
    }

    @Test
    void aNumberThatMayNotBeWhatItIsHasTheCaretUnderIt() throws Exception {
        // the column is where the number starts, however the numbers are separated; a file replayed
        // from the library (the second drawing) points at the same place
        String[][] cases = {
            {"ambient 0 0 -0.1", "13"},
            {"light 1 1 1 1 -2", "15"},
            {"surface 1 1 1 -0.3 2", "15"},
            {"light (1, 1, 1) 0, 0", "17"},
            {"depth -10 -50 (0, -1, 0)", "19"},
            {"light 1 -1 1 1 0", "9"}};
        for (String[] c : cases) {
            Path file = write("bad", c[0]);
            SceneLibrary library = new SceneLibrary();
            for (int drawing = 0; drawing < 2; drawing++) {
                SceneException e = assertThrows(SceneException.class, () -> ScenePipeline.draw(file, new PageCanvas(),
                        ScenePipeline.Options.lit(library), SceneMonitor.NONE));
                assertEquals(Integer.parseInt(c[1]), e.column(), c[0] + ": " + e.getMessage());
            }
        }
    }

    @Test
    void aColourOutsideZeroToOneIsClampedWithOneWarningNamingTheFirstLine() throws Exception {
        List<String> warnings = new ArrayList<>();
        SceneMonitor monitor = keeping(warnings);
        PageCanvas canvas = new PageCanvas();
        ScenePipeline.draw(write("c", "ambient 1 1 1", "polygon (-50 -50 -100 2 0 0) (50 -50 -100 2 0 0) (0 50 -100 2 0 0)",
                "line (-90 90 -100 0 -1 0) (90 90 -100 0 0 0)"), canvas,
                ScenePipeline.Options.lit(new SceneLibrary()), monitor);
        assertEquals(List.of("c.simp:2: colour channels outside 0 to 1 were clamped (this is the first such line): a"
                + " colour runs from 0 to 1, not 0 to 255 (2 of 255 is 0.008)"), warnings);
        assertEquals(List.of(255, 0, 0), list(rgb(canvas, 325, 325)), "red clamped to 1");
    }

    /**
     * A vertex that a finite CTM takes beyond the doubles, lit: a simp polygon, a line and a model's face each
     * named (the first, and how many more), none drawn, everything else drawn as it is. Before, the polygon was
     * lost without a word: a NaN vertex culled as outside every plane, an Infinity lost in the clipper.
     */
    @Test
    void aVertexBeyondTheDoublesIsNamedInALitSceneAndInAModel() throws Exception {
        Files.writeString(dir.resolve("ovf.obj"), "v -50 -50 -100\nv 1e308 -50 -100\nv 0 50 -100\nf 1 2 3\n"
                + "v -50 -50 -100\nv 50 -50 -100\nv 0 50 -100\nf 4 5 6\n");
        List<String> warnings = new ArrayList<>();
        PageCanvas canvas = new PageCanvas();
        ScenePipeline.draw(write("ovf", "ambient 1 1 1", "{", "scale 10 1 1", "obj ovf",
                "polygon (-50, -50, -100) (1e308, -50, -100) (0, 50, -100)", "}"), canvas,
                ScenePipeline.Options.lit(new SceneLibrary()), keeping(warnings));
        assertEquals(List.of("ovf.obj:4 face (of the model drawn by ovf.simp:4 obj): a vertex comes out"
                + " infinite or NaN in camera space (its numbers are finite, but the CTM takes them beyond about"
                + " 1.8e308), so this primitive was not drawn, nor 1 more like it"), warnings);
        assertEquals(List.of(255, 255, 255), list(rgb(canvas, 325, 325)), "the model's second face is drawn");
        warnings.clear();
        ScenePipeline.draw(write("nanlit", "ambient 1 1 1", "polygon (0,0,-10)(50,0,-10)(0,50,-10)", "scale 1e300 1 1",
                "line (0,0,-10)(1e10,0,-10)"), new PageCanvas(),
                ScenePipeline.Options.lit(new SceneLibrary()), keeping(warnings));
        assertEquals(List.of("nanlit.simp:4 line: a vertex comes out infinite or NaN in camera space (its"
                + " numbers are finite, but the CTM takes them beyond about 1.8e308), so this primitive was not drawn"),
                warnings);
    }

    @Test
    void aModelsColourOutsideZeroToOneIsClampedWithTheSameWarning() throws Exception {
        Files.writeString(dir.resolve("m.obj"), "v -50 -50 -100 1 0 0\nv 50 -50 -100 255 0 0\nv 0 50 -100 1 -1 0\nf 1 2 3\n");
        for (int drawing = 0; drawing < 2; drawing++) { // the model parsed, then kept and replayed
            List<String> warnings = new ArrayList<>();
            SceneMonitor monitor = keeping(warnings);
            SceneLibrary library = new SceneLibrary();
            PageCanvas canvas = new PageCanvas();
            Path scene = write("m", "ambient 1 1 1", "obj \"m\"", "obj \"m\"");
            ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(library), monitor);
            ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(library), monitor);
            String clamped = "m.obj:2: colour channels outside 0 to 1 were clamped (this is the first such line): a"
                    + " colour runs from 0 to 1, not 0 to 255 (255 of 255 is 1)";
            assertEquals(List.of(clamped, clamped), warnings);
            assertEquals(List.of(255, 0, 0), list(rgb(canvas, 325, 325)), "red clamped to 1");
        }
        Files.writeString(dir.resolve("m.obj"), "v -50 -50 -100 1 0 0\nv 50 -50 -100 1 0 0\nv 0 50 -100 1 0 0\nf 1 2 3\n");
        List<String> none = new ArrayList<>();
        ScenePipeline.draw(write("m", "ambient 1 1 1", "obj \"m\""), new PageCanvas(),
                ScenePipeline.Options.lit(new SceneLibrary()), keeping(none));
        assertEquals(List.of(), none, "colours within 0 to 1 warn of nothing");
        // the first in reading order, a model's or the scene's own
        Files.writeString(dir.resolve("m.obj"), "v -50 -50 -100 2 0 0\nv 50 -50 -100 1 0 0\nv 0 50 -100 1 0 0\nf 1 2 3\n");
        List<String> first = new ArrayList<>();
        ScenePipeline.draw(write("m", "ambient 1 1 1", "obj \"m\"", "line (0 0 -5 1.5 0 0) (1 1 -5 0 0 0)"),
                new PageCanvas(), ScenePipeline.Options.lit(new SceneLibrary()), keeping(first));
        assertEquals(List.of("m.obj:1: colour channels outside 0 to 1 were clamped (this is the first such line): a"
                + " colour runs from 0 to 1, not 0 to 255 (2 of 255 is 0.008)"), first);
    }

    /**
     * A model saved under a German locale ("0,5" for 0.5): read as SPEC
     * reads it, its v lines are positions with colours, clamped; the scene
     * says why, before the clamp, on its first drawing and when the kept
     * model is replayed.
     */
    @Test
    void aModelsDecimalCommasAreNamedBeforeTheClampTheyCause() throws Exception {
        Files.writeString(dir.resolve("de.obj"), "v 0,5 -1,0 -4,0\nv 1,0 0,0 -4,0\nv 0,0 1,0 -4,0\nf 1 2 3\n");
        Path scene = write("de", "obj \"de\"");
        SceneLibrary library = new SceneLibrary();
        for (int drawing = 0; drawing < 2; drawing++) {
            List<String> warnings = warningsOf(scene, library);
            assertEquals(List.of("de.obj:1:3: '0,5' is read as two numbers, so this v line's 6 numbers are"
                    + " x y z r g b (a comma separates two numbers: one and a half is 1.5, not 1,5); this is the first"
                    + " such line", "de.obj:1: colour channels outside 0 to 1 were clamped (this is the first such line)",
                    "de.simp: every lit polygon came out black: the scene has no light and no ambient (ambient 0 0 0)"
                    + " where they are drawn; add 'ambient 0.2 0.2 0.2' or a 'light' before them"),
                    warnings, "drawing " + drawing);
        }
    }

    /**
     * A model that gives no face says so, through the scene's warnings, on
     * its first drawing and when it is replayed; one that is not UTF-8 text
     * is an error naming the line that read it, and what was drawn stays.
     */
    @Test
    void aModelWithoutFacesWarnsAndOneThatIsNotTextStops() throws Exception {
        Files.writeString(dir.resolve("empty.obj"), "");
        Files.writeString(dir.resolve("tri.obj"), "v -50 -50 -100\nv 50 -50 -100\nv 0 50 -100\nf 1 2 3\n");
        Path scene = write("s", "ambient 1 1 1", "obj \"empty\"", "obj \"tri\"", "obj \"empty\"");
        SceneLibrary library = new SceneLibrary();
        for (int drawing = 0; drawing < 2; drawing++) {
            List<String> warnings = warningsOf(scene, library);
            assertEquals(List.of("empty.obj: no f lines, so nothing is drawn (the file is empty)"), warnings,
                    "drawing " + drawing);
        }
        Files.write(dir.resolve("notepad.obj"), "\uFEFFv 0 0 0\r\n".getBytes(StandardCharsets.UTF_16LE));
        PageCanvas canvas = new PageCanvas();
        SceneException e = assertThrows(SceneException.class, () -> ScenePipeline.draw(
                write("u", "ambient 1 1 1", "obj \"tri\"", "obj \"notepad\""), canvas,
                ScenePipeline.Options.lit(library), SceneMonitor.NONE));
        assertTrue(e.getMessage().contains("notepad.obj:1:1, included from u.simp:3: UTF-16 text, not UTF-8"),
                e.getMessage());
        assertEquals(List.of(255, 255, 255), list(rgb(canvas, 325, 325)), "the triangle before it stays");
    }

    /** An obj name that misses its model only by case, as the course's Windows users write it, names the model. */
    @Test
    void aModelNamedInAnotherCaseIsNamed() throws Exception {
        Files.writeString(dir.resolve("Teapot.obj"), "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
        SceneException e = assertThrows(SceneException.class, () -> ScenePipeline.draw(write("t", "obj \"teapot\""),
                new PageCanvas(), ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE));
        assertTrue(e.problem().startsWith("file not found: teapot.obj (there is Teapot.obj: names are case-sensitive"
                + " here); looked for "), e.problem());
    }

    @Test
    void aSceneIsLitWhenAnyFileItReadsHasALitCommand() throws Exception {
        write("part", "ambient 1 1 1");
        Path top = write("top", "# includes a lit part", "{", "file \"part\"", "}");
        ScenePipeline.Drawn lit = DrawnScenes.draw(top);
        assertTrue(lit.lit());
        assertEquals("part.simp:1 ambient", lit.litBecause());
        Path plain = write("plain", "polygon (0 0 0) (1 0 0) (0 1 0)");
        ScenePipeline.Drawn cued = DrawnScenes.draw(plain);
        assertFalse(cued.lit());
        assertNull(cued.litBecause());
        Path cycle = write("cycle", "file \"cycle\"");
        SceneException e = assertThrows(SceneException.class, () -> DrawnScenes.draw(cycle));
        assertTrue(e.getMessage().contains("file cycle"), e.getMessage());
    }

    /**
     * SPEC's nine commands that make a scene lit, each alone, in the top
     * file or in a file it includes: each makes it lit and is named as the
     * reason; the same scene with the command only in a comment is depth-cued.
     */
    @Test
    void eachOfTheNineLitCommandsMakesASceneLit() throws Exception {
        Files.writeString(dir.resolve("tri.obj"), "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
        String[] commands = {"camera -1 -1 1 1 -1 -100", "ambient 0.5 0.5 0.5", "surface 1 0 0",
            "depth -10 -50 0 0 0", "light 1 1 1 1 0", "obj \"tri\"", "flat", "gouraud", "phong"};
        String polygon = "polygon (0 0 -10) (1 0 -10) (0 1 -10)";
        for (String command : commands) {
            String word = command.split(" ")[0];
            ScenePipeline.Drawn alone = DrawnScenes.draw(write("alone", command, polygon));
            assertTrue(alone.lit(), command);
            assertEquals("alone.simp:1 " + word, alone.litBecause());
            write("part", command);
            ScenePipeline.Drawn included = DrawnScenes.draw(write("top", "{", "file \"part\"", "}", polygon));
            assertTrue(included.lit(), command + " in an included file");
            assertEquals("part.simp:1 " + word, included.litBecause());
            ScenePipeline.Drawn commented = DrawnScenes.draw(write("commented", "# " + command, polygon));
            assertFalse(commented.lit(), command + " in a comment");
        }
    }
}
