package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.scene.SceneException;
import simpview.testing.CourseFiles;

/**
 * The course's own .obj files (read from ../shared, never copied here) read
 * without error, with the counts and coordinates a plain String.split reading
 * of them gives, and replayed from a model exactly as streamed.
 */
class CourseObjFilesTest {

    /** The course's folders sit beside course-simp (-Dsimpview.courseSimp), in ../shared. */
    static Path courseFile(String name) {
        Path courseSimp = Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
        Path file = courseSimp.resolveSibling(name);
        if (!Files.isRegularFile(file)) {
            if ("true".equals(System.getenv("CI"))) {
                fail("the course's file " + file + " is missing, and under CI=true it must be there");
            }
            Assumptions.abort("the course's file " + file + " is not here (../shared is not beside the project)");
        }
        return file;
    }

    /** What the file holds, counted and summed without the reader under test. */
    record Expected(int vertices, int normals, int faces, long references, double sum) {
    }

    /** The sum, in file order, of x + 2y + 3z + 5nx over every reference of every face. */
    static Expected splitCount(Path file) throws IOException {
        List<double[]> v = new ArrayList<>();
        List<double[]> vn = new ArrayList<>();
        int faces = 0;
        long references = 0;
        double sum = 0;
        for (String line : Files.readAllLines(file)) {
            String[] w = line.trim().split("\\s+");
            switch (w[0].toLowerCase(Locale.ROOT)) {
                case "v" -> v.add(new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2]),
                    Double.parseDouble(w[3])});
                case "vn" -> vn.add(new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2]),
                    Double.parseDouble(w[3])});
                case "f" -> {
                    faces++;
                    for (int k = 1; k < w.length; k++) {
                        String[] parts = w[k].split("/");
                        double[] p = v.get(Integer.parseInt(parts[0]) - 1);
                        sum += p[0] + 2 * p[1] + 3 * p[2];
                        if (parts.length == 3) {
                            sum += 5 * vn.get(Integer.parseInt(parts[2]) - 1)[0];
                        }
                        references++;
                    }
                }
                default -> { }
            }
        }
        return new Expected(v.size(), vn.size(), faces, references, sum);
    }

    @ParameterizedTest
    @ValueSource(strings = {"course-simp-a3/dummy.obj", "course-simp-a3/bowling.obj", "course-simp-a4/cylinder.obj",
        "course-simp-a4/octohedron.obj", "course-simp-a4/dummy.obj", "course-simp-a4/bowling.obj"})
    void readsAsAPlainSplitReadsIt(String name) throws IOException, SceneException {
        Path file = courseFile(name);
        Expected expected = splitCount(file);
        long[] references = {0};
        double[] sum = {0};
        ObjCounts counts = ObjReader.stream(file, face -> {
            assertTrue(face.size() >= 3);
            for (int k = 0; k < face.size(); k++) {
                sum[0] += face.x(k) + 2 * face.y(k) + 3 * face.z(k);
                if (face.hasNormal(k)) {
                    sum[0] += 5 * face.nx(k);
                }
                references[0]++;
            }
        });
        assertEquals(new ObjCounts(expected.vertices(), expected.normals(), expected.faces()), counts);
        assertEquals(expected.references(), references[0], "references");
        assertEquals(expected.sum(), sum[0], 0.0, "sum of coordinates over every reference");
        assertTrue(expected.faces() > 0);
    }

    @ParameterizedTest
    @ValueSource(strings = {"course-simp-a3/dummy.obj", "course-simp-a3/bowling.obj", "course-simp-a4/cylinder.obj",
        "course-simp-a4/octohedron.obj"})
    void replayingTheModelGivesWhatStreamingGives(String name) throws SceneException {
        Path file = courseFile(name);
        CollectedFaces streamed = new CollectedFaces();
        ObjCounts counts = ObjReader.stream(file, streamed);
        ObjModel model = ObjModel.read(file);
        CollectedFaces replayed = new CollectedFaces();
        model.replay(replayed);
        assertEquals(counts, model.counts());
        assertEquals(streamed.faces.size(), replayed.faces.size());
        assertEquals(streamed.faces, replayed.faces);
        CollectedFaces again = new CollectedFaces();
        model.replay(again);
        assertEquals(streamed.faces, again.faces, "a second replay");
    }

    @ParameterizedTest
    @ValueSource(strings = {"course-simp-a3/dummy.obj", "course-simp-a4/cylinder.obj"})
    void theCourseFilesNameANormalAtEveryReference(String name) throws SceneException {
        int[] without = {0};
        ObjReader.stream(courseFile(name), face -> {
            for (int k = 0; k < face.size(); k++) {
                without[0] += face.hasNormal(k) ? 0 : 1;
            }
        });
        assertEquals(0, without[0]);
    }

    /** An {@code obj} command of a scene, and the model's name: {@code obj "name"} or {@code obj name}. */
    private static final Pattern OBJ = Pattern.compile("(?m)^\\s*obj\\s+\"?([^\"\\s]+)");

    /**
     * No scene of the course's lit folders says its model is inside out: that warning is the model reader's,
     * whatever the scene does with the model, so each model the scenes of course-simp-a3 and course-simp-a4 name
     * is read (once: the same bytes in both folders are read once) and none gives it.
     */
    @Test
    void noModelTheCourseScenesReadIsSaidToBeInsideOut() throws IOException, SceneException {
        List<Path> models = new ArrayList<>();
        for (String folder : List.of("course-simp-a3", "course-simp-a4")) {
            Path dir = CourseFiles.require(folder);
            List<Path> scenes;
            try (Stream<Path> files = Files.list(dir)) {
                scenes = files.filter(f -> f.toString().endsWith(".simp")).sorted().collect(Collectors.toList());
            }
            for (Path scene : scenes) {
                Matcher m = OBJ.matcher(Files.readString(scene));
                while (m.find()) {
                    Path model = dir.resolve(m.group(1) + ".obj");
                    if (!models.contains(model)) {
                        models.add(model);
                    }
                }
            }
        }
        List<Path> read = new ArrayList<>();
        for (Path model : models) {
            if (read.stream().anyMatch(r -> sameBytes(r, model))) {
                continue;
            }
            read.add(model);
            List<String> insideOut = ObjReader.stream(model, face -> { }).warnings().stream()
                    .filter(w -> w.contains("inside out")).collect(Collectors.toList());
            assertEquals(List.of(), insideOut, model.toString());
        }
        assertEquals(List.of("bowling.obj", "cylinder.obj", "dummy.obj", "octohedron.obj"), read.stream()
                .map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList()), "the models read");
    }

    /**
     * The course's dummy.obj holds ten quads whose fan from the first vertex is not their outline, each twisted
     * out of its plane; the reader names only flat ones for their fan, so none of the course's models is named.
     */
    @Test
    void noCourseModelIsNamedForItsFan() throws SceneException {
        for (String name : List.of("course-simp-a3/dummy.obj", "course-simp-a3/bowling.obj",
                "course-simp-a4/cylinder.obj", "course-simp-a4/octohedron.obj")) {
            Path model = courseFile(name);
            List<String> named = ObjReader.stream(model, face -> { }).warnings().stream()
                    .filter(w -> w.contains("is not convex")).collect(Collectors.toList());
            assertEquals(List.of(), named, name);
        }
    }

    private static boolean sameBytes(Path a, Path b) {
        try {
            return Files.mismatch(a, b) == -1;
        } catch (IOException e) {
            throw new AssertionError(a + " or " + b + " cannot be read", e);
        }
    }

    /**
     * The course's own cylinder with its normals negated, and its octahedron with each face's vertices reversed
     * (made from them in memory), are each said to be inside out, naming the face the warning gives as example.
     */
    @Test
    void theCourseModelsTurnedInsideOutAreSaidToBe() throws IOException, SceneException {
        StringBuilder cylinder = new StringBuilder();
        for (String line : Files.readAllLines(courseFile("course-simp-a4/cylinder.obj"))) {
            String[] w = line.trim().split("\\s+");
            cylinder.append(w[0].equals("vn") ? "vn " + -Double.parseDouble(w[1]) + " " + -Double.parseDouble(w[2])
                    + " " + -Double.parseDouble(w[3]) : line).append('\n');
        }
        StringBuilder octahedron = new StringBuilder();
        for (String line : Files.readAllLines(courseFile("course-simp-a4/octohedron.obj"))) {
            String[] w = line.trim().split("\\s+");
            octahedron.append(w[0].equals("f") ? "f " + w[3] + " " + w[2] + " " + w[1] : line).append('\n');
        }
        assertEquals(List.of("cylinder.obj:25"), insideOut("cylinder.obj", cylinder.toString()));
        assertEquals(List.of("octohedron.obj:8"), insideOut("octohedron.obj", octahedron.toString()));
    }

    /** The places the inside-out warnings of the model {@code text} name. */
    private static List<String> insideOut(String name, String text) throws SceneException {
        return ObjReader.stream(Path.of(name), text.getBytes(StandardCharsets.UTF_8), face -> { })
                .warnings().stream().filter(w -> w.contains(": the model is inside out"))
                .map(w -> w.substring(0, w.indexOf(": the model is inside out"))).collect(Collectors.toList());
    }
}
