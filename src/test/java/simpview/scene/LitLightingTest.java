package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * Lighting through the whole pipeline (ScenePipeline.draw on scene files
 * written here), against SPEC's formula evaluated by hand in this test:
 *
 * <pre>
 * I = kd Ia + sum_i Ii fi (kd (N . Li) + ks max(0, V . Ri)^p),  fi = 1 / (Ai + Bi di)
 * </pre>
 *
 * Most scenes use the parallel view (no camera), where V = (0, 0, 1) and a
 * world point (x, y) is seen at panel pixel ((x + 100) 3.25, (y + 100) 3.25):
 * a large square at z = -100 facing +z, lights above it. Expected bytes are
 * exact; every expectation is first checked to lie clear of a rounding
 * boundary (so an exact comparison is sound), and each test also shows that
 * what it checks could have come out otherwise.
 */
class LitLightingTest {

    /** The pixel whose centre is right under the lights placed "above the centre". */
    private static final int CX = 325;
    private static final int CY = 325;
    private static final String SQUARE_AT_100 = square(-100, -100, 100, 100, -100);

    @TempDir
    Path dir;

    // ---------------------------------------------------------------- the formula, by hand

    /** One point light in camera space. */
    record Light(double x, double y, double z, double r, double g, double b, double a, double bAtt) {
        double[] intensity() {
            return new double[] {r, g, b};
        }
    }

    /** SPEC's formula at P with normal N (any length) and view vector V (any length), clamped to [0, 1]. */
    static double[] formula(double[] p, double[] n, double[] v, double[] kd, double[] ia, double ks, double exp,
            List<Light> lights) {
        double[] out = new double[3];
        for (int c = 0; c < 3; c++) {
            out[c] = kd[c] * ia[c];
        }
        double[] un = unit(n);
        double[] uv = unit(v);
        if (un != null) {
            for (Light light : lights) {
                double[] l = {light.x() - p[0], light.y() - p[1], light.z() - p[2]};
                double d = Math.sqrt(dot(l, l));
                double[] ul = unit(l);
                if (ul == null || dot(un, ul) <= 0) {
                    continue;
                }
                double nl = dot(un, ul);
                double[] r = {2 * nl * un[0] - ul[0], 2 * nl * un[1] - ul[1], 2 * nl * un[2] - ul[2]};
                double specular = ks * Math.pow(Math.max(0, dot(uv, r)), exp);
                double f = 1 / (light.a() + light.bAtt() * d);
                for (int c = 0; c < 3; c++) {
                    out[c] += light.intensity()[c] * f * (kd[c] * nl + specular);
                }
            }
        }
        for (int c = 0; c < 3; c++) {
            out[c] = Math.max(0, Math.min(1, out[c]));
        }
        return out;
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] unit(double[] a) {
        double length = Math.sqrt(dot(a, a));
        return length > 0 ? new double[] {a[0] / length, a[1] / length, a[2] / length} : null;
    }

    /** round(c * 255) per channel, after checking c * 255 is clear of a .5, where float noise could tip it. */
    static int[] bytes(double[] colour) {
        int[] out = new int[3];
        for (int c = 0; c < 3; c++) {
            double level = colour[c] * 255;
            double fraction = level - Math.floor(level);
            assertTrue(Math.abs(fraction - 0.5) > 0.01, "the test's own numbers: channel " + c + " at " + level
                    + " is too near a rounding boundary for an exact expectation");
            out[c] = (int) Math.floor(level + 0.5);
        }
        return out;
    }

    // ---------------------------------------------------------------- scenes

    private Path write(String name, String... lines) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, String.join("\n", lines).concat("\n").getBytes(StandardCharsets.UTF_8));
        return file;
    }

    private PageCanvas draw(String... lines) throws Exception {
        PageCanvas canvas = new PageCanvas();
        ScenePipeline.draw(write("scene.simp", lines), canvas, ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE);
        return canvas;
    }

    private static int[] rgb(PageCanvas canvas, int x, int y) {
        int p = canvas.panel().getPixel(x, y);
        return new int[] {p >> 16 & 0xFF, p >> 8 & 0xFF, p & 0xFF};
    }

    /** The world x (or y) of the centre of panel column (or row) i in the parallel view. */
    static double world(int i) {
        return (i + 0.5) * 200.0 / 650 - 100;
    }

    static String n(double v) {
        return Double.toString(v);
    }

    /** Two polygons filling the rectangle [x0, x1] x [y0, y1] at depth z, facing +z. */
    static String square(double x0, double y0, double x1, double y1, double z) {
        return "polygon (" + n(x0) + ", " + n(y0) + ", " + n(z) + ") (" + n(x1) + ", " + n(y0) + ", " + n(z) + ") ("
                + n(x1) + ", " + n(y1) + ", " + n(z) + ")\npolygon (" + n(x0) + ", " + n(y0) + ", " + n(z) + ") ("
                + n(x1) + ", " + n(y1) + ", " + n(z) + ") (" + n(x0) + ", " + n(y1) + ", " + n(z) + ")";
    }

    /** A light at world (x, y, z) as a scene writes it: at the origin of a translated frame. */
    static String light(double x, double y, double z, String rgbAb) {
        return "{\ntranslate " + n(x) + " " + n(y) + " " + n(z) + "\nlight " + rgbAb + "\n}";
    }

    private static final double[] KD = {0.2, 0.5, 0.3};
    private static final double[] IA = {0.3, 0.3, 0.3};
    private static final double[] UP = {0, 0, 1};

    /** The parallel view's lit point under pixel (i, j) of the square at z = -100. */
    private static double[] onSquare(int i, int j) {
        return new double[] {world(i), world(j), -100};
    }

    private static String surroundings(double ks, double p) {
        return "ambient 0.3 0.3 0.3\nsurface 0.2 0.5 0.3 " + n(ks) + " " + n(p);
    }

    // ---------------------------------------------------------------- straight above, at an angle, attenuation

    @Test
    void underALightStraightAboveThePixelIsKdIaPlusIfTimesKdPlusKs() throws Exception {
        double d = 50;
        Light above = new Light(world(CX), world(CY), -100 + d, 0.6, 0.5, 0.8, 0.5, 0.03);
        PageCanvas canvas = draw(surroundings(0.25, 10), light(above.x(), above.y(), above.z(), "0.6 0.5 0.8 0.5 0.03"),
                SQUARE_AT_100);
        // N = L = R = V = (0, 0, 1): N . L = 1, V . R = 1, f = 1 / (0.5 + 0.03 * 50) = 1/2.
        double f = 0.5;
        double[] byHand = new double[3];
        for (int c = 0; c < 3; c++) {
            byHand[c] = KD[c] * IA[c] + above.intensity()[c] * f * (KD[c] + 0.25);
        }
        assertArrayEquals(bytes(byHand), rgb(canvas, CX, CY));
        assertArrayEquals(bytes(byHand), bytes(formula(onSquare(CX, CY), UP, UP, KD, IA, 0.25, 10, List.of(above))));
        int[] ambientOnly = bytes(new double[] {KD[0] * IA[0], KD[1] * IA[1], KD[2] * IA[2]});
        assertTrue(!Arrays.equals(ambientOnly, rgb(canvas, CX, CY)), "the light shows");
    }

    @Test
    void whereTheLightComesInAtSixtyDegreesTheDiffuseTermHalves() throws Exception {
        // The pixel 100 columns right of the one under the light: its centre is 100 / 3.25 world units
        // away, so a light at height h = that / sqrt(3) comes in at 60 degrees from the normal there.
        int k = 100;
        double h = k * 200.0 / 650 / Math.sqrt(3);
        Light light = new Light(world(CX), world(CY), -100 + h, 0.9, 0.8, 0.5, 1, 0);
        PageCanvas canvas = draw(surroundings(0, 8), light(light.x(), light.y(), light.z(), "0.9 0.8 0.5 1 0"),
                SQUARE_AT_100);
        double[] under = new double[3];
        double[] slanted = new double[3];
        for (int c = 0; c < 3; c++) {
            double diffuse = light.intensity()[c] * KD[c]; // f = 1, ks = 0
            under[c] = KD[c] * IA[c] + diffuse;
            slanted[c] = KD[c] * IA[c] + diffuse / 2;
        }
        assertArrayEquals(bytes(under), rgb(canvas, CX, CY));
        assertArrayEquals(bytes(slanted), rgb(canvas, CX + k, CY), "60 degrees to the right");
        assertArrayEquals(bytes(slanted), rgb(canvas, CX, CY - k), "60 degrees below");
        assertArrayEquals(bytes(slanted), bytes(formula(onSquare(CX + k, CY), UP, UP, KD, IA, 0, 8, List.of(light))));
    }

    @Test
    void attenuationWithAPlusBdEqualToTwoHalvesTheLight() throws Exception {
        double d = 40;
        String above = "0.7 0.6 0.9";
        String[] halving = {"2 0", "0 " + n(2 / d), "1 " + n(1 / d), "1.5 " + n(0.5 / d)};
        double[] half = new double[3];
        double[] intensity = {0.7, 0.6, 0.9};
        for (int c = 0; c < 3; c++) {
            half[c] = KD[c] * IA[c] + intensity[c] / 2 * (KD[c] + 0.4);
        }
        for (String ab : halving) {
            PageCanvas canvas = draw(surroundings(0.4, 5), light(world(CX), world(CY), -100 + d, above + " " + ab),
                    SQUARE_AT_100);
            assertArrayEquals(bytes(half), rgb(canvas, CX, CY), "A B = " + ab);
        }
        double[] full = new double[3];
        for (int c = 0; c < 3; c++) {
            full[c] = KD[c] * IA[c] + intensity[c] * (KD[c] + 0.4);
        }
        PageCanvas unattenuated = draw(surroundings(0.4, 5), light(world(CX), world(CY), -100 + d, above + " 1 0"),
                SQUARE_AT_100);
        assertArrayEquals(bytes(full), rgb(unattenuated, CX, CY), "A + B d = 1");
    }

    @Test
    void aLightBehindTheSurfaceOrInItsPlaneAddsNothing() throws Exception {
        int[] ambient = bytes(new double[] {KD[0] * IA[0], KD[1] * IA[1], KD[2] * IA[2]});
        for (double z : new double[] {-150, -100.0001, -100}) {
            PageCanvas canvas = draw(surroundings(1, 1), light(world(CX), world(CY), z, "50 50 50 1 0"), SQUARE_AT_100);
            assertEquals(1, distinctColours(canvas, 0, 0, 650, 650).size(), "light at z = " + z);
            assertArrayEquals(ambient, rgb(canvas, CX, CY), "light at z = " + z);
        }
        PageCanvas inFront = draw(surroundings(1, 1), light(world(CX), world(CY), -99.9, "50 50 50 1 0"), SQUARE_AT_100);
        assertArrayEquals(new int[] {255, 255, 255}, rgb(inFront, CX, CY), "the same light just in front");
    }

    /** The colours of the panel's pixels in [x0, x1) x [y0, y1). */
    private static Set<Integer> distinctColours(PageCanvas canvas, int x0, int y0, int x1, int y1) {
        Set<Integer> colours = new HashSet<>();
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                colours.add(canvas.panel().getPixel(x, y) & 0xFFFFFF);
            }
        }
        return colours;
    }

    @Test
    void inPerspectiveVPointsFromTheLitPointToTheEye() throws Exception {
        // The eye at the origin, a square at z = -10 facing it, a light at the eye. A panel pixel's centre
        // (i + 0.5, j + 0.5) looks along (x', y', -1) with x' = (i + 0.5) / 325 - 1, so it sees the point
        // 10 (x', y', -1). There L = V, so V . R = 2 (N . L)^2 - 1, not N . L as with a parallel V.
        PageCanvas canvas = draw("camera -1 -1 1 1 -1 -100", surroundings(0.6, 4), "light 0.7 0.7 0.7 0 0.1",
                square(-20, -20, 20, 20, -10));
        Light eye = new Light(0, 0, 0, 0.7, 0.7, 0.7, 0, 0.1);
        int checked = 0;
        for (int[] pixel : new int[][] {{325, 325}, {500, 325}, {150, 480}, {600, 60}}) {
            double[] p = {10 * ((pixel[0] + 0.5) / 325 - 1), 10 * ((pixel[1] + 0.5) / 325 - 1), -10};
            double[] toEye = {-p[0], -p[1], -p[2]};
            double[] expected = formula(p, UP, toEye, KD, IA, 0.6, 4, List.of(eye));
            assertArrayEquals(bytes(expected), rgb(canvas, pixel[0], pixel[1]), Arrays.toString(pixel));
            double[] parallel = formula(p, UP, UP, KD, IA, 0.6, 4, List.of(eye));
            checked += Arrays.equals(round(parallel), round(expected)) ? 0 : 1;
        }
        assertTrue(checked >= 2, "V = (0, 0, 1) would have given other colours off the axis");
    }

    // ---------------------------------------------------------------- shading modes

    @Test
    void flatGivesOneColourPerFaceLitAtItsCentroid() throws Exception {
        // An obj quad (one face, drawn as a fan of two triangles) and a simp triangle, under a close light.
        write("quad.obj", "v -60 -25 -100", "v -10 -25 -100", "v -10 25 -100", "v -60 25 -100", "f 1 2 3 4");
        String[] scene = {surroundings(0.5, 12), light(-20, 5, -70, "1 1 1 1 0"), "SHADING", "obj \"quad\"",
            "polygon (10, -25, -100) (60, -25, -100) (35, 25, -100)"};
        scene[2] = "flat";
        PageCanvas flat = draw(scene);
        Light light = new Light(-20, 5, -70, 1, 1, 1, 1, 0);
        // The quad's pixels: x from -60 to -10 is columns 130 to 292, y from -25 to 25 rows 244 to 406.
        assertEquals(Set.of(packed(bytes(formula(new double[] {-35, 0, -100}, UP, UP, KD, IA, 0.5, 12,
                List.of(light))))), distinctColours(flat, 131, 245, 291, 405), "the quad, lit at (-35, 0, -100)");
        double[] triangleCentroid = {35, -25.0 / 3, -100};
        assertEquals(Set.of(packed(bytes(formula(triangleCentroid, UP, UP, KD, IA, 0.5, 12, List.of(light))))),
                distinctColours(flat, 400, 260, 410, 290), "inside the triangle");
        scene[2] = "phong";
        assertTrue(distinctColours(draw(scene), 131, 245, 291, 405).size() > 100, "phong varies over the quad");
    }

    /**
     * One colour is that colour to the bit, however the depth runs, whatever carries it: kd 0.5 under ambient 1
     * is 0.5, whose byte is round(127.5) = 128 at every pixel. A flat polygon has "one colour per polygon" (SPEC
     * Part 2, rounded once); a gouraud polygon whose vertices are all lit alike, a wire outline and a line of the
     * surface colour carry the same colour at each end, and a lerp between one value and itself is that value;
     * a phong polygon of the surface colour has that kd at every vertex, so at every pixel, lit there by the
     * ambient term alone, kd Ia = 0.5. Interpolated perspective-correct, (c q) / q missed 0.5 by a last bit at
     * some pixels, which came out 127 (the wire cubes of A3's pageB had 758 such pixels; this phong triangle
     * 3,136 of its 36,806). Drawn on one thread and in bands by two.
     */
    @ParameterizedTest
    @ValueSource(strings = {"flat", "gouraud", "wire", "line", "phong"})
    void oneColourTiltedInDepthIsThatColourToTheBit(String carrier) throws Exception {
        String primitive = carrier.equals("line") ? "line (-10, -10, -20) (3, 10, -50)"
                : "polygon (-10, -10, -20) (10, -10, -20) (0, 10, -50)";
        String[] scene = {"camera -1 -1 1 1 -0.1 -200", "ambient 1 1 1", "surface 0.5 0.5 0.5",
            carrier.equals("line") ? "flat" : carrier, primitive};
        for (int threads : new int[] {1, 2}) {
            PageCanvas canvas = new PageCanvas();
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                canvas.drawWith(drawing);
                ScenePipeline.draw(write("tilted.simp", scene), canvas, ScenePipeline.Options.lit(new SceneLibrary()),
                        SceneMonitor.NONE);
            }
            NotBlack drawn = NotBlack.of(pixels(canvas));
            assertEquals(Set.of(0x808080), drawn.colours(), carrier + ", " + threads + " thread(s)");
            int least = carrier.equals("line") || carrier.equals("wire") ? 150 : 30_000;
            assertTrue(drawn.count() > least, carrier + ": " + drawn.count() + " pixels");
        }
    }

    /**
     * The same phong triangle of kd 0.5 with lights that are all behind it (N . L &lt; 0 at every point: they
     * add nothing, and kd Ia is 0.5 again), so that its pixels wait to be lit at the picture's end, as the drawing
     * threads' stages keep a lit look's (FragmentStage.shadeLater): with one light a short span's pixels wait as
     * points, with two as kept spans, and a picture drawn after one whose short spans passed several pixels each
     * keeps them as spans too; all are lit at the end a batch of runs at a time, short pieces pixel by pixel.
     * Every pixel is 128, drawn in any of these ways, on one, two and seven threads, and the pictures are the same
     * to the bit. (Resolved as (kd q) / q, 3,136 of its 36,806 pixels came out 127 each way.)
     */
    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void phongOfOneKdWhosePixelsWaitToBeLitIsThatKdToTheBit(int lights) throws Exception {
        List<String> scene = new ArrayList<>(List.of("camera -1 -1 1 1 -0.1 -200", "ambient 1 1 1",
                "surface 0.5 0.5 0.5 0.8 4", "phong"));
        for (int i = 0; i < lights; i++) {
            scene.add(light(3 * i, -100, -100, "1 1 1 1 0")); // below and beyond: the face's normal is (0, 3, 2)
        }
        scene.add("polygon (-10, -10, -20) (10, -10, -20) (0, 10, -50)");
        Path file = write("behind.simp", scene.toArray(new String[0]));
        int[] first = null;
        for (int threads : new int[] {1, 2, 7}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (int picture = 0; picture < 2; picture++) {
                    PageCanvas canvas = new PageCanvas();
                    canvas.drawWith(drawing);
                    ScenePipeline.draw(file, canvas, ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE);
                    int[] pixels = pixels(canvas);
                    NotBlack drawn = NotBlack.of(pixels);
                    String where = lights + " light(s), " + threads + " thread(s), picture " + picture;
                    assertEquals(Set.of(0x808080), drawn.colours(), where);
                    assertTrue(drawn.count() > 30_000, where + ": " + drawn.count() + " pixels");
                    if (first == null) {
                        first = pixels;
                    }
                    assertArrayEquals(first, pixels, where + ": the same picture");
                }
            }
        }
    }

    /** The colours (RGB) of a picture's pixels that are not black, and how many such pixels there are. */
    private record NotBlack(Set<Integer> colours, int count) {

        static NotBlack of(int[] pixels) {
            Set<Integer> colours = new HashSet<>();
            int count = 0;
            for (int p : pixels) {
                if ((p & 0xFFFFFF) != 0) {
                    colours.add(p & 0xFFFFFF);
                    count++;
                }
            }
            return new NotBlack(colours, count);
        }
    }

    private static int packed(int[] c) {
        return c[0] << 16 | c[1] << 8 | c[2];
    }

    /** A 5 x 5 grid of vertices at pixel centres (columns and rows 205 + 60 i), tilted normals, quads. */
    private void writeBumpyGrid() throws IOException {
        List<String> obj = new ArrayList<>();
        for (int j = 0; j < 5; j++) {
            for (int i = 0; i < 5; i++) {
                obj.add("v " + n(world(205 + 60 * i)) + " " + n(world(205 + 60 * j)) + " -100");
                obj.add("vn " + n(0.5 * Math.sin(1.7 * i + 0.4 * j)) + " " + n(0.5 * Math.cos(1.1 * j + i)) + " 1");
            }
        }
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                int a = 1 + 5 * j + i;
                obj.add("f " + a + "//" + a + " " + (a + 1) + "//" + (a + 1) + " " + (a + 6) + "//" + (a + 6) + " "
                        + (a + 5) + "//" + (a + 5));
            }
        }
        Files.write(dir.resolve("grid.obj"), obj);
    }

    @Test
    void gouraudEqualsPhongAtTheVertices() throws Exception {
        // Both light a vertex with its own P, N and kd; at a pixel whose centre is a vertex the two agree
        // up to float noise (at most one level), and equal the formula there. Between vertices they differ.
        writeBumpyGrid();
        String lights = light(-20, 10, -70, "0.9 0.9 0.9 1 0") + "\n" + light(30, -20, -60, "0.5 0.5 0.5 1 0");
        PageCanvas gouraud = draw(surroundings(0.6, 20), lights, "gouraud", "obj \"grid\"");
        PageCanvas phong = draw(surroundings(0.6, 20), lights, "phong", "obj \"grid\"");
        List<Light> both = List.of(new Light(-20, 10, -70, 0.9, 0.9, 0.9, 1, 0),
                new Light(30, -20, -60, 0.5, 0.5, 0.5, 1, 0));
        for (int j = 1; j < 4; j++) {
            for (int i = 1; i < 4; i++) {
                int x = 205 + 60 * i;
                int y = 205 + 60 * j;
                double[] normal = {0.5 * Math.sin(1.7 * i + 0.4 * j), 0.5 * Math.cos(1.1 * j + i), 1};
                int[] byFormula = round(formula(onSquare(x, y), normal, UP, KD, IA, 0.6, 20, both));
                int[] g = rgb(gouraud, x, y);
                int[] p = rgb(phong, x, y);
                for (int c = 0; c < 3; c++) {
                    assertTrue(Math.abs(g[c] - p[c]) <= 1, "vertex " + i + "," + j + ": " + Arrays.toString(g)
                            + " and " + Arrays.toString(p));
                    assertTrue(Math.abs(g[c] - byFormula[c]) <= 1, "vertex " + i + "," + j + ": "
                            + Arrays.toString(g) + ", the formula " + Arrays.toString(byFormula));
                }
            }
        }
        int widest = 0;
        for (int y = 205; y < 445; y++) {
            for (int x = 205; x < 445; x++) {
                int[] g = rgb(gouraud, x, y);
                int[] p = rgb(phong, x, y);
                for (int c = 0; c < 3; c++) {
                    widest = Math.max(widest, Math.abs(g[c] - p[c]));
                }
            }
        }
        assertTrue(widest >= 10, "between the vertices gouraud and phong differ; at most by " + widest);
    }

    private static int[] round(double[] colour) {
        return new int[] {(int) Math.floor(colour[0] * 255 + 0.5), (int) Math.floor(colour[1] * 255 + 0.5),
            (int) Math.floor(colour[2] * 255 + 0.5)};
    }

    // ---------------------------------------------------------------- which lights light what

    @Test
    void lightsAccumulateLightOnlyWhatComesAfterThemAndOutliveTheirBraces() throws Exception {
        // Squares A, B, C left to right; a red light above B defined after A, a blue one above C after B.
        double[] kd = {0.8, 0.8, 0.8};
        double[] ia = {0.1, 0.1, 0.1};
        PageCanvas canvas = draw("ambient 0.1 0.1 0.1", "surface 0.8 0.8 0.8 0 1",
                square(-90, -20, -50, 20, -100),
                "{", "translate " + n(world(CX)) + " " + n(world(CY)) + " -60", "light 0.9 0 0 1 0", "}",
                square(-20, -20, 20, 20, -100),
                "{", "translate " + n(world(CX + 195)) + " " + n(world(CY)) + " -60", "light 0 0 0.9 1 0", "}",
                square(50, -20, 90, 20, -100));
        Light red = new Light(world(CX), world(CY), -60, 0.9, 0, 0, 1, 0);
        Light blue = new Light(world(CX + 195), world(CY), -60, 0, 0, 0.9, 1, 0);
        assertEquals(Set.of(packed(bytes(new double[] {0.08, 0.08, 0.08}))), distinctColours(canvas, 35, 265, 160, 385),
                "A came before every light: ambient only, though the red light is near enough to light it");
        assertArrayEquals(bytes(formula(onSquare(CX, CY), UP, UP, kd, ia, 0, 1, List.of(red))), rgb(canvas, CX, CY),
                "B: the red light, straight above");
        assertArrayEquals(new int[] {204, 20, 20}, rgb(canvas, CX, CY), "0.08 + 0.9 * 0.8 = 0.8");
        int[] c = rgb(canvas, CX + 195, CY);
        assertArrayEquals(bytes(formula(onSquare(CX + 195, CY), UP, UP, kd, ia, 0, 1, List.of(red, blue))), c,
                "C: both lights, the red one still where its frame put it after its }");
        assertTrue(c[0] > 20 && c[2] > 200, Arrays.toString(c));
    }

    @Test
    void lightsBeforeTheCameraAreWorldPositionsTakenByW() throws Exception {
        String camera = "{\ntranslate 2 3 15\nrotate Y 20\nrotate X -10\ncamera -1 -1 1 1 -1 -200\n}";
        String world = light(3, 4, -2, "1 0.9 0.8 0.5 0.05");
        String rest = "ambient 0.1 0.1 0.1\nsurface 0.7 0.7 0.7 0.5 16\n" + square(-20, -20, 20, 20, -10)
                + "\n{\nrotate X -90\n" + square(-20, -30, 20, 10, -5) + "\n}";
        int[] before = pixels(draw(world, camera, rest));
        int[] after = pixels(draw(camera, world, rest));
        assertEquals(0, differing(before, after), "a light before the camera is where the same light after it is");
        // Had the light been left in camera space (not taken by W), it would sit elsewhere.
        String inCameraSpace = "{\ntranslate 2 3 15\nrotate Y 20\nrotate X -10\ntranslate 3 4 -2\nlight 1 0.9 0.8"
                + " 0.5 0.05\n}";
        int[] unmoved = pixels(draw(camera, inCameraSpace, rest));
        assertTrue(differing(before, unmoved) > 10_000, "differs from a light left in camera space: "
                + differing(before, unmoved));
    }

    private static int[] pixels(PageCanvas canvas) {
        int[] all = new int[650 * 650];
        for (int y = 0; y < 650; y++) {
            for (int x = 0; x < 650; x++) {
                all[y * 650 + x] = canvas.panel().getPixel(x, y);
            }
        }
        return all;
    }

    private static int differing(int[] a, int[] b) {
        int n = 0;
        for (int i = 0; i < a.length; i++) {
            n += a[i] == b[i] ? 0 : 1;
        }
        return n;
    }

    // ---------------------------------------------------------------- hostile lights and normals

    /**
     * Draws, or fails once 60 s have passed: a guard against a hostile light that never ends the drawing, not a
     * measure of speed (each of these takes 0.1-4 s here; under a load average of 8 the ten thousand lights took
     * over 20 s).
     */
    private PageCanvas drawBounded(String... lines) {
        return assertTimeoutPreemptively(Duration.ofSeconds(60), () -> draw(lines));
    }

    @Test
    void aLightAtTheLitPointItselfAddsNothingThere() throws Exception {
        // d = 0 with A = 0: f would be 1/0. The light lies in the square's plane, so N . L = 0 at every
        // point of it (and L = 0 at the point under it): the whole square is ambient, no NaN, no black.
        PageCanvas canvas = drawBounded(surroundings(0.5, 8), light(world(CX), world(CY), -100, "1 1 1 0 1"),
                SQUARE_AT_100);
        int ambient = packed(bytes(new double[] {KD[0] * IA[0], KD[1] * IA[1], KD[2] * IA[2]}));
        assertEquals(Set.of(ambient), distinctColours(canvas, 0, 0, 650, 650));
        // Curved: a triangle whose first vertex is at the light, with normals that turn toward it at the
        // other two. There L = 0 (nothing added); close by f = 1 / d is huge. Every pixel is at least the
        // ambient colour (a NaN channel would come out 0), and some are lit.
        write("at.obj", "v 0 0 -100", "v 60 0 -100", "v 0 60 -100", "vn 0 0 1", "vn -1 0 1", "vn 0 -1 1",
                "f 1//1 2//2 3//3");
        int[] least = bytes(new double[] {KD[0] * IA[0], KD[1] * IA[1], KD[2] * IA[2]});
        for (String mode : List.of("flat", "gouraud", "phong")) {
            PageCanvas curved = drawBounded(surroundings(0.5, 8), light(0, 0, -100, "1 1 1 0 1"), mode, "obj \"at\"");
            int lit = 0;
            for (int y = 327; y < 515; y++) {
                for (int x = 327; x < 515 - (y - 327); x++) {
                    int[] c = rgb(curved, x, y);
                    for (int k = 0; k < 3; k++) {
                        assertTrue(c[k] >= least[k], mode + " at " + x + "," + y + ": " + Arrays.toString(c));
                    }
                    lit += Arrays.equals(c, least) ? 0 : 1;
                }
            }
            assertTrue(lit > 1000, mode + ": lit pixels " + lit);
        }
    }

    @Test
    void exponentZeroMakesTheSpecularTermKsWhereverTheLightReaches() throws Exception {
        int k = 100;
        double h = k * 200.0 / 650 / Math.sqrt(3);
        PageCanvas canvas = drawBounded(surroundings(0.3, 0), light(world(CX), world(CY), -100 + h, "0.5 0.5 0.5 1 0"),
                SQUARE_AT_100);
        double[] slanted = new double[3];
        for (int c = 0; c < 3; c++) {
            slanted[c] = KD[c] * IA[c] + 0.5 * (KD[c] * 0.5 + 0.3); // max(0, V . R)^0 = 1
        }
        assertArrayEquals(bytes(slanted), rgb(canvas, CX + k, CY));
    }

    @Test
    void aHugeExponentLeavesTheSpecularPeakOnly() throws Exception {
        int k = 100;
        double h = k * 200.0 / 650 / Math.sqrt(3);
        PageCanvas canvas = drawBounded(surroundings(0.3, 1e6), light(world(CX), world(CY), -100 + h,
                "0.5 0.5 0.5 1 0"), SQUARE_AT_100);
        double[] under = new double[3];
        double[] slanted = new double[3];
        for (int c = 0; c < 3; c++) {
            under[c] = KD[c] * IA[c] + 0.5 * (KD[c] + 0.3); // V . R = 1 exactly under the light
            slanted[c] = KD[c] * IA[c] + 0.5 * KD[c] * 0.5; // 0.5^1e6 = 0
        }
        assertArrayEquals(bytes(under), rgb(canvas, CX, CY));
        assertArrayEquals(bytes(slanted), rgb(canvas, CX + k, CY));
    }

    @Test
    void hugeIntensitiesSaturateWithoutNaN() throws Exception {
        // 1e308 / 1e-300 overflows to infinity; times kd = 0 that has no value, and must add nothing.
        PageCanvas canvas = drawBounded("ambient 0.2 0.2 0.2", "surface 0.5 0 0.5 0 1",
                light(0, 0, -50, "1e308 1e308 1e308 1e-300 0"), SQUARE_AT_100);
        assertEquals(Set.of(0xFF00FF), distinctColours(canvas, 0, 0, 650, 650));
        PageCanvas ambient = drawBounded("ambient 1e308 1e308 1e308", "surface 0.5 0 0.5 0.3 8", SQUARE_AT_100);
        assertEquals(Set.of(0xFF00FF), distinctColours(ambient, 0, 0, 650, 650));
    }

    @Test
    void tenThousandLightsAddUpToOneOfTheirSum() throws Exception {
        // 10,000 lights of 1/10,000 each, all at one point 30 above the pixel, light it as one light of 1.
        List<String> scene = new ArrayList<>(List.of(surroundings(0.2, 10), "{",
                "translate " + n(world(CX)) + " " + n(world(CY)) + " -70"));
        for (int i = 0; i < 10_000; i++) {
            scene.add("light 0.0001 0.0001 0.0001 1 0");
        }
        scene.add("}");
        scene.add(square(-10, -10, 10, 10, -100)); // 65 x 65 pixels, each lit by every light
        PageCanvas canvas = drawBounded(scene.toArray(String[]::new));
        double[] one = new double[3];
        for (int c = 0; c < 3; c++) {
            one[c] = KD[c] * IA[c] + (KD[c] + 0.2);
        }
        assertArrayEquals(bytes(one), rgb(canvas, CX, CY));
        Set<Integer> colours = distinctColours(canvas, CX - 30, CY - 30, CX + 30, CY + 30);
        assertTrue(!colours.contains(0), "every pixel of the square is drawn");
    }

    @Test
    void aZeroNormalGivesTheAmbientTermInEveryMode() throws Exception {
        // An obj face whose every vertex has the normal 0 0 0, and one whose first three vertices are
        // collinear (its face normal is zero); a bright light right above both.
        write("zero.obj", "v -60 -30 -100", "v -10 -30 -100", "v -10 30 -100", "v -60 30 -100", "vn 0 0 0",
                "f 1//1 2//1 3//1 4//1");
        write("degenerate.obj", "v 10 -30 -100", "v 35 -30 -100", "v 60 -30 -100", "v 60 30 -100",
                "v 10 30 -100", "f 1 2 3 4 5");
        int ambient = packed(bytes(new double[] {KD[0] * IA[0], KD[1] * IA[1], KD[2] * IA[2]}));
        for (String mode : List.of("flat", "gouraud", "phong")) {
            PageCanvas canvas = drawBounded(surroundings(0.5, 8), light(0, 0, -60, "5 5 5 1 0"), mode,
                    "obj \"zero\"", "obj \"degenerate\"", "polygon (0, 50, -100) (0, 50, -100) (0, 50, -100)");
            assertEquals(Set.of(ambient), distinctColours(canvas, 131, 229, 292, 422), mode + ", vn 0 0 0");
            assertEquals(Set.of(ambient), distinctColours(canvas, 358, 229, 520, 422), mode + ", collinear start");
        }
        PageCanvas lit = drawBounded(surroundings(0.5, 8), light(0, 0, -60, "5 5 5 1 0"),
                square(10, -30, 60, 30, -100));
        assertTrue(!distinctColours(lit, 358, 229, 520, 422).contains(ambient), "the same light on a sound face");
    }
}
