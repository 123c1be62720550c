package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.scene.SceneException;

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
}
