package simpview.reference;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

/**
 * Random lit scenes written to a folder, so that simpview and the reference
 * read the very same files: a random camera (sometimes none, sometimes inside
 * a box, non-square windows), triangles through the eye plane, random lights
 * before and after the camera, surfaces of 3 and 5 numbers, every shading
 * mode, wire and filled, lines, vertex colours, fog, and .obj models with and
 * without normals (w, colours, every face reference form, negative indices).
 * Every scene is valid by SPEC.
 */
public final class RandomLitScenes {

    private final Random random;
    private final List<String> lines = new ArrayList<>();
    /** The camera's own placement, repeated to put things near the eye. */
    private String cameraPlacement = "";

    private RandomLitScenes(long seed) {
        random = new Random(seed);
    }

    /** Writes randomN.simp (and the cube and models it uses) into dir; returns the scene. */
    public static Path write(Path dir, long seed) throws IOException {
        writeParts(dir);
        Path scene = dir.resolve("random" + seed + ".simp");
        Files.writeString(scene, new RandomLitScenes(seed).scene());
        return scene;
    }

    static void writeParts(Path dir) throws IOException {
        Files.writeString(dir.resolve("unitbox.simp"), cube());
        Files.writeString(dir.resolve("ball.obj"), sphere(7, 11));
        Files.writeString(dir.resolve("gem.obj"), gem());
        Files.writeString(dir.resolve("strip.obj"), strip());
    }

    private String scene() {
        if (chance(0.7)) {
            add("ambient %s", colour(0, 0.6));
        }
        for (int i = random.nextInt(3); i > 0; i--) {
            light();
        }
        boolean camera = chance(0.85);
        if (camera) {
            camera();
        }
        if (chance(0.5)) {
            double near = uniform(-60, -5);
            add("depth %s %s (%s)", f(near), f(near - uniform(20, 200)), colour(0, 1));
        }
        for (int i = random.nextInt(3); i > 0; i--) {
            light();
        }
        if (camera && chance(0.3)) {
            // The eye inside a box: filled, it hides the rest; wire, its outline crosses the eye plane.
            add(chance(0.5) ? "wire" : "filled");
            add("{");
            add(cameraPlacement);
            add("translate -20 -20 -20");
            add("scale 40 40 40");
            add("file \"unitbox\"");
            add("}");
        }
        for (int group = 0; group < 10; group++) {
            group(camera);
        }
        return String.join("\n", lines) + "\n";
    }

    private void camera() {
        double xlow = uniform(-1.5, -0.2);
        double ylow = uniform(-1.5, -0.2);
        double xhigh = chance(0.3) ? uniform(0.2, 1.5) : -xlow;
        double yhigh = chance(0.3) ? uniform(0.2, 1.5) : -ylow;
        double hither = -uniform(0.02, 3);
        cameraPlacement = String.format(Locale.ROOT, "translate %s %s %s\nrotate Y %s\nrotate X %s",
                f(uniform(-40, 40)), f(uniform(-40, 40)), f(uniform(-60, 40)), f(uniform(-60, 60)),
                f(uniform(-40, 40)));
        add("{");
        add(cameraPlacement);
        add("camera %s %s %s %s %s %s", f(xlow), f(ylow), f(xhigh), f(yhigh), f(hither), f(hither - uniform(60, 400)));
        add("}");
    }

    private void light() {
        add("{");
        add("translate %s %s %s", f(uniform(-80, 80)), f(uniform(-80, 80)), f(uniform(-150, 30)));
        add("light %s %s %s", colour(0, 1.3), f(uniform(0.3, 1.5)), f(chance(0.5) ? 0 : uniform(0, 0.05)));
        add("}");
    }

    private void group(boolean camera) {
        add(chance(0.25) ? "wire" : "filled");
        add(List.of("flat", "gouraud", "phong").get(random.nextInt(3)));
        if (chance(0.5)) {
            add("surface %s", colour(0.1, 1));
        } else {
            add("surface %s %s %s", colour(0.1, 1), f(uniform(0, 1)), f(List.of(0.0, 1.0, 8.0, 64.0).get(random.nextInt(4))));
        }
        add("{");
        boolean nearEye = camera && chance(0.25);
        if (nearEye) {
            add(cameraPlacement);
        } else {
            add("translate %s %s %s", f(uniform(-90, 90)), f(uniform(-90, 90)), f(uniform(-190, -10)));
        }
        add("rotate %s %s", "XYZ".charAt(random.nextInt(3)), f(uniform(-180, 180)));
        add("rotate %s %s", "XYZ".charAt(random.nextInt(3)), f(uniform(-180, 180)));
        double size = nearEye ? uniform(2, 10) : uniform(5, 45);
        add("scale %s %s %s", f(size * uniform(0.5, 1.5)), f(size * uniform(0.5, 1.5)), f(size * uniform(0.5, 1.5)));
        shape();
        add("}");
    }

    private void shape() {
        switch (random.nextInt(6)) {
            case 0 -> add("file \"unitbox\"");
            case 1 -> add("obj \"ball\"");
            case 2 -> add(chance(0.5) ? "obj \"gem\"" : "obj gem");
            case 3 -> add("obj \"strip\"");
            case 4 -> {
                for (int i = 0; i < 3; i++) {
                    add(chance(0.5) ? "polygon %s %s %s" : "polygon %s, %s, %s", point(false), point(false),
                            point(false));
                }
                add("polygon %s %s %s", point(true), point(true), point(true));
            }
            default -> {
                add("line %s %s", point(false), point(false));
                add("line %s %s", point(true), point(true));
            }
        }
    }

    /** A point in [-1.5, 1.5]^3, with its own colour written one of the course's ways. */
    private String point(boolean coloured) {
        String xyz = f(uniform(-1.5, 1.5)) + ", " + f(uniform(-1.5, 1.5)) + ", " + f(uniform(-1.5, 1.5));
        if (!coloured) {
            return "(" + xyz + ")";
        }
        return chance(0.5) ? "(" + xyz + ", " + colour(0, 1) + ")" : "(" + xyz + ", (" + colour(0, 1) + "))";
    }

    private String colour(double lo, double hi) {
        return f(uniform(lo, hi)) + " " + f(uniform(lo, hi)) + " " + f(uniform(lo, hi));
    }

    private void add(String format, Object... args) {
        lines.add(String.format(Locale.ROOT, format, args));
    }

    private boolean chance(double p) {
        return random.nextDouble() < p;
    }

    private double uniform(double lo, double hi) {
        return lo + random.nextDouble() * (hi - lo);
    }

    private static String f(double v) {
        return String.format(Locale.ROOT, "%.4f", v);
    }

    /** The unit cube [0,1]^3 as 12 triangles, each turned to be counter-clockwise seen from outside. */
    static String cube() {
        int[][] faces = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
        StringBuilder out = new StringBuilder("# the unit cube\n");
        for (int[] q : faces) {
            if (!outward(q)) {
                q = new int[] {q[3], q[2], q[1], q[0]};
            }
            out.append("polygon ").append(corner(q[0])).append(corner(q[1])).append(corner(q[2])).append('\n');
            out.append("polygon ").append(corner(q[0])).append(corner(q[2])).append(corner(q[3])).append('\n');
        }
        return out.toString();
    }

    private static boolean outward(int[] q) {
        double[] a = xyz(q[0]);
        double[] normal = RefMatrix.cross(RefMatrix.minus(xyz(q[1]), a), RefMatrix.minus(xyz(q[2]), a));
        double[] centre = new double[3];
        for (int corner : q) {
            for (int k = 0; k < 3; k++) {
                centre[k] += xyz(corner)[k] / 4 - 0.125;
            }
        }
        return RefMatrix.dot(normal, centre) > 0;
    }

    private static double[] xyz(int i) {
        return new double[] {i >> 2 & 1, i >> 1 & 1, i & 1};
    }

    /** Corner i of the unit cube: bit 0 is z, bit 1 is y, bit 2 is x. */
    private static String corner(int i) {
        return String.format(Locale.ROOT, "(%d, %d, %d) ", i >> 2 & 1, i >> 1 & 1, i & 1);
    }

    /** A unit sphere of quads with vertex normals, in the v//vn and v/vt/vn forms, some with negative indices. */
    static String sphere(int stacks, int slices) {
        StringBuilder out = new StringBuilder("# a ball\nmtllib none.mtl\no ball\n");
        for (int i = 0; i <= stacks; i++) {
            for (int j = 0; j < slices; j++) {
                double theta = Math.PI * i / stacks;
                double phi = 2 * Math.PI * j / slices;
                double x = Math.sin(theta) * Math.cos(phi);
                double y = Math.cos(theta);
                double z = -Math.sin(theta) * Math.sin(phi);
                out.append(String.format(Locale.ROOT, "v %.6f %.6f %.6f%n", x, y, z));
                out.append(String.format(Locale.ROOT, "vn %.6f %.6f %.6f%n", 2 * x, 2 * y, 2 * z));
            }
        }
        out.append("vt 0 0\ns 1\ng band\n");
        int total = (stacks + 1) * slices;
        for (int i = 0; i < stacks; i++) {
            for (int j = 0; j < slices; j++) {
                int a = i * slices + j + 1;
                int b = i * slices + (j + 1) % slices + 1;
                int c = a + slices;
                int d = b + slices;
                int[] face = {a, c, d, b};
                out.append('f');
                for (int k = 0; k < 4; k++) {
                    int v = (i + j) % 3 == 0 ? face[k] - total - 1 : face[k];
                    out.append(' ').append(i % 2 == 0 ? v + "//" + v : v + "/1/" + v);
                }
                out.append('\n');
            }
        }
        return out.toString();
    }

    /** A pyramid on a pentagon, no normals: w != 1 on some vertices, colours on some, a five-vertex face. */
    static String gem() {
        StringBuilder out = new StringBuilder("# a gem\n");
        for (int k = 0; k < 5; k++) {
            double a = 2 * Math.PI * k / 5;
            double x = Math.cos(a);
            double z = -Math.sin(a);
            switch (k % 3) {
                case 0 -> out.append(String.format(Locale.ROOT, "v %.6f 0 %.6f%n", x, z));
                case 1 -> out.append(String.format(Locale.ROOT, "v %.6f 0 %.6f 2%n", 2 * x, 2 * z));
                default -> out.append(String.format(Locale.ROOT, "v %.6f 0 %.6f 0.9 0.2 0.1%n", x, z));
            }
        }
        out.append("V 0 0.75 0 0.5 0.1 0.8 0.4\n");
        out.append("f 5 4 3 2 1\n");
        for (int k = 0; k < 5; k++) {
            out.append(String.format(Locale.ROOT, "f %d/%d %d %d%n", k + 1, k + 1, (k + 1) % 5 + 1, 6));
        }
        return out.toString();
    }

    /** Quads made as the handout does, v and vn interleaved and referenced with negative indices. */
    static String strip() {
        StringBuilder out = new StringBuilder("# a bent strip\n");
        for (int k = 0; k < 6; k++) {
            double x = k * 0.4 - 1;
            double z = 0.3 * Math.sin(k);
            out.append(String.format(Locale.ROOT, "v %.4f -1 %.4f%nvn %.4f 0 1%n", x, z, -0.3 * Math.cos(k)));
            out.append(String.format(Locale.ROOT, "v %.4f 1 %.4f%nvn %.4f 0.2 1%n", x, z, -0.3 * Math.cos(k)));
            if (k > 0) {
                out.append("f -4//-4 -2//-2 -1//-1 -3//-3\n");
            }
        }
        return out.toString();
    }
}
