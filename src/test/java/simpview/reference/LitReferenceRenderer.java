package simpview.reference;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A second, deliberately plain renderer of lit SIMP scenes (SPEC Part 2),
 * written from SPEC and sharing no code with simpview: lines split on
 * blanks, commas and parentheses, recursion for `file`, its own matrices,
 * clipper, rasterizer and lighting. It reads a scene and leaves the picture
 * in {@link #page()}.
 *
 * <p>A vertex on its way through the pipeline is a double[{@value #SIZE}]:
 * camera-space position (x, y, z), a colour (r, g, b) and a camera-space
 * normal (nx, ny, nz). The colour is what shows for unlit primitives, flat
 * and gouraud (already lit), and kd for phong, which lights every pixel.
 *
 * <p>Where SPEC leaves a reading open, this reference takes: a gouraud
 * vertex's lit colour is clamped to [0, 1] at the vertex, before it is
 * interpolated (SPEC's "Order": the lit colour is clamped, then fogged); a lit
 * point exactly at the eye (possible only for flat and gouraud, which light
 * before clipping) has no eye direction and so no specular term.
 */
final class LitReferenceRenderer {

    static final int R = 3;
    static final int NX = 6;
    static final int SIZE = 9;

    enum ShadingMode { FLAT, GOURAUD, PHONG }

    record Fog(double near, double far, double[] colour) {
    }

    private record WorldLight(double[] position, double[] intensity, double a, double b) {
    }

    private final RefRaster raster = new RefRaster();
    private final Deque<double[][]> stack = new ArrayDeque<>();
    private final List<WorldLight> lights = new ArrayList<>();
    /** Models read in this scene, so a page that draws one twice (pageI) reads it once. */
    private final Map<Path, RefObj> models = new HashMap<>();
    private double[][] ctm = RefMatrix.identity();
    private double[][] worldToCamera = RefMatrix.identity();
    private RefView view = RefView.parallel();
    private boolean wire;
    private double[] ambient = {0, 0, 0};
    private double[] surface = {1, 1, 1};
    private double ks = 0.3;
    private double exponent = 8;
    private Fog fog;
    private ShadingMode shading = ShadingMode.PHONG;

    static BufferedImage render(Path scene) throws IOException {
        LitReferenceRenderer renderer = new LitReferenceRenderer();
        renderer.run(scene);
        return renderer.page();
    }

    BufferedImage page() {
        return raster.page();
    }

    int[] panel() {
        return raster.panel;
    }

    void run(Path file) throws IOException {
        int number = 0;
        for (String raw : Files.readAllLines(file)) {
            number++;
            String line = raw.strip();
            if (!line.isEmpty() && !line.startsWith("#")) {
                try {
                    command(file, line);
                } catch (RuntimeException e) {
                    throw new IllegalArgumentException("reference: " + file + ":" + number + ": " + line + ": "
                            + e.getMessage(), e);
                }
            }
        }
    }

    private void command(Path file, String line) throws IOException {
        String[] tokens = RefObj.SEPARATORS.split(line);
        String word = tokens[0];
        switch (word) {
            case "{" -> stack.push(ctm);
            case "}" -> ctm = stack.pop();
            case "scale" -> ctm = RefMatrix.times(ctm, RefMatrix.scale(num(tokens, 1), num(tokens, 2), num(tokens, 3)));
            case "translate" -> ctm = RefMatrix.times(ctm,
                    RefMatrix.translate(num(tokens, 1), num(tokens, 2), num(tokens, 3)));
            case "rotate" -> ctm = RefMatrix.times(ctm, RefMatrix.rotate(tokens[1].charAt(0), num(tokens, 2)));
            case "wire" -> wire = true;
            case "filled" -> wire = false;
            case "flat" -> shading = ShadingMode.FLAT;
            case "gouraud" -> shading = ShadingMode.GOURAUD;
            case "phong" -> shading = ShadingMode.PHONG;
            case "ambient" -> ambient = numbers(tokens, 3);
            case "surface" -> surface(numbers(tokens, -1));
            case "depth" -> depth(numbers(tokens, 5));
            case "light" -> light(numbers(tokens, 5));
            case "camera" -> camera(numbers(tokens, 6));
            case "line", "polygon" -> simpPrimitive(word.equals("line") ? 2 : 3, numbers(tokens, -1));
            case "file" -> run(find(file, name(line, word), ".simp"));
            case "obj" -> obj(model(find(file, name(line, word), ".obj")));
            default -> throw new IllegalArgumentException("unknown command");
        }
    }

    private RefObj model(Path file) throws IOException {
        Path key = file.toAbsolutePath().normalize();
        RefObj model = models.get(key);
        if (model == null) {
            model = RefObj.read(file);
            models.put(key, model);
        }
        return model;
    }

    private static double num(String[] tokens, int i) {
        return Double.parseDouble(tokens[i]);
    }

    /** The numbers after the command word; count -1 takes any count. */
    private static double[] numbers(String[] tokens, int count) {
        double[] n = new double[tokens.length - 1];
        for (int i = 1; i < tokens.length; i++) {
            n[i - 1] = Double.parseDouble(tokens[i]);
        }
        if (count >= 0 && n.length != count) {
            throw new IllegalArgumentException("expected " + count + " numbers, found " + n.length);
        }
        return n;
    }

    private static String name(String line, String word) {
        return line.substring(word.length()).strip().replace("\"", "");
    }

    /** The folder of the including file, then the working directory. */
    static Path find(Path including, String name, String extension) {
        Path beside = including.resolveSibling(name + extension);
        if (Files.exists(beside)) {
            return beside;
        }
        Path working = Path.of(name + extension);
        if (Files.exists(working)) {
            return working;
        }
        throw new IllegalArgumentException("no " + beside + " and no " + working.toAbsolutePath());
    }

    private void surface(double[] n) {
        if (n.length != 3 && n.length != 5) {
            throw new IllegalArgumentException("surface takes 3 or 5 numbers");
        }
        surface = Arrays.copyOf(n, 3);
        if (n.length == 5) {
            ks = n[3];
            exponent = n[4];
        }
    }

    private void depth(double[] n) {
        fog = new Fog(n[0], n[1], new double[] {n[2], n[3], n[4]});
    }

    private void light(double[] n) {
        lights.add(new WorldLight(RefMatrix.point(ctm, new double[3]), new double[] {n[0], n[1], n[2]}, n[3], n[4]));
    }

    private void camera(double[] n) {
        worldToCamera = RefMatrix.inverse(ctm);
        if (worldToCamera == null) {
            throw new IllegalArgumentException("the CTM at camera cannot be inverted");
        }
        view = RefView.camera(n[0], n[1], n[2], n[3], n[4], n[5]);
    }

    private void simpPrimitive(int count, double[] n) {
        boolean coloured = n.length == 6 * count;
        if (!coloured && n.length != 3 * count) {
            throw new IllegalArgumentException("found " + n.length + " numbers");
        }
        int stride = coloured ? 6 : 3;
        List<double[]> points = new ArrayList<>();
        List<double[]> colours = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            points.add(Arrays.copyOfRange(n, stride * i, stride * i + 3));
            colours.add(coloured ? clamp(Arrays.copyOfRange(n, stride * i + 3, stride * i + 6)) : null);
        }
        List<double[]> normals = new ArrayList<>(Arrays.asList(new double[count][]));
        if (count == 2) {
            line(points, colours);
        } else {
            polygon(points, colours, normals);
        }
    }

    private void obj(RefObj model) {
        for (int[][] face : model.faces()) {
            List<double[]> points = new ArrayList<>();
            List<double[]> colours = new ArrayList<>();
            List<double[]> normals = new ArrayList<>();
            for (int[] ref : face) {
                points.add(model.positions().get(ref[0]));
                colours.add(model.colours().get(ref[0]));
                normals.add(ref[1] < 0 ? null : model.normals().get(ref[1]));
            }
            polygon(points, colours, normals);
        }
    }

    private static double[] clamp(double[] c) {
        return new double[] {clamp(c[0]), clamp(c[1]), clamp(c[2])};
    }

    private static double clamp(double c) {
        return Math.max(0, Math.min(1, c));
    }

    private double[][] objectToCamera() {
        return RefMatrix.times(worldToCamera, ctm);
    }

    /** Lights in camera space, as they stand at this command. */
    private RefLighting lighting() {
        List<RefLighting.Light> inCamera = new ArrayList<>();
        for (WorldLight light : lights) {
            inCamera.add(new RefLighting.Light(RefMatrix.point(worldToCamera, light.position()), light.intensity(),
                    light.a(), light.b()));
        }
        return new RefLighting(ambient, ks, exponent, inCamera, view.perspective());
    }

    private void line(List<double[]> points, List<double[]> colours) {
        double[][] m = objectToCamera();
        double[][] v = new double[2][];
        for (int i = 0; i < 2; i++) {
            v[i] = vertex(RefMatrix.point(m, points.get(i)), kd(colours.get(i)), new double[3]);
        }
        if (RefClipper.culled(view, List.of(v))) {
            return;
        }
        double[][] clipped = RefClipper.line(view, v[0], v[1]);
        if (clipped != null) {
            raster.line(view, clipped[0], clipped[1], unlit(fog));
        }
    }

    private double[] kd(double[] own) {
        return own != null ? own : surface.clone();
    }

    private static double[] vertex(double[] position, double[] colour, double[] normal) {
        double[] v = new double[SIZE];
        System.arraycopy(position, 0, v, 0, 3);
        System.arraycopy(colour, 0, v, R, 3);
        System.arraycopy(normal, 0, v, NX, 3);
        return v;
    }

    /** One simp triangle or obj face: lit as its shading says, clipped, then filled as a fan or outlined. */
    private void polygon(List<double[]> points, List<double[]> colours, List<double[]> ownNormals) {
        double[][] m = objectToCamera();
        double[][] normalMatrix = RefMatrix.normalMatrix(m);
        int n = points.size();
        double[][] p = new double[n][];
        double[][] kd = new double[n][];
        double[][] normal = new double[n][];
        for (int i = 0; i < n; i++) {
            p[i] = RefMatrix.point(m, points.get(i));
            kd[i] = kd(colours.get(i));
        }
        double[] face = RefMatrix.unit(RefMatrix.cross(RefMatrix.minus(p[1], p[0]), RefMatrix.minus(p[2], p[0])));
        boolean allOwn = true;
        for (int i = 0; i < n; i++) {
            double[] own = ownNormals.get(i);
            allOwn &= own != null;
            normal[i] = own != null ? RefMatrix.unit(RefMatrix.times3(normalMatrix, own)) : face;
        }
        List<double[]> vertices = new ArrayList<>();
        RefLighting lighting = lighting();
        double[] flat = wire || shading != ShadingMode.FLAT ? null : flatColour(lighting, p, kd, normal, allOwn, face);
        for (int i = 0; i < n; i++) {
            double[] colour = wire || shading == ShadingMode.PHONG ? kd[i]
                    : shading == ShadingMode.FLAT ? flat : lighting.colour(p[i], normal[i], kd[i]);
            vertices.add(vertex(p[i], colour, wire ? new double[3] : normal[i]));
        }
        if (RefClipper.culled(view, vertices)) {
            return;
        }
        List<double[]> clipped = RefClipper.polygon(view, vertices);
        RefRaster.Fragment fragment = wire || shading != ShadingMode.PHONG ? unlit(fog) : phong(lighting, fog);
        if (wire) {
            for (int i = 0; clipped.size() >= 2 && i < clipped.size(); i++) {
                raster.line(view, clipped.get(i), clipped.get((i + 1) % clipped.size()), fragment);
            }
        } else {
            for (int i = 1; i + 1 < clipped.size(); i++) {
                raster.triangle(view, clipped.get(0), clipped.get(i), clipped.get(i + 1), fragment);
            }
        }
    }

    /** Lit once at the centroid, with the mean kd and the unit mean of the own normals (when all have one). */
    private static double[] flatColour(RefLighting lighting, double[][] p, double[][] kd, double[][] normal,
            boolean allOwn, double[] face) {
        double[] centroid = new double[3];
        double[] meanKd = new double[3];
        double[] meanNormal = new double[3];
        for (int i = 0; i < p.length; i++) {
            for (int k = 0; k < 3; k++) {
                centroid[k] += p[i][k] / p.length;
                meanKd[k] += kd[i][k] / p.length;
                meanNormal[k] += normal[i][k] / p.length;
            }
        }
        return lighting.colour(centroid, allOwn ? meanNormal : face, meanKd);
    }

    /** The colour slots as they are (clamped), then fog on z. */
    static RefRaster.Fragment unlit(Fog fog) {
        double[] c = new double[3];
        return attributes -> {
            for (int k = 0; k < 3; k++) {
                c[k] = clamp(attributes[R + k]);
            }
            return pack(fogged(fog, attributes[2], c));
        };
    }

    /** Lit at the pixel: P, N (made unit again) and kd interpolated. */
    private static RefRaster.Fragment phong(RefLighting lighting, Fog fog) {
        double[] p = new double[3];
        double[] kd = new double[3];
        double[] n = new double[3];
        return attributes -> {
            System.arraycopy(attributes, 0, p, 0, 3);
            System.arraycopy(attributes, R, kd, 0, 3);
            System.arraycopy(attributes, NX, n, 0, 3);
            return pack(fogged(fog, attributes[2], lighting.colour(p, n, kd)));
        };
    }

    /** {@code z >= near} keeps c, {@code z <= far} gives the fog colour, lerp between. */
    static double[] fogged(Fog fog, double z, double[] c) {
        if (fog == null || z >= fog.near()) {
            return c;
        }
        if (z <= fog.far()) {
            return fog.colour();
        }
        double t = (z - fog.far()) / (fog.near() - fog.far());
        return new double[] {t * c[0] + (1 - t) * fog.colour()[0], t * c[1] + (1 - t) * fog.colour()[1],
            t * c[2] + (1 - t) * fog.colour()[2]};
    }

    private static int pack(double[] c) {
        int rgb = 0;
        for (int k = 0; k < 3; k++) {
            rgb = rgb << 8 | (int) Math.max(0, Math.min(255, Math.round(c[k] * 255)));
        }
        return rgb;
    }
}
