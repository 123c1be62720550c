package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.scene.obj.CollectedFaces.at;
import static simpview.scene.obj.CollectedFaces.coloured;
import static simpview.scene.obj.CollectedFaces.withNormal;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.scene.SceneException;
import simpview.scene.obj.CollectedFaces.Corner;
import simpview.scene.obj.CollectedFaces.Face;

/** Every form of the .obj subset, read from text in memory; each also replayed from a model, which must agree. */
class ObjReaderTest {

    static final Path NAME = Path.of("model.obj");
    private static final String TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

    static List<Face> read(String text) throws SceneException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        CollectedFaces streamed = new CollectedFaces();
        ObjReader.stream(NAME, bytes, streamed);
        CollectedFaces replayed = new CollectedFaces();
        ObjModel.of(NAME, bytes).replay(replayed);
        assertEquals(streamed.faces, replayed.faces, "replaying the model differs from streaming the file");
        return streamed.faces;
    }

    static List<Corner> onlyFace(String text) throws SceneException {
        List<Face> faces = read(text);
        assertEquals(1, faces.size(), "faces");
        return faces.get(0).corners();
    }

    // ---- vertices --------------------------------------------------------------------------------

    @Test
    void threeNumbersAreAPoint() throws SceneException {
        assertEquals(List.of(at(1.5, -2, 3e2, 0), at(4, 5, 6, 1), at(-.25, 0, 7, 2)),
                onlyFace("v 1.5 -2 3e2\nv 4 5 6\nv -.25 0 7\nf 1 2 3\n"));
    }

    /**
     * A byte order mark (Windows' Notepad saves one) is not part of the first
     * line: before it was skipped, that line's vertex was read as an unknown
     * word and left out, so every index after it named the next vertex.
     */
    @Test
    void aByteOrderMarkIsNotPartOfTheFirstVertex() throws SceneException {
        assertEquals(List.of(at(0, 0, 0, 0), at(1, 0, 0, 1), at(0, 1, 0, 2)),
                onlyFace("\uFEFFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    }

    @Test
    void wDividesThePoint() throws SceneException {
        assertEquals(List.of(at(1, 2, 3, 0), at(-1, -2, -3, 1), at(10, 20, 30, 2)),
                onlyFace("v 2 4 6 2\nv 1 2 3 -1\nv 1 2 3 0.1\nf 1 2 3\n").stream()
                        .map(ObjReaderTest::rounded).toList());
    }

    private static Corner rounded(Corner c) {
        return at(Math.rint(c.x() * 1e9) / 1e9, Math.rint(c.y() * 1e9) / 1e9, Math.rint(c.z() * 1e9) / 1e9,
                c.vertex());
    }

    @Test
    void aWOfOneLeavesThePointExactly() throws SceneException {
        assertEquals(at(0.1, 0.7, 1e-300, 0), onlyFace("v 0.1 0.7 1e-300 1\nv 1 0 0\nv 0 1 0\nf 1 2 3").get(0));
    }

    @Test
    void sixNumbersAreAPointAndAColourAsWritten() throws SceneException {
        assertEquals(List.of(coloured(1, 2, 3, 0.5, 0.25, 1, 0), coloured(0, 0, 0, 1.5, -0.5, 2, 1), at(9, 9, 9, 2)),
                onlyFace("v 1 2 3 0.5 0.25 1\nv 0 0 0 1.5 -0.5 2\nv 9 9 9\nf 1 2 3\n"));
    }

    @Test
    void sevenNumbersAreAPointWithWAndAColour() throws SceneException {
        assertEquals(List.of(at(0, 0, 0, 0), coloured(1, 2, 3, 0.5, 0.25, 1.5, 1), at(0, 1, 0, 2)),
                onlyFace("v 0 0 0\nv 2 4 6 2 0.5 0.25 1.5\nv 0 1 0\nf 1 2 3\n"));
    }

    @Test
    void aColourlessVertexAfterAColouredOneHasNoColour() throws SceneException {
        List<Corner> face = onlyFace("v 0 0 0 1 1 1\nv 1 0 0\nv 0 1 0 0 0 0\nf 1 2 3\n");
        assertEquals(List.of(true, false, true), face.stream().map(Corner::colored).toList());
        assertTrue(Double.isNaN(face.get(1).r()));
    }

    // ---- normals and references ------------------------------------------------------------------

    @Test
    void normalsAreKeptAsWrittenNotMadeUnit() throws SceneException {
        List<Corner> face = onlyFace(TRIANGLE + "vn 0 0 2\nvn 3 4 0\nf 1//1 2//2 3//1\n");
        assertEquals(List.of(withNormal(at(0, 0, 0, 0), 0, 0, 2, 0), withNormal(at(1, 0, 0, 1), 3, 4, 0, 1),
                withNormal(at(0, 1, 0, 2), 0, 0, 2, 0)), face);
    }

    @Test
    void everyReferenceFormNamesTheSameVertex() throws SceneException {
        String model = TRIANGLE + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                + "f 1 2 3\nf 1/1 2/2 3/3\nf 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/3/1\nf 1 2/3 3//1\n";
        List<Face> faces = read(model);
        assertEquals(5, faces.size());
        List<Corner> plain = List.of(at(0, 0, 0, 0), at(1, 0, 0, 1), at(0, 1, 0, 2));
        List<Corner> normal = plain.stream().map(c -> withNormal(c, 0, 0, 1, 0)).toList();
        assertEquals(plain, faces.get(0).corners(), "v");
        assertEquals(plain, faces.get(1).corners(), "v/vt");
        assertEquals(normal, faces.get(2).corners(), "v//vn");
        assertEquals(normal, faces.get(3).corners(), "v/vt/vn");
        assertEquals(List.of(plain.get(0), plain.get(1), normal.get(2)), faces.get(4).corners(), "mixed");
        assertEquals(List.of(8, 9, 10, 11, 12), faces.stream().map(Face::line).toList());
    }

    @Test
    void negativeIndicesCountBackFromTheLastDefined() throws SceneException {
        String model = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nvn 0 1 0\n"
                + "f -3 -2 -1\n"
                + "v 5 5 5\nvn 0 0 1\nf -1//-1 -2//-2 -4//-3\n";
        List<Face> faces = read(model);
        assertEquals(List.of(at(0, 0, 0, 0), at(1, 0, 0, 1), at(0, 1, 0, 2)), faces.get(0).corners());
        assertEquals(List.of(withNormal(at(5, 5, 5, 3), 0, 0, 1, 2), withNormal(at(0, 1, 0, 2), 0, 1, 0, 1),
                withNormal(at(0, 0, 0, 0), 1, 0, 0, 0)), faces.get(1).corners());
    }

    @Test
    void verticesNormalsAndFacesMayComeInAnyOrder() throws SceneException {
        String model = "vn 0 0 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\nv 1 1 0\nvn 1 0 0\nf 2//2 4//2 3//1\n";
        List<Face> faces = read(model);
        assertEquals(2, faces.size());
        assertEquals(withNormal(at(1, 1, 0, 3), 1, 0, 0, 1), faces.get(1).corners().get(1));
        assertEquals(withNormal(at(0, 1, 0, 2), 0, 0, 1, 0), faces.get(1).corners().get(2));
    }

    @Test
    void aFaceMayHaveAnyNumberOfVertices() throws SceneException {
        StringBuilder model = new StringBuilder();
        StringBuilder face = new StringBuilder("f");
        int n = 1000;
        for (int k = 0; k < n; k++) {
            model.append("v ").append(Math.cos(k)).append(' ').append(Math.sin(k)).append(" 0\n");
            face.append(' ').append(n - k);
        }
        List<Corner> corners = onlyFace(model.append(face).append('\n').toString());
        assertEquals(n, corners.size());
        for (int k = 0; k < n; k++) {
            assertEquals(at(Math.cos(n - 1 - k), Math.sin(n - 1 - k), 0, n - 1 - k), corners.get(k));
        }
    }

    @Test
    void facesComeInFileOrderWithTheirLines() throws SceneException {
        List<Face> faces = read(TRIANGLE + "f 1 2 3\n\nf 3 2 1\n# note\nf 2 3 1");
        assertEquals(List.of(4, 6, 8), faces.stream().map(Face::line).toList());
        assertEquals(List.of(2, 1, 0), faces.get(1).corners().stream().map(Corner::vertex).toList());
        assertEquals(List.of(1, 2, 0), faces.get(2).corners().stream().map(Corner::vertex).toList());
    }

    // ---- spelling --------------------------------------------------------------------------------

    @Test
    void keywordsMayBeUpperOrLowerCase() throws SceneException {
        assertEquals(read(TRIANGLE + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n"),
                read("V 0 0 0\nv 1 0 0\nV 0 1 0\nVT 0 0\nVN 0 0 1\nF 1/1/1 2/1/1 3/1/1\n"));
        assertEquals(1, read("v 0 0 0\nv 1 0 0\nv 0 1 0\nVt 0 0\nvN 0 0 1\nf 1/1/1 2//1 3\n").size());
    }

    @Test
    void commentsAndOtherLinesAreIgnored() throws SceneException {
        String model = "# a comment\n\n   \nmtllib a.mtl\no thing\ng group one\ns 1\ns off\nusemtl red\n"
                + "vt 0.5 0.5\nvp 1 2 3\nl 1 2\np 1\ncstype bezier\nvx 1 2\nfo 1 2\n"
                + TRIANGLE + "  # indented comment, then the face\nf 1 2 3\n#f 1 2\n";
        List<Face> faces = read(model);
        assertEquals(1, faces.size());
        assertEquals(List.of(at(0, 0, 0, 0), at(1, 0, 0, 1), at(0, 1, 0, 2)), faces.get(0).corners());
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "v 1 2 3\nv 4 5 6\nv 7 8 9\nf 1 2 3\n",
        "v 1,2,3\nv 4, 5, 6\nv (7, 8, 9)\nf 1, 2, 3\n",
        "v(1 2 3)\nv\t4\t5\t6\nv (7 8 9)\nf (1 2 3)\n",
        "\tv  1   2 3  \r\nv 4 5 6\r\nv 7 8 9\r\n  f 1 2 3 \r\n",
        "v 1.0 2.00 3e0\nv +4 5 6\nv 7 8 9\nf 1 +2 3",
        "v ((1)), 2 ,3,\nv 4 5 6\nv 7 8 9\nf 1,,2 ,3\n",
    })
    void blanksCommasAndParenthesesSeparateAlike(String model) throws SceneException {
        assertEquals(List.of(at(1, 2, 3, 0), at(4, 5, 6, 1), at(7, 8, 9, 2)), onlyFace(model));
    }

    @Test
    void aColourMayBeGroupedInItsOwnParentheses() throws SceneException {
        assertEquals(coloured(1, 2, 3, 0.5, 0.5, 0.5, 0),
                onlyFace("v (1, 2, 3) (0.5, 0.5, 0.5)\nv 0 0 0\nv 1 1 1\nf 1 2 3\n").get(0));
        assertEquals(coloured(1, 2, 3, 0.5, 0.5, 0.5, 0),
                onlyFace("v (1, 2, 3, (0.5, 0.5, 0.5))\nv 0 0 0\nv 1 1 1\nf 1 2 3\n").get(0));
    }

    @Test
    void countsAreReturned() throws SceneException {
        ObjCounts counts = ObjReader.stream(NAME,
                (TRIANGLE + "vn 0 0 1\nv 1 1 1\nf 1 2 3\nf 2 3 4\n").getBytes(StandardCharsets.UTF_8), face -> { });
        assertEquals(new ObjCounts(4, 1, 2), counts);
        assertEquals(counts, ObjModel.of(NAME, (TRIANGLE + "vn 0 0 1\nv 1 1 1\nf 1 2 3\nf 2 3 4\n")
                .getBytes(StandardCharsets.UTF_8)).counts());
    }

    @Test
    void anEmptyFileHasNoFaces() throws SceneException {
        assertEquals(List.of(), read(""));
        assertEquals(List.of(), read(TRIANGLE));
    }

    @Test
    void facesBeforeAnErrorHaveReachedTheSink() {
        CollectedFaces sink = new CollectedFaces();
        byte[] model = (TRIANGLE + "f 1 2 3\nf 1 2 4\n").getBytes(StandardCharsets.UTF_8);
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.stream(NAME, model, sink));
        assertEquals(5, e.line());
        assertEquals(1, sink.faces.size());
        assertFalse(sink.faces.get(0).corners().isEmpty());
    }
}
