package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * The explanation's terms against SPEC's formula computed here, in plain
 * steps that share no code with simpview's lighting: per light L, d, f,
 * N . L, R, V . R, (V . R)^p and the diffuse and specular parts, the sum,
 * the clamp, the fog and the bytes; gouraud's lit vertex colours, each
 * worked out term by term, and weights;
 * flat's centroid colour. Within 1e-9; the bytes exactly.
 */
class LightingExplanationTest {

    private static final double EPS = 1e-9;
    /** Lights in camera space (the camera stands at the identity, so W is the identity): x, y, z, r, g, b, A, B. */
    private static final double[][] LIGHTS = {
        {20, 30, -10, 1, 0.9, 0.8, 1, 0.01},
        {-5, -40, -90, 0.5, 0.5, 1, 0.5, 0.02},
        {0, 0, 0, 0.3, 0.3, 0.3, 1, 0},
    };
    private static final double[] AMBIENT = {0.1, 0.2, 0.15};
    private static final double[] KD = {0.8, 0.5, 0.3};
    private static final double KS = 0.6;
    private static final double P = 12;
    private static final double FOG_NEAR = -20;
    private static final double FOG_FAR = -60;
    private static final double[] FOG = {0.1, 0.1, 0.3};
    private static final double[][] TRIANGLE = {{-30, -30, -50}, {30, -30, -40}, {0, 30, -45}};

    @TempDir
    Path dir;

    private Path scene(String shading) throws Exception {
        Path file = dir.resolve(shading + ".simp");
        StringBuilder sb = new StringBuilder("camera -1 -1 1 1 -1 -100\n");
        sb.append("ambient ").append(AMBIENT[0]).append(' ').append(AMBIENT[1]).append(' ').append(AMBIENT[2]).append('\n');
        sb.append("surface ").append(KD[0]).append(' ').append(KD[1]).append(' ').append(KD[2]).append(' ').append(KS)
                .append(' ').append(P).append('\n');
        for (double[] l : LIGHTS) {
            sb.append("{\ntranslate ").append(l[0]).append(' ').append(l[1]).append(' ').append(l[2]).append("\nlight ")
                    .append(l[3]).append(' ').append(l[4]).append(' ').append(l[5]).append(' ').append(l[6]).append(' ')
                    .append(l[7]).append("\n}\n");
        }
        sb.append("depth ").append(FOG_NEAR).append(' ').append(FOG_FAR).append(" (").append(FOG[0]).append(", ")
                .append(FOG[1]).append(", ").append(FOG[2]).append(")\n");
        sb.append(shading).append('\n');
        sb.append("polygon");
        for (double[] v : TRIANGLE) {
            sb.append(" (").append(v[0]).append(", ").append(v[1]).append(", ").append(v[2]).append(')');
        }
        Files.writeString(file, sb.append('\n').toString());
        return file;
    }

    @Test
    void phongTermsFollowTheFormula() throws Exception {
        Path file = scene("phong");
        PixelInspector inspector = new PixelInspector();
        int checked = 0;
        int behind = 0;
        for (int y = 100; y < 600; y += 37) {
            for (int x = 100; x < 600; x += 41) {
                PixelReport report = inspector.inspect(InspectedScene.of(file), x, y);
                Terms t = report.explanation();
                if (t == null) {
                    continue;
                }
                checked++;
                String where = "pixel (" + x + ", " + y + ")";
                assertEquals("phong", t.get("shading"));
                double[] p = t.vector("P");
                double[] nRaw = t.vector("N_interpolated");
                double[] kd = t.vector("kd");
                // P lies on the triangle's plane and projects onto the pixel's centre.
                double[] normal = faceNormal();
                assertEquals(0, dot(normal, sub(p, TRIANGLE[0])) / length(normal), 1e-7, where + ": P off the plane");
                assertEquals(x + 0.5, (p[0] / -p[2] + 1) * 325, 1e-6, where + ": P's panel x");
                assertEquals(y + 0.5, (p[1] / -p[2] + 1) * 325, 1e-6, where + ": P's panel y");
                assertArrayEquals(KD, kd, EPS, where + ": kd");
                double[] n = scale(nRaw, 1 / length(nRaw));
                assertArrayEquals(n, t.vector("N"), EPS, where + ": N");
                double[] v = scale(p, -1 / length(p));
                assertArrayEquals(v, t.vector("V"), EPS, where + ": V");
                double[] sum = {KD[0] * AMBIENT[0], KD[1] * AMBIENT[1], KD[2] * AMBIENT[2]};
                assertArrayEquals(sum, t.terms("ambient").vector("kd_Ia"), EPS, where + ": ambient");
                List<Terms> lights = t.list("lights");
                assertEquals(LIGHTS.length, lights.size());
                for (int i = 0; i < LIGHTS.length; i++) {
                    double[] light = LIGHTS[i];
                    Terms lt = lights.get(i);
                    double[] toLight = sub(new double[] {light[0], light[1], light[2]}, p);
                    double d = length(toLight);
                    double[] l = scale(toLight, 1 / d);
                    double f = 1 / (light[6] + light[7] * d);
                    double nl = dot(n, l);
                    assertArrayEquals(l, lt.vector("L"), EPS, where + ": L" + i);
                    assertEquals(d, lt.number("distance"), EPS, where + ": d" + i);
                    assertEquals(f, lt.number("f"), EPS, where + ": f" + i);
                    assertEquals(nl, lt.number("N_dot_L"), EPS, where + ": N.L" + i);
                    if (nl <= 0) {
                        behind++;
                        assertEquals(true, lt.get("behind_surface"), where + ": light " + i + " is behind");
                        continue;
                    }
                    double[] r = sub(scale(n, 2 * nl), l);
                    double vr = dot(v, r);
                    double power = Math.pow(Math.max(0, vr), P);
                    assertArrayEquals(r, lt.vector("R"), EPS, where + ": R" + i);
                    assertEquals(vr, lt.number("V_dot_R"), EPS, where + ": V.R" + i);
                    assertEquals(power, lt.number("V_dot_R_pow_p"), EPS, where + ": (V.R)^p" + i);
                    for (int c = 0; c < 3; c++) {
                        double diffuse = light[3 + c] * f * KD[c] * nl;
                        double specular = light[3 + c] * f * KS * power;
                        assertEquals(diffuse, lt.vector("diffuse")[c], EPS, where + ": diffuse" + i);
                        assertEquals(specular, lt.vector("specular")[c], EPS, where + ": specular" + i);
                        sum[c] += diffuse + specular;
                    }
                }
                assertArrayEquals(sum, t.vector("sum"), EPS, where + ": sum");
                double[] clamped = new double[3];
                for (int c = 0; c < 3; c++) {
                    clamped[c] = Math.max(0, Math.min(1, sum[c]));
                }
                assertArrayEquals(clamped, t.vector("clamped"), EPS, where + ": clamp");
                assertArrayEquals(clamped, t.vector("lit"), EPS, where + ": the lighting's own colour");
                fogAndBytes(t, report, clamped, where);
            }
        }
        assertTrue(checked > 40, "too few lit pixels: " + checked);
        assertTrue(behind > 0, "no light was behind the surface: the test does not reach that case");
    }

    @Test
    void gouraudVertexColoursAndWeights() throws Exception {
        Path file = scene("gouraud");
        PixelInspector inspector = new PixelInspector();
        double[][] lit = new double[3][];
        for (int k = 0; k < 3; k++) {
            lit[k] = clamp(light(TRIANGLE[k], unit(faceNormal())));
        }
        int checked = 0;
        for (int y = 100; y < 600; y += 53) {
            for (int x = 100; x < 600; x += 47) {
                PixelReport report = inspector.inspect(InspectedScene.of(file), x, y);
                Terms t = report.explanation();
                if (t == null) {
                    continue;
                }
                checked++;
                String where = "pixel (" + x + ", " + y + ")";
                assertEquals("gouraud", t.get("shading"));
                List<Terms> vertices = t.list("vertex_colours");
                double[] w = t.vector("weights");
                double[] mixed = new double[3];
                for (int k = 0; k < 3; k++) {
                    int index = (int) vertices.get(k).number("vertex");
                    assertArrayEquals(lit[index], vertices.get(k).vector("colour"), EPS, where + ": vertex " + index);
                    // each vertex's colour worked out term by term where it was lit
                    Terms lighting = vertices.get(k).terms("lighting");
                    assertArrayEquals(TRIANGLE[index], lighting.vector("P"), EPS, where + ": P of vertex " + index);
                    assertArrayEquals(unit(faceNormal()), lighting.vector("N"), EPS, where + ": N of vertex " + index);
                    assertArrayEquals(KD, lighting.vector("kd"), EPS, where + ": kd of vertex " + index);
                    assertArrayEquals(light(TRIANGLE[index], unit(faceNormal())), lighting.vector("sum"), EPS,
                            where + ": unclamped sum of vertex " + index);
                    assertArrayEquals(lit[index], lighting.vector("clamped"), EPS, where + ": clamp of vertex " + index);
                    for (int c = 0; c < 3; c++) {
                        mixed[c] += w[k] * lit[index][c];
                    }
                }
                assertEquals(1, w[0] + w[1] + w[2], EPS, where + ": weights");
                assertArrayEquals(mixed, t.vector("interpolated"), 1e-6, where + ": weighted colours");
                fogAndBytes(t, report, t.vector("interpolated"), where);
            }
        }
        assertTrue(checked > 20, "too few lit pixels: " + checked);
    }

    @Test
    void flatCentroidColour() throws Exception {
        Path file = scene("flat");
        double[] centroid = new double[3];
        for (double[] v : TRIANGLE) {
            for (int c = 0; c < 3; c++) {
                centroid[c] += v[c] / 3;
            }
        }
        double[] expected = clamp(light(centroid, unit(faceNormal())));
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(file), 325, 325);
        Terms t = report.explanation();
        assertEquals("flat", t.get("shading"));
        assertArrayEquals(expected, t.vector("centroid_colour"), EPS);
        fogAndBytes(t, report, expected, "pixel (325, 325)");
        // worked out term by term where it was lit: at the centroid, with the face normal and kd
        assertArrayEquals(centroid, t.vector("P"), EPS);
        assertArrayEquals(unit(faceNormal()), t.vector("N"), EPS);
        assertArrayEquals(unit(faceNormal()), t.vector("N_face"), EPS, "a polygon of simp has no normals of its own");
        assertTrue(t.get("lit_at").toString().contains("its face normal"), t.get("lit_at").toString());
        assertArrayEquals(KD, t.vector("kd"), EPS);
        assertArrayEquals(light(centroid, unit(faceNormal())), t.vector("sum"), EPS, "unclamped");
        assertArrayEquals(expected, t.vector("clamped"), EPS);
    }

    /**
     * A flat face whose vertices all have their own normals is lit with
     * their sum: (0, 0, 1) twice and (0, 0.6, 0.8) make (0, 0.6, 2.8), named
     * N_summed; one vertex without its own normal gives the face normal,
     * N_face, (0, 0, 1) for this face square to the eye.
     */
    @Test
    void flatNamesTheNormalItWasLitWith() throws Exception {
        Files.writeString(dir.resolve("own.obj"), "v -5 -5 0\nv 5 -5 0\nv 0 5 0\nvn 0 0 1\nvn 0 0.6 0.8\n"
                + "f 1//1 2//1 3//2\n");
        Files.writeString(dir.resolve("some.obj"), "v -5 -5 0\nv 5 -5 0\nv 0 5 0\nvn 0 0.6 0.8\n"
                + "f 1 2 3//1\n");
        for (String model : new String[] {"own", "some"}) {
            Path file = dir.resolve(model + ".simp");
            Files.writeString(file, "camera -1 -1 1 1 -1 -100\nflat\n{\ntranslate 0 0 -20\nobj \"" + model
                    + "\"\n}\n");
            Terms t = new PixelInspector().inspect(InspectedScene.of(file), 325, 325).explanation();
            if (model.equals("own")) {
                assertArrayEquals(new double[] {0, 0.6, 2.8}, t.vector("N_summed"), EPS);
                assertEquals(null, t.get("N_face"));
                assertTrue(t.get("lit_at").toString().contains("the sum of its vertices' own unit normals"));
            } else {
                assertArrayEquals(new double[] {0, 0, 1}, t.vector("N_face"), EPS);
                assertEquals(null, t.get("N_summed"));
            }
        }
    }

    /**
     * A back face says so: the triangle (-3, -3, -8) (0, 3, -8) (3, -3, -8)
     * runs clockwise on the panel, its face normal (0, 0, -1) points away
     * from the eye; lit at its centroid (0, -1, -8), V = (0, 1, 8) / sqrt(65),
     * so N . V = -8 / sqrt(65), and the light at the eye is behind it. The
     * same triangle the other way round faces the eye and says nothing.
     */
    @Test
    void aBackFaceSaysItFacesAway() throws Exception {
        String[] triangles = {"(-3, -3, -8) (0, 3, -8) (3, -3, -8)", "(-3, -3, -8) (3, -3, -8) (0, 3, -8)"};
        for (int k = 0; k < 2; k++) {
            Path file = dir.resolve("facing" + k + ".simp");
            Files.writeString(file, "camera -1 -1 1 1 -1 -100\nambient 0.3 0.3 0.3\nlight 1 1 1 1 0\nflat\npolygon "
                    + triangles[k] + "\n");
            Terms t = new PixelInspector().inspect(InspectedScene.of(file), 325, 300).explanation();
            if (k == 0) {
                assertEquals(-8 / Math.sqrt(65), t.number("N_dot_V"), EPS);
                assertTrue(t.get("facing").toString().startsWith("away from the eye (N . V < 0): the eye sees the "
                        + "polygon's back"), t.get("facing").toString());
                assertEquals(true, t.list("lights").get(0).get("behind_surface"));
            } else {
                assertEquals(null, t.get("N_dot_V"));
                assertEquals(null, t.get("facing"));
            }
        }
    }

    /**
     * The same back face under phong (the shading a scene starts with), whose N is interpolated, and gouraud,
     * lit at each vertex: a simp polygon has no normal of its own at any vertex, so its N is its face normal
     * everywhere, and the words say the eye sees its back, not that vertex normals point away near an outline.
     * At the pixel (325, 300) phong's P lies on the plane z = -8 on the ray through the pixel's centre,
     * (x' (-z), y' (-z), z) with x' = (325.5 - 325) / 325 and y' = (300.5 - 325) / 325.
     */
    @Test
    void aBackFaceSaysItFacesAwayUnderEveryShading() throws Exception {
        for (String shading : new String[] {"phong", "gouraud"}) {
            Path file = dir.resolve("facing-" + shading + ".simp");
            Files.writeString(file, "camera -1 -1 1 1 -1 -100\nambient 0.3 0.3 0.3\nlight 1 1 1 1 0\n" + shading
                    + "\npolygon (-3, -3, -8) (0, 3, -8) (3, -3, -8)\n");
            Terms t = new PixelInspector().inspect(InspectedScene.of(file), 325, 300).explanation();
            Terms lit = shading.equals("phong") ? t : (Terms) t.list("vertex_colours").get(0).get("lighting");
            String facing = String.valueOf(lit.get("facing"));
            assertTrue(facing.startsWith("away from the eye (N . V < 0): the eye sees the polygon's back"),
                    shading + ": " + facing);
            assertFalse(facing.contains("own normals"), shading + ": " + facing);
            if (shading.equals("phong")) {
                double[] p = {0.5 / 325 * 8, -24.5 / 325 * 8, -8};
                assertEquals(-8 / length(p), t.number("N_dot_V"), 1e-6);
            }
        }
    }

    /**
     * A polygon that faces the eye (counter-clockwise on the panel) whose own vertex normals point away, (0, 0.6,
     * -0.8) at every vertex, as they may near a smooth model's outline: phong's N . V is below 0, and the words
     * say it is N, from the vertices' normals, that points away, not that the eye sees the polygon's back.
     */
    @Test
    void vertexNormalsPointingAwayOnAFrontFaceAreNotCalledItsBack() throws Exception {
        Files.writeString(dir.resolve("bent.obj"), "v -3 -3 0\nv 3 -3 0\nv 0 3 0\nvn 0 0.6 -0.8\n"
                + "f 1//1 2//1 3//1\n");
        Path file = dir.resolve("bent.simp");
        Files.writeString(file, "camera -1 -1 1 1 -1 -100\nambient 0.2 0.2 0.2\nlight 1 1 1 1 0\nphong\n"
                + "translate 0 0 -8\nobj bent\n");
        Terms t = new PixelInspector().inspect(InspectedScene.of(file), 325, 300).explanation();
        assertTrue(t.number("N_dot_V") < 0);
        String facing = t.get("facing").toString();
        assertTrue(facing.startsWith("away from the eye (N . V < 0): N, made from the vertices' own normals"), facing);
        assertFalse(facing.contains("back"), facing);
        assertEquals(true, t.list("lights").get(0).get("behind_surface"));
    }

    /** A flat polygon's colour is told as the polygon's own, to the bit, at a pixel where its depth runs. */
    @Test
    void flatCentroidColourIsThePolygonsToTheBit() throws Exception {
        Path file = dir.resolve("half.simp");
        Files.writeString(file, "camera -1 -1 1 1 -0.1 -200\nambient 0.5 0.5 0.5\nflat\n"
                + "polygon (-10, -10, -20) (10, -10, -20) (0, 10, -50)\n");
        for (int[] at : new int[][] {{164, 164}, {325, 200}, {300, 260}}) {
            PixelReport report = new PixelInspector().inspect(InspectedScene.of(file), at[0], at[1]);
            Terms t = report.explanation();
            assertArrayEquals(new double[] {0.5, 0.5, 0.5}, t.vector("centroid_colour"), 0, Arrays.toString(at));
            assertArrayEquals(new int[] {128, 128, 128}, t.bytes("final_rgb"), Arrays.toString(at));
        }
    }

    @Test
    void depthCueTerms() throws Exception {
        Path file = dir.resolve("cued.simp");
        Files.writeString(file, "polygon (-90, -90, -20) (90, -90, -180) (0, 90, -100)\n");
        PixelReport report = new PixelInspector().inspect(
                InspectedScene.cued(file, new Rgb(0.2, 1, 0.6), new Rgb(0.1, 0, 0.3)),
                325, 325);
        Terms t = report.explanation();
        double z = t.number("z");
        assertEquals(report.depth(), z, 0);
        double tt = (z + 200) / 200;
        assertEquals(tt, t.number("t"), 1e-12);
        double[] cued = {0.1 + 0.1 * tt, tt, 0.3 + 0.3 * tt};
        assertArrayEquals(cued, t.vector("cued"), 1e-12);
        int[] bytes = t.bytes("final_rgb");
        for (int c = 0; c < 3; c++) {
            assertEquals(Math.floor(cued[c] * 255 + 0.5), bytes[c], 1, "channel " + c + " off by more than a rounding");
        }
    }

    /**
     * The fog says why its t is what it is: a flat triangle facing the eye at
     * z = -30 under fog from -10 to -50 is halfway, t = (-30 + 50) / (-10 +
     * 50) = 0.5; at z = -5 it is nearer than near (no fog), at z = -80
     * beyond far (the fog's colour alone).
     */
    @Test
    void theFogSaysWhyItsTIsWhatItIs() throws Exception {
        String[] whys = {
            "t = (z - far) / (near - far) = (-30 + 50) / (-10 + 50) = 0.5; "
                    + "fogged = t (the colour before fog) + (1 - t) (the fog's colour)",
            "z -5 is at or nearer than near -10: no fog (t = 1), the colour stays as it is",
            "z -80 is at or beyond far -50: the fog's colour alone (t = 0)",
        };
        double[] depths = {-30, -5, -80};
        for (int k = 0; k < depths.length; k++) {
            double z = depths[k];
            Path file = dir.resolve("fog" + k + ".simp");
            Files.writeString(file, "camera -1 -1 1 1 -1 -100\ndepth -10 -50 (0 0 1)\nflat\npolygon (" + z + ", " + z
                    + ", " + z + ") (" + -z + ", " + z + ", " + z + ") (0, " + -z + ", " + z + ")\n");
            Terms fog = new PixelInspector().inspect(InspectedScene.of(file), 325, 325).explanation().terms("fog");
            assertEquals(whys[k], fog.get("why"), "z " + z);
        }
    }

    /** Fog's t and colour and the bytes, from the unfogged colour; the bytes are the pixel's. */
    private static void fogAndBytes(Terms t, PixelReport report, double[] colour, String where) {
        double z = t.number("z");
        double[] fogged = colour.clone();
        if (z < FOG_NEAR) {
            double ft = z <= FOG_FAR ? 0 : (z - FOG_FAR) / (FOG_NEAR - FOG_FAR);
            assertEquals(ft, t.terms("fog").number("t"), EPS, where + ": fog t");
            for (int c = 0; c < 3; c++) {
                fogged[c] = ft * colour[c] + (1 - ft) * FOG[c];
            }
        }
        assertArrayEquals(fogged, t.vector("fogged"), 1e-6, where + ": fogged");
        int[] bytes = t.bytes("final_rgb");
        int argb = report.argb();
        assertArrayEquals(new int[] {argb >>> 16 & 0xFF, argb >>> 8 & 0xFF, argb & 0xFF}, bytes,
                where + ": the final bytes are not the pixel's");
        for (int c = 0; c < 3; c++) {
            double level = fogged[c] * 255 + 0.5;
            // Away from a rounding tie the bytes follow from the formula alone.
            if (Math.abs(level - Math.rint(level)) > 1e-6) {
                assertEquals((int) Math.floor(level), bytes[c], where + ": byte " + c);
            }
        }
    }

    /** SPEC's I at camera-space point p with unit normal n, the scene's kd, before the clamp. */
    private static double[] light(double[] p, double[] n) {
        double[] v = scale(p, -1 / length(p));
        double[] sum = {KD[0] * AMBIENT[0], KD[1] * AMBIENT[1], KD[2] * AMBIENT[2]};
        for (double[] light : LIGHTS) {
            double[] toLight = sub(new double[] {light[0], light[1], light[2]}, p);
            double d = length(toLight);
            double[] l = scale(toLight, 1 / d);
            double nl = dot(n, l);
            if (nl <= 0) {
                continue;
            }
            double f = 1 / (light[6] + light[7] * d);
            double[] r = sub(scale(n, 2 * nl), l);
            double power = Math.pow(Math.max(0, dot(v, r)), P);
            for (int c = 0; c < 3; c++) {
                sum[c] += light[3 + c] * f * (KD[c] * nl + KS * power);
            }
        }
        return sum;
    }

    private static double[] faceNormal() {
        double[] a = sub(TRIANGLE[1], TRIANGLE[0]);
        double[] b = sub(TRIANGLE[2], TRIANGLE[0]);
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /**
     * A lit line from camera (-5, -5, -10), red, to (5, 5, -40), green: panel
     * (162.5, 162.5) and (365.625, 365.625), rounded (163, 163) to (366, 366),
     * 203 steps. Pixel (300, 300) is step 137, t = 137 / 203; q = 1 / -z is
     * 0.1 and 0.025 at the ends, and the ends weigh (1 - t) 0.1 / q and
     * t 0.025 / q: the red and green of the pixel, and z = -1 / q.
     */
    @Test
    void aLitLinesPixelIsItsEndsWeighedPerspectiveCorrect() throws Exception {
        Path file = dir.resolve("line.simp");
        Files.writeString(file, "camera -1 -1 1 1 -1 -100\nline (-5 -5 -10 1 0 0) (5 5 -40 0 1 0)\n");
        PixelReport r = new PixelInspector().inspect(InspectedScene.of(file), 300, 300);
        Terms along = r.explanation().terms("along");
        double t = 137.0 / 203;
        double q = (1 - t) * 0.1 + t * 0.025;
        assertEquals(137, along.number("step"), 0);
        assertEquals(203, along.number("steps"), 0);
        assertEquals(t, along.number("t"), 1e-15);
        assertEquals(q, along.number("q"), 1e-15);
        assertEquals(-1 / q, r.explanation().number("z"), 1e-12);
        double[] weights = {(1 - t) * 0.1 / q, t * 0.025 / q};
        assertArrayEquals(weights, along.vector("weights"), 1e-12);
        assertArrayEquals(new double[] {weights[0], weights[1], 0}, along.vector("weighted"), 1e-12);
        assertArrayEquals(along.vector("weighted"), r.explanation().vector("kd"), 1e-12, "what was drawn");
        assertEquals(0, along.terms("start").number("vertex"), 0);
        assertArrayEquals(new double[] {1, 0, 0}, along.terms("start").vector("kd"), 1e-12);
    }

    /**
     * A phong triangle of kd 0.5 under the ambient light alone, tilted in depth: at every pixel of its box
     * the inspector's colour is the drawn pixel's, and at each pixel it covers the explanation's kd is 0.5 to the
     * bit, says it is the one kd every vertex has, and its final_rgb (the explained colour) is the drawn pixel,
     * 128, drawn on one thread and on two, the same to the bit. Resolved as (kd q) / q, 94 of its 1,452 pixels
     * were drawn (and explained) 127.
     */
    @Test
    void aPhongPolygonOfOneKdIsExplainedAsItIsDrawnAtEveryPixel() throws Exception {
        Path file = dir.resolve("half-phong.simp");
        Files.writeString(file, "camera -1 -1 1 1 -0.1 -200\nambient 1 1 1\nsurface 0.5 0.5 0.5\nphong\n"
                + "polygon (-2, -2, -20) (2, -2, -20) (0, 2, -50)\n");
        PageCanvas one = drawn(file, 1);
        PageCanvas two = drawn(file, 2);
        int minX = PageCanvas.PANEL;
        int minY = PageCanvas.PANEL;
        int maxX = -1;
        int maxY = -1;
        for (int y = 0; y < PageCanvas.PANEL; y++) {
            for (int x = 0; x < PageCanvas.PANEL; x++) {
                int p = one.panel().getPixel(x, y);
                assertEquals(p, two.panel().getPixel(x, y), "pixel (" + x + ", " + y + ") on two threads");
                if ((p & 0xFFFFFF) != 0) {
                    minX = Math.min(minX, x);
                    minY = Math.min(minY, y);
                    maxX = Math.max(maxX, x);
                    maxY = Math.max(maxY, y);
                }
            }
        }
        PixelInspector inspector = new PixelInspector();
        double[] half = {0.5, 0.5, 0.5};
        int covered = 0;
        for (int y = minY - 2; y <= maxY + 2; y++) {
            for (int x = minX - 2; x <= maxX + 2; x++) {
                String where = "pixel (" + x + ", " + y + ")";
                int drawn = one.panel().getPixel(x, y);
                PixelReport r = inspector.inspect(InspectedScene.of(file), x, y);
                assertEquals(drawn, r.argb(), where + ": the replay's pixel");
                Terms t = r.explanation();
                if (t == null) {
                    assertEquals(0, drawn & 0xFFFFFF, where + ": drawn, but not explained");
                    continue;
                }
                covered++;
                assertEquals("phong", t.get("shading"), where);
                assertArrayEquals(half, t.vector("kd"), 0, where + ": kd");
                String from = (String) t.get("kd_from");
                assertTrue(from.startsWith("every vertex of the clipped polygon has this kd"), where + ": " + from);
                assertArrayEquals(new int[] {drawn >>> 16 & 0xFF, drawn >>> 8 & 0xFF, drawn & 0xFF},
                        t.bytes("final_rgb"), where + ": the explained colour is not the drawn pixel");
                assertArrayEquals(new int[] {128, 128, 128}, t.bytes("final_rgb"), where);
            }
        }
        assertEquals(1452, covered, "pixels covered");
    }

    /**
     * A phong triangle whose vertices have kd of their own, not all the same: its kd is interpolated, and the
     * explanation says so; the explained colour is still the drawn pixel.
     */
    @Test
    void aPhongPolygonOfSeveralKdSaysItsKdIsInterpolated() throws Exception {
        Path file = dir.resolve("mixed-phong.simp");
        Files.writeString(file, "camera -1 -1 1 1 -0.1 -200\nambient 1 1 1\nphong\n"
                + "polygon (-2, -2, -20, 1, 0.5, 0) (2, -2, -20, 0.5, 0.5, 0.5) (0, 2, -50, 0, 0.5, 1)\n");
        PageCanvas one = drawn(file, 1);
        PixelReport r = new PixelInspector().inspect(InspectedScene.of(file), 325, 310);
        Terms t = r.explanation();
        String from = (String) t.get("kd_from");
        assertTrue(from.startsWith("interpolated perspective-correct"), from);
        int drawn = one.panel().getPixel(325, 310);
        assertArrayEquals(new int[] {drawn >>> 16 & 0xFF, drawn >>> 8 & 0xFF, drawn & 0xFF}, t.bytes("final_rgb"));
        double[] kd = t.vector("kd");
        assertTrue(kd[0] > 0.1 && kd[0] < 0.9 && kd[2] > 0.1 && kd[2] < 0.9, Arrays.toString(kd));
    }

    /** The scene drawn as render draws it, on {@code threads} threads. */
    private static PageCanvas drawn(Path file, int threads) throws Exception {
        PageCanvas canvas = new PageCanvas();
        try (DrawingThreads drawing = DrawingThreads.of(threads)) {
            canvas.drawWith(drawing);
            ScenePipeline.draw(file, canvas, ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE);
        }
        return canvas;
    }

    /**
     * The same line in one colour, kd 0.5 at both ends: its kd at every pixel
     * is 0.5 to the bit, and so its byte round(127.5) = 128. The explanation
     * shows each end's kd as it is and says why the pixel's is the same.
     */
    @Test
    void aLitLineOfOneColourIsThatColourToTheBit() throws Exception {
        Path file = dir.resolve("grey.simp");
        Files.writeString(file, "camera -1 -1 1 1 -1 -100\nline (-5 -5 -10 0.5 0.5 0.5) (5 5 -40 0.5 0.5 0.5)\n");
        double[] half = {0.5, 0.5, 0.5};
        for (int k = 0; k <= 203; k++) {
            PixelReport r = new PixelInspector().inspect(InspectedScene.of(file), 163 + k, 163 + k);
            assertArrayEquals(half, r.explanation().vector("kd"), 0, "step " + k);
            assertArrayEquals(new int[] {128, 128, 128}, r.explanation().bytes("final_rgb"), "step " + k);
            if (k == 137) {
                Terms along = r.explanation().terms("along");
                assertArrayEquals(half, along.terms("start").vector("kd"), 0);
                assertArrayEquals(half, along.terms("end").vector("kd"), 0);
                String rule = (String) along.get("rule");
                assertTrue(rule.contains("both ends carry the same kd"), rule);
            }
        }
    }

    /**
     * A lit wire triangle: camera (-20, -20, -40), (20, -20, -40) and
     * (0, 20, -40) land at window (-0.5, -0.5), (0.5, -0.5) and (0, 0.5),
     * panel (162.5, 162.5), (487.5, 162.5) and (325, 487.5). Its edge from
     * vertex 2 to vertex 0 is y-major and runs down, so the DDA starts at
     * vertex 0's end; pixel (244, 325) is on it.
     */
    @Test
    void aWireEdgeNamesItselfAndItsEndsInTheWalksOrder() throws Exception {
        Path file = dir.resolve("wire.simp");
        Files.writeString(file, "camera -1 -1 1 1 -1 -100\nwire\n"
                + "polygon (-20 -20 -40 1 0 0) (20 -20 -40 0 1 0) (0 20 -40 0 0 1)\n");
        PixelReport r = new PixelInspector().inspect(InspectedScene.of(file), 244, 325);
        Terms along = r.explanation().terms("along");
        assertEquals("2-0", along.get("edge"));
        assertEquals(0, along.terms("start").number("vertex"), 0);
        assertEquals(2, along.terms("end").number("vertex"), 0);
        // y-major from row 163 to 488: 325 steps, row 325 is step 162; every z alike, so the weights are 1 - t and t.
        double t = 162.0 / 325;
        assertEquals(t, along.number("t"), 1e-15);
        assertArrayEquals(new double[] {1 - t, t}, along.vector("weights"), 1e-12);
        assertArrayEquals(new double[] {1 - t, 0, t}, r.explanation().vector("kd"), 1e-12);
    }

    private static double[] clamp(double[] c) {
        return new double[] {Math.max(0, Math.min(1, c[0])), Math.max(0, Math.min(1, c[1])),
            Math.max(0, Math.min(1, c[2]))};
    }

    private static double[] unit(double[] a) {
        return scale(a, 1 / length(a));
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double[] scale(double[] a, double s) {
        return new double[] {a[0] * s, a[1] * s, a[2] * s};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double length(double[] a) {
        return Math.sqrt(dot(a, a));
    }
}
