package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The reference's .obj reader on the forms SPEC lists. */
class RefObjTest {

    @TempDir
    Path dir;

    private RefObj read(String text) throws IOException {
        Path file = dir.resolve("model.obj");
        Files.writeString(file, text);
        return RefObj.read(file);
    }

    @Test
    void everyVertexAndFaceForm() throws IOException {
        RefObj obj = read("""
                # comment
                mtllib x.mtl
                v 1 2 3
                v 2 4 6 2
                V 0 1 0 0.5 0.25 2
                v 4 0 0 4 0 0 1
                vt 0.5 0.5
                vn 0 0 2
                vn 1 0 0
                g group
                s off
                f 1 2 3
                f 1/1 2/1 3/1 4/1
                f 1//2 2//1 -1//-1
                F -4/1/-2 -3/1/-1 -2/1/1
                usemtl red
                """);
        assertEquals(4, obj.positions().size());
        assertArrayEquals(new double[] {1, 2, 3}, obj.positions().get(1), "w divides");
        assertArrayEquals(new double[] {1, 0, 0}, obj.positions().get(3));
        assertNull(obj.colours().get(0));
        assertArrayEquals(new double[] {0.5, 0.25, 1}, obj.colours().get(2), "clamped to [0, 1]");
        assertArrayEquals(new double[] {0, 0, 1}, obj.colours().get(3));
        assertEquals(4, obj.faces().size());
        assertEquals(4, obj.faces().get(1).length);
        assertArrayEquals(new int[][] {{0, 1}, {1, 0}, {3, 1}}, obj.faces().get(2));
        assertArrayEquals(new int[][] {{0, 0}, {1, 1}, {2, 0}}, obj.faces().get(3));
        assertEquals(-1, obj.faces().get(0)[0][1], "no normal");
    }

    @Test
    void badInputIsAnErrorNamingTheLine() {
        String[] bad = {"v 1 2", "v 1 2 3 0", "v 1 2 3\nf 1 2", "v 1 2 3\nf 1 2 0", "v 1 2 3\nf 1 1 2",
            "v 1 2 3\nf -2 1 1", "v 1 x 3"};
        for (String text : bad) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> read(text), text);
            assertTrue(e.getMessage().contains("model.obj:"), e.getMessage());
        }
    }

    @Test
    void theGeneratedModelsRead() throws IOException {
        assertEquals(7 * 11, read(RandomLitScenes.sphere(7, 11)).faces().size());
        RefObj gem = read(RandomLitScenes.gem());
        assertEquals(6, gem.faces().size());
        assertArrayEquals(new double[] {0, 1.5, 0}, gem.positions().get(5), 1e-12);
        assertEquals(5, read(RandomLitScenes.strip()).faces().size());
    }
}
