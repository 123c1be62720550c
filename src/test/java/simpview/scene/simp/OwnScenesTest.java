package simpview.scene.simp;

import simpview.testing.DrawnScenes;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Vertex;
import simpview.tools.shapes.ShapeGenerator;
import java.util.HashSet;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

/** The project's own scenes under simp/: generated files are up to date, pages 4 and 5 do what SPEC asks. */
class OwnScenesTest {

    private static Path simpDir() {
        return Path.of(System.getProperty("simpview.projectDir", ".")).resolve("simp");
    }

    @Test
    void generatedShapesAreCommittedAsGenerated(@TempDir Path out) throws Exception {
        ShapeGenerator.writeAll(out);
        Map<String, String> shapes = ShapeGenerator.shapes();
        assertTrue(shapes.keySet().containsAll(List.of("cube.simp", "sphere.simp", "cone.simp", "letters.simp",
                "torus.obj", "crystal.obj")));
        for (String name : shapes.keySet()) {
            assertArrayEquals(Files.readAllBytes(out.resolve(name)), Files.readAllBytes(simpDir().resolve(name)),
                    name + " differs from a fresh run of ShapeGenerator: regenerate it");
        }
    }

    @Test
    void everyGeneratedFileUnderSimpIsOneTheGeneratorWrites() throws Exception {
        // A file under simp/ that says it was generated must still come out of the generator.
        Set<String> generated = new TreeSet<>();
        try (Stream<Path> files = Files.list(simpDir())) {
            for (Path f : (Iterable<Path>) files::iterator) {
                if (Files.readString(f).contains("written by simpview.tools.shapes.ShapeGenerator")) {
                    generated.add(f.getFileName().toString());
                }
            }
        }
        assertEquals(new TreeSet<>(ShapeGenerator.shapes().keySet()), generated);
    }

    @Test
    void theTorusHasItsOwnNormalsAndTheCrystalNone() throws Exception {
        List<String> torus = Files.readAllLines(simpDir().resolve("torus.obj"));
        long vertices = torus.stream().filter(l -> l.startsWith("v ")).count();
        assertEquals(vertices, torus.stream().filter(l -> l.startsWith("vn ")).count(), "a normal per vertex");
        assertTrue(torus.stream().filter(l -> l.startsWith("f ")).allMatch(l -> l.matches("f( \\d+//\\d+){4}")),
                "quads, every vertex with its normal");
        List<String> crystal = Files.readAllLines(simpDir().resolve("crystal.obj"));
        assertTrue(crystal.stream().noneMatch(l -> l.startsWith("vn") || l.contains("/")), "faceted: no normals");
        assertTrue(crystal.stream().anyMatch(l -> l.matches("f( \\d+){4}")), "quads on the sides");
    }

    @Test
    void theOwnLitScenesAreLitAndUseTheGeneratedModels() throws Exception {
        for (String name : List.of("lit-shading", "lit-corridor", "lit-lights")) {
            Path scene = simpDir().resolve(name + ".simp");
            assertTrue(DrawnScenes.isLit(scene), name);
            String text = Files.readString(scene);
            assertTrue(text.contains("camera ") && text.contains("obj \"") && text.contains("light "), name);
        }
        String shading = Files.readString(simpDir().resolve("lit-shading.simp"));
        assertTrue(shading.contains("\nflat\n") && shading.contains("\ngouraud\n") && shading.contains("\nphong\n"));
        assertTrue(Files.readString(simpDir().resolve("lit-corridor.simp")).contains("\ndepth "), "fog");
        String lights = Files.readString(simpDir().resolve("lit-lights.simp"));
        assertTrue(lights.indexOf("light ") < lights.indexOf("camera "), "a light before the camera");
    }

    @Test
    void ourCubeIsTheUnitCube() throws Exception {
        SimpReader reader = SimpReader.open(simpDir().resolve("cube.simp"));
        Command c = new Command();
        int polygons = 0;
        Set<String> corners = new HashSet<>();
        while (reader.next(c)) {
            assertEquals(Command.Kind.POLYGON, c.kind());
            polygons++;
            for (int k = 0; k < 3; k++) {
                corners.add(c.coordinate(k, 0) + "," + c.coordinate(k, 1) + "," + c.coordinate(k, 2));
            }
        }
        reader.close();
        assertEquals(12, polygons);
        assertEquals(8, corners.size(), "every corner of the unit cube and no other point: " + corners);
        assertTrue(corners.stream().allMatch(p -> p.matches("[01]\\.0,[01]\\.0,[01]\\.0")), corners.toString());
    }

    private static double[] depthRange(SceneFixture scene) {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (Vertex[] triangle : scene.filled) {
            for (Vertex v : triangle) {
                min = Math.min(min, v.z());
                max = Math.max(max, v.z());
            }
        }
        return new double[] {min, max};
    }

    @Test
    void page4BoxesSpanTheWholeDepthRangeFilled() throws Exception {
        SceneFixture scene = new SceneFixture(simpDir());
        scene.run("page4");
        assertTrue(scene.wire.isEmpty() && scene.lines.isEmpty(), "page 4 is filled polygons only");
        assertTrue(scene.filled.size() >= 5 * 12, "several boxes: " + scene.filled.size());
        double[] range = depthRange(scene);
        assertTrue(range[0] <= -199, "reaches the far plane: " + range[0]);
        assertTrue(range[1] >= -1, "reaches the near plane: " + range[1]);
        assertTrue(scene.warnings.isEmpty());
        String text = Files.readString(simpDir().resolve("page4.simp"));
        assertTrue(text.contains("file \"cube\"") && text.contains("rotate") && text.contains("scale"));
    }

    @Test
    void page5UsesFilesOfSeveralGeneratedShapes() throws Exception {
        SceneFixture scene = new SceneFixture(simpDir());
        scene.run("page5");
        assertTrue(scene.warnings.isEmpty());
        assertTrue(scene.filled.size() > 1000, "drew " + scene.filled.size());
        List<String> included = Files.readAllLines(simpDir().resolve("page5.simp")).stream()
                .map(String::trim).filter(l -> l.startsWith("file ")).distinct().collect(Collectors.toList());
        assertTrue(included.size() >= 3, "kinds of shape: " + included);
        assertTrue(included.contains("file \"sphere\"") && included.contains("file \"cone\""), included.toString());
    }
}
