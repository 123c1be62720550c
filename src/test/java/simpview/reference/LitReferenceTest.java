package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The lit reference on its own, against numbers worked out by hand from
 * SPEC Part 2: perspective, lighting, fog, the non-square window, a camera
 * inside a box. Panel rows count from the bottom.
 */
class LitReferenceTest {

    private static final int N = RefView.PANEL;

    @TempDir
    Path dir;

    private int[] render(String scene) throws IOException {
        Path file = dir.resolve("scene.simp");
        Files.writeString(file, scene);
        LitReferenceRenderer renderer = new LitReferenceRenderer();
        renderer.run(file);
        return renderer.panel();
    }

    private static int channel(int[] panel, int x, int y, int shift) {
        return panel[y * N + x] >> shift & 0xFF;
    }

    /**
     * A floor at y = -5 from z = -10 (white) to z = -30 (black): each row at
     * the centre column has the colour of the camera-space point that
     * perspective puts there; the colour halfway (z = -20) lands at row
     * 243.75, not at the screen midpoint of the floor's edges (216.7).
     */
    @Test
    void aRecedingQuadIsPerspectiveCorrect() throws IOException {
        int[] panel = render("""
                camera -1 -1 1 1 -0.1 -200
                ambient 1 1 1
                polygon (-5, -5, -10, 1, 1, 1) (5, -5, -10, 1, 1, 1) (5, -5, -30, 0, 0, 0)
                polygon (-5, -5, -10, 1, 1, 1) (5, -5, -30, 0, 0, 0) (-5, -5, -30, 0, 0, 0)
                """);
        for (int row = 163; row <= 270; row++) {
            double yOnWindow = (row + 0.5) / 325 - 1;
            double z = 5 / yOnWindow;
            long expected = Math.round((z + 30) / 20 * 255);
            assertEquals(expected, channel(panel, 325, row, 8), 1, "row " + row);
        }
        assertEquals(128, channel(panel, 325, 243, 8), 2);
        assertEquals(191, channel(panel, 325, 216, 8), 2);
        assertEquals(0, panel[162 * N + 325], "below the floor's near edge");
        assertEquals(0, panel[271 * N + 325], "beyond its far edge");
    }

    private static final String SQUARE_AT_MINUS_50 = """
            polygon (-40, -40, -50) (40, -40, -50) (40, 40, -50)
            polygon (-40, -40, -50) (40, 40, -50) (-40, 40, -50)
            """;

    /** Straight under a light at distance 20 with A + B d = 2: kd Ia + I f (kd + ks), f = 1/2. */
    @Test
    void underALightTheColourIsAmbientPlusDiffusePlusSpecular() throws IOException {
        for (String shading : new String[] {"phong", "gouraud"}) {
            String scene = "camera -1 -1 1 1 -0.1 -200\n{\ntranslate 0 0 -30\nlight 1 1 1 1 0.05\n}\n"
                    + "ambient 0.2 0.2 0.2\nsurface 0.6 0.4 0.2 0.3 8\n" + shading + "\n" + SQUARE_AT_MINUS_50;
            int[] panel = render(scene);
            double[] kd = {0.6, 0.4, 0.2};
            for (int ch = 0; ch < 3; ch++) {
                long expected = Math.round((kd[ch] * 0.2 + 0.5 * (kd[ch] + 0.3)) * 255);
                int shift = 16 - 8 * ch;
                if (shading.equals("phong")) {
                    assertEquals(expected, channel(panel, 325, 325, shift), 1, "channel " + ch);
                } else {
                    // Gouraud lights the corners only: the centre is far darker than phong's highlight.
                    assertTrue(channel(panel, 325, 325, shift) < expected - 20, "gouraud channel " + ch);
                }
            }
        }
    }

    /**
     * Only a sharp specular term (kd = 0, p = 1000): the brightest pixel is where
     * the eye sees the light mirrored in the plane z = -50, (50/70) (20, 10, -70)
     * for a light at (20, 10, -30): panel (417.9, 371.4).
     */
    @Test
    void theSpecularPeakIsAtTheMirrorDirection() throws IOException {
        int[] panel = render("camera -1 -1 1 1 -0.1 -200\n{\ntranslate 20 10 -30\nlight 1 1 1 1 0\n}\n"
                + "surface 0 0 0 1 1000\n" + SQUARE_AT_MINUS_50);
        int best = 0;
        for (int i = 1; i < N * N; i++) {
            if ((panel[i] & 0xFF) > (panel[best] & 0xFF)) {
                best = i;
            }
        }
        assertEquals(417, best % N, 1, "column of the peak");
        assertEquals(371, best / N, 1, "row of the peak");
        assertTrue((panel[best] & 0xFF) > 250, "the peak is white");
    }

    private static final String SQUARE_AT_MINUS_100 = """
            polygon (-90, -90, -100) (90, -90, -100) (90, 90, -100)
            polygon (-90, -90, -100) (90, 90, -100) (-90, 90, -100)
            """;

    /** Light 20 above the plane: 20 tan 60 to the side, N.L = 1/2 and the diffuse term halves. */
    @Test
    void lightComingInAtSixtyDegreesHalvesTheDiffuseTerm() throws IOException {
        int[] panel = render("{\ntranslate 0 0 -80\nlight 1 1 1 1 0\n}\nambient 0.1 0.1 0.1\n"
                + "surface 0.8 0.6 0.4 0 8\n" + SQUARE_AT_MINUS_100);
        int column = (int) Math.floor((20 * Math.tan(Math.toRadians(60)) + 100) * 3.25);
        double[] kd = {0.8, 0.6, 0.4};
        for (int ch = 0; ch < 3; ch++) {
            int shift = 16 - 8 * ch;
            double ambient = kd[ch] * 0.1 * 255;
            double under = channel(panel, 325, 325, shift) - ambient;
            double aside = channel(panel, column, 325, shift) - ambient;
            assertEquals(kd[ch] * 255, under, 1, "diffuse straight under, channel " + ch);
            assertEquals(under / 2, aside, 1.5, "diffuse at 60 degrees, channel " + ch);
        }
    }

    @Test
    void aLightBehindTheSurfaceAddsNothing() throws IOException {
        int[] panel = render("{\ntranslate 0 0 -120\nlight 1 1 1 1 0\n}\nambient 0.1 0.1 0.1\n"
                + "surface 0.8 0.6 0.4 1 1\n" + SQUARE_AT_MINUS_100);
        assertEquals(Math.round(0.08 * 255) << 16 | Math.round(0.06 * 255) << 8 | Math.round(0.04 * 255),
                panel[325 * N + 325]);
    }

    /** Fog from near -20 to far -180: at near the colour stays, at far it is the fog, half way between is half. */
    @Test
    void fogAtNearFarAndHalfWay() throws IOException {
        StringBuilder scene = new StringBuilder("ambient 1 1 1\nsurface 1 0.8 0.6\ndepth -20 -180 (0.2 0.4 0.6)\n");
        double[][] squares = {{-90, -40, -20}, {-25, 25, -100}, {40, 90, -180}};
        for (double[] s : squares) {
            scene.append(String.format(Locale.ROOT,
                    "polygon (%f, -25, %f) (%f, -25, %f) (%f, 25, %f)%npolygon (%f, -25, %f) (%f, 25, %f) (%f, 25, %f)%n",
                    s[0], s[2], s[1], s[2], s[1], s[2], s[0], s[2], s[1], s[2], s[0], s[2]));
        }
        int[] panel = render(scene.toString());
        assertEquals(0xFFCC99, panel[325 * N + (int) ((-65 + 100) * 3.25)], "at near");
        assertEquals(0x999999, panel[325 * N + 325], "half way");
        assertEquals(0x336699, panel[325 * N + (int) ((65 + 100) * 3.25)], "at far");
    }

    /** A 2:1 window is drawn as a centred 650x325 band; the rest of the panel stays black. */
    @Test
    void aWideWindowIsACentredBand() throws IOException {
        int[] panel = render("""
                camera -2 -1 2 1 -0.1 -200
                ambient 1 1 1
                polygon (-500, -500, -10) (500, -500, -10) (500, 500, -10)
                polygon (-500, -500, -10) (500, 500, -10) (-500, 500, -10)
                """);
        int[] box = litBox(panel);
        assertEquals(0, box[0]);
        assertEquals(N - 1, box[1]);
        assertEquals(325, box[3] - box[2] + 1, "band height");
        assertTrue(box[2] == 162 || box[2] == 163, "band bottom " + box[2]);
    }

    /** The course's pageH: its window is [-1, 1] x [-1, 0]. */
    @Test
    void pageHIsABandOf650By325() throws IOException {
        Path a3 = CourseFiles.require("course-simp-a3");
        LitReferenceRenderer renderer = new LitReferenceRenderer();
        renderer.run(a3.resolve("pageH.simp"));
        int[] box = litBox(renderer.panel());
        assertEquals(0, box[0]);
        assertEquals(N - 1, box[1]);
        assertTrue(box[2] >= 162 && box[3] <= 488 && box[3] - box[2] + 1 >= 324,
                "band rows " + box[2] + " to " + box[3]);
    }

    /** x from, x to, y from, y to of the non-black pixels. */
    private static int[] litBox(int[] panel) {
        int[] box = {N, -1, N, -1};
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                if (panel[y * N + x] != 0) {
                    box[0] = Math.min(box[0], x);
                    box[1] = Math.max(box[1], x);
                    box[2] = Math.min(box[2], y);
                    box[3] = Math.max(box[3], y);
                }
            }
        }
        return box;
    }

    /** The eye inside a closed box: the clipper keeps the faces around it and they cover every pixel. */
    @Test
    void aCameraInsideABoxSeesItsInsideEverywhere() throws IOException {
        Files.writeString(dir.resolve("unitbox.simp"), RandomLitScenes.cube());
        int[] panel = render("""
                { rotate Y 30
                rotate X 20
                camera -1.3 -0.7 0.9 1.5 -0.5 -300
                }
                ambient 1 1 1
                surface 0.5 0.25 1
                translate -20 -20 -20
                scale 40 40 40
                file "unitbox"
                """);
        for (int i = 0; i < N * N; i++) {
            assertEquals(0x8040FF, panel[i], "pixel " + i % N + "," + i / N);
        }
    }

    /** Wire polygons and lines are not lit: their edges carry kd, even with no ambient light. */
    @Test
    void wireAndLinesCarryTheirColourUnlit() throws IOException {
        int[] panel = render("""
                ambient 0 0 0
                surface 0.2 0.4 0.6
                wire
                polygon (-50, -50, -50) (50, -50, -50) (0, 50, -50)
                line (-80, 80, -50, 1, 0.5, 0) (80, 80, -50, 1, 0.5, 0)
                """);
        // The bottom edge is at panel y 162.5, which SPEC's line rule rounds to row 163.
        assertEquals(Math.round(0.2 * 255) << 16 | Math.round(0.4 * 255) << 8 | Math.round(0.6 * 255),
                panel[163 * N + 325], "the triangle's bottom edge");
        assertEquals(0xFF8000, panel[(int) (180 * 3.25) * N + 325], "the line");
        assertEquals(0, panel[325 * N + 325], "inside the wire triangle");
    }

    /** Flat: one colour per polygon, lit once at its centroid. */
    @Test
    void flatGivesEachTriangleOneColour() throws IOException {
        int[] panel = render("camera -1 -1 1 1 -0.1 -200\n{\ntranslate 15 5 -40\nlight 1 1 1 1 0\n}\n"
                + "flat\nsurface 0.6 0.4 0.2 0.5 4\n" + SQUARE_AT_MINUS_50);
        int lowerRight = panel[200 * N + 450];
        int upperLeft = panel[450 * N + 200];
        assertFalse(lowerRight == upperLeft, "the two triangles are lit at different centroids");
        for (int y = 180; y < 470; y += 7) {
            for (int x = 180; x < 470; x += 7) {
                if (Math.abs(x - y) > 3) {
                    assertEquals(x > y ? lowerRight : upperLeft, panel[y * N + x], x + "," + y);
                }
            }
        }
    }

    @Test
    void theSceneRulesFindLitCommandsInIncludedFiles() throws IOException {
        Files.writeString(dir.resolve("part.simp"), "surface 1 0 0\n");
        Files.writeString(dir.resolve("plain.simp"), "polygon (0 0 -1) (1 0 -1) (0 1 -1)\n");
        Path lit = dir.resolve("lit.simp");
        Files.writeString(lit, "file \"plain\"\n{\nfile part\n}\n");
        Path depthCued = dir.resolve("cued.simp");
        Files.writeString(depthCued, "# camera in a comment does not count\nfile \"plain\"\n");
        assertTrue(ReferencePage.isLit(lit));
        assertFalse(ReferencePage.isLit(depthCued));
    }

    /** `file` looks beside the including file first, then in the working directory (the project, under Gradle). */
    @Test
    void fileLooksBesideTheSceneThenInTheWorkingDirectory() throws IOException {
        assumeTrue(Files.exists(Path.of("simp/cube.simp")), "not run from the project folder");
        Files.createDirectories(dir.resolve("simp"));
        Files.writeString(dir.resolve("simp/cube.simp"), "polygon (0 0 0) (1 0 0) (0 1 0)\n");
        String scene = "ambient 1 1 1\ntranslate -50 -50 -150\nscale 100 100 100\nfile \"simp/cube\"\n";
        int[] beside = render(scene);
        int drawnBeside = 0;
        for (int rgb : beside) {
            drawnBeside += rgb != 0 ? 1 : 0;
        }
        Files.delete(dir.resolve("simp/cube.simp"));
        int[] working = render(scene);
        int drawnWorking = 0;
        for (int rgb : working) {
            drawnWorking += rgb != 0 ? 1 : 0;
        }
        assertEquals(325 * 325 / 2, drawnBeside, 400, "the one triangle beside the scene");
        assertEquals(325 * 325, drawnWorking, 1000, "the project's whole cube from the working directory");
    }

    /** The biggest course page (dummy.obj twice, about 29,000 filled triangles) renders in a few seconds. */
    @Test
    void pageIRendersInAFewSeconds() throws IOException {
        Path a3 = CourseFiles.require("course-simp-a3");
        long start = System.nanoTime();
        LitReferenceRenderer.render(a3.resolve("pageI.simp"));
        double seconds = (System.nanoTime() - start) / 1e9;
        assertTrue(seconds < 15, "pageI took " + seconds + " s");
    }
}
