package simpview.tools.shapes;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Writes the project's generated SIMP shapes (cube, sphere, cylinder, cone,
 * pyramid, block letters) and .obj models (a torus with vertex normals, a
 * faceted crystal without) into a folder. Their output is committed under
 * simp/ and a test checks that regenerating gives the same bytes.
 *
 * <p>Usage: {@code java simpview.tools.shapes.ShapeGenerator [folder]} (default simp).
 */
public final class ShapeGenerator {

    private ShapeGenerator() {
    }

    /** File name to content, in a fixed order. */
    public static Map<String, String> shapes() {
        Map<String, String> files = new LinkedHashMap<>();
        files.put("cube.simp", Solids.cube());
        files.put("sphere.simp", Solids.sphere(24, 16));
        files.put("cylinder.simp", Solids.cylinder(24));
        files.put("cone.simp", Solids.cone(24));
        files.put("pyramid.simp", Solids.pyramid());
        files.put("letters.simp", BlockLetters.word("SIMP"));
        files.put("torus.obj", Models.torus(1, 0.4, 40, 20));
        files.put("crystal.obj", Models.crystal(6));
        return files;
    }

    /** Writes every shape into {@code folder}, creating it if needed. */
    public static void writeAll(Path folder) throws IOException {
        Files.createDirectories(folder);
        for (Map.Entry<String, String> e : shapes().entrySet()) {
            Files.write(folder.resolve(e.getKey()), e.getValue().getBytes(StandardCharsets.UTF_8));
        }
    }

    public static void main(String[] args) throws IOException {
        Path folder = Path.of(args.length > 0 ? args[0] : "simp");
        writeAll(folder);
        System.out.println("wrote " + shapes().keySet() + " to " + folder.toAbsolutePath().normalize());
    }
}
