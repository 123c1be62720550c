package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import simpview.scene.SceneException;

/**
 * What reading a model warns of without stopping: each warning names the
 * file, and a model kept and replayed gives the same warnings as streaming it.
 */
class ObjWarningsTest {

    private static List<String> warnings(String text) throws SceneException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        ObjCounts streamed = ObjReader.stream(ObjReaderTest.NAME, bytes, face -> { });
        assertEquals(streamed, ObjModel.of(ObjReaderTest.NAME, bytes).counts(), "the kept model's counts");
        return streamed.warnings();
    }

    private static final String HINT = "(a comma separates two numbers: one and a half is 1.5, not 1,5)";

    /**
     * A model saved under a German or French locale: SPEC reads "0,5" as two
     * numbers, so each v line is a position and a colour, drawn; the first
     * such line is named, at its first such number.
     */
    @Test
    void decimalCommasThatMakeAnotherCountAVertexTakesAreNamed() throws SceneException {
        assertEquals(List.of("model.obj:2:4: '-1,0' is read as two numbers, so this v line's 6 numbers are"
                + " x y z r g b " + HINT + "; this is the first such line"),
                warnings("# saved in Berlin\nv  -1,0 0,5 -4,0\nv 1,0 0,0 -4,0\nv 0,0 1,0 -4,0\nf 1 2 3\n"));
        assertEquals(List.of("model.obj:1:3: '1,5' is read as two numbers, so this v line's 4 numbers are"
                + " x y z w " + HINT + "; this is the first such line"), warnings("v 1,5 2 3\nv 0 0 0\nv 1 0 0\nf 1 2 3\n"));
    }

    @Test
    void commasThatCannotBeDecimalCommasWarnOfNothing() throws SceneException {
        assertEquals(List.of(), warnings("v 1,2,3\nv (1,5, 2, 3)\nv 1, 2, 3, 0.5, 0.5, 0.5\nv 0.5,1 2 3\nv 1,5,2 3\nf 1,2,4\n"));
    }

    // ---- faces SPEC draws otherwise than their outline ------------------------------------------

    /**
     * A five-vertex face that starts on an edge: SPEC's face normal from its first three vertices is zero, so
     * (without vn) it is lit by the ambient light alone; the same face started at a corner is not named, nor a
     * face whose every vertex has its own normal.
     */
    @Test
    void aFaceStartingOnAnEdgeIsNamedForItsNormal() throws SceneException {
        String square = "v -2 -1 0\nv -1 -1 0\nv 0 -1 0\nv 0 1 0\nv -2 1 0\nvn 0 0 1\n";
        assertEquals(List.of("model.obj:7: this face's first three vertices lie on one line, so its face normal,"
                + " (p2 - p1) x (p3 - p1) by SPEC, is zero or made of rounding errors, and where a vertex has no vn it"
                + " is lit by the ambient light alone or wrongly: start the face at a corner, or give its vertices vn"
                + " normals (and 1 more face like it)"),
                warnings(square + "f 1 2 3 4 5\nf 2 3 4 5 1\nf 3 2 1 5 4\nf 1/1/1 2//1 3//1 4//1 5//1\n"));
        assertEquals(List.of(), warnings(square + "f 3 4 5 1 2\nf 1//1 2//1 3//1 4//1 5//1\nf 1 3 4\n"));
    }

    /**
     * Faces of no area (a triangle whose vertices lie on one line, a quad naming one vertex four times, a
     * five-vertex face along one line) fill nothing: one warning names the first and counts them, and the one of
     * more than three vertices is not named again for its first three vertices on one line. A thin face is not
     * named, nor one whose vertices are far apart, near the end of the doubles, unless they do lie on one line.
     */
    @Test
    void aFaceOfNoAreaIsNamedOnce() throws SceneException {
        String points = "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nv 0 1 0\n";
        assertEquals(List.of("model.obj:7: this face has no area (its vertices lie on one line, or coincide), so, as"
                + " SPEC fills a triangle of no area, it fills no pixel (in wire style only its edges show, along that"
                + " line): remove it, or check which v lines it names (and 2 more faces like it)"),
                warnings(points + "f 1 2 5\nf 1 2 3\nf 4 4 4 4\nf 2 1 4 3 2\n"));
        assertEquals(List.of(), warnings(points + "v 1 1.000001 1\nf 1 2 6\nf 1 2 5\n"));
        // a vertex near the doubles' end: its squares would overflow and make any face look like one of no area
        assertEquals(List.of(), warnings("v -50 -50 -100\nv 1e308 -50 -100\nv 0 50 -100\nf 1 2 3\n"));
        assertEquals(List.of("model.obj:4: this face has no area (its vertices lie on one line, or coincide), so, as"
                + " SPEC fills a triangle of no area, it fills no pixel (in wire style only its edges show, along that"
                + " line): remove it, or check which v lines it names"),
                warnings("v 0 0 0\nv 1e308 1e308 1e308\nv 5e307 5e307 5e307\nf 1 2 3\n"));
    }

    /**
     * The test of no area is exact: a sliver thin against its length has an area (seen close, it fills pixels), at
     * any size of coordinates, and is never named; vertices exactly on one line, large integers or tiny numbers,
     * are.
     */
    @Test
    void aThinSliverIsNoFaceOfNoArea() throws SceneException {
        assertEquals(List.of(), warnings("v 0 0 0\nv 1000000 0 0\nv 2000000 0.001 0\nf 1 2 3\n"));
        assertEquals(List.of(), warnings("v 0 0 0\nv 1000000000 0 0\nv 2000000000 1 0\nf 1 2 3\n"));
        assertEquals(List.of(), warnings("v 0 0 0\nv 2 0 0\nv 1 0.0000000001 0\nf 1 2 3\n"));
        assertEquals(List.of(), warnings("v 0 0 0\nv 1e-300 0 0\nv 2e-300 1e-310 0\nf 1 2 3\n"));
        assertEquals(List.of(), warnings("v 1e200 0 0\nv 2e200 1e200 0\nv 3e200 2e200 1\nf 1 2 3\n"));
        String noArea = "model.obj:4: this face has no area (its vertices lie on one line, or coincide), so, as SPEC"
                + " fills a triangle of no area, it fills no pixel (in wire style only its edges show, along that"
                + " line): remove it, or check which v lines it names";
        assertEquals(List.of(noArea), warnings("v 1 2 3\nv 4 6 8\nv 1000000003 1333333338 1666666673\nf 1 2 3\n"));
        assertEquals(List.of(noArea), warnings("v 0 0 0\nv 1e-300 1e-300 0\nv 3e-300 3e-300 0\nf 1 2 3\n"));
    }

    /**
     * A face that uses vn 0 0 0 is lit by the ambient light alone where it is used: one warning names the first
     * such face, the normal's number, and counts the faces; a face that names the normal only through other faces,
     * or a tiny normal, is not named.
     */
    @Test
    void aFaceUsingANormalOfZeroLengthIsNamedOnce() throws SceneException {
        String model = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 -0 0\nvn 0 0 1e-30\n";
        assertEquals(List.of("model.obj:8: this face uses a normal of zero length (vn 0 0 0, normal 2 as f lines number"
                + " the vn lines), which SPEC cannot make unit length, and a zero normal gives only the ambient term, so where it is"
                + " used the face is lit by the ambient light alone: give that vn a direction, or leave it out of the face"
                + " (its face normal is then used) (and 1 more face like it)"),
                warnings(model + "f 1//1 2//1 3//1\nf 1//1 2//2 3//1\nf 1//3 2//3 3//3\nf 1/1/2 2 3\n"));
        assertEquals(List.of(), warnings(model + "f 1//1 2//1 3//1\nf 1//3 2//3 3//3\nf 1 2 3\n"));
    }

    /** A star of ten vertices is filled as a fan from its first, which is not its outline: named. */
    @Test
    void aFaceThatIsNotConvexIsNamedForItsFan() throws SceneException {
        String star = "v 0 3 0\nv 1 1 0\nv 3 1 0\nv 1.5 -0.5 0\nv 2 -3 0\nv 0 -1.5 0\nv -2 -3 0\nv -1.5 -0.5 0\n"
                + "v -3 1 0\nv -1 1 0\n";
        assertEquals(List.of("model.obj:11: this face of 10 vertices is not convex, and SPEC fills a face as a fan"
                + " from its first vertex, which covers what its outline leaves out: split it into triangles"
                + " (Blender: Triangulate)"), warnings(star + "f 1 2 3 4 5 6 7 8 9 10\n"));
        // Its outer five points make a convex pentagon (either way round): no warning.
        assertEquals(List.of(), warnings(star + "f 1 3 5 7 9\nf 9 7 5 3 1\n"));
        // The same five points in one stroke, a pentagram: it turns one way at every point, twice round.
        assertEquals(List.of("model.obj:11: this face of 5 vertices is not convex, and SPEC fills a face as a fan"
                + " from its first vertex, which covers what its outline leaves out: split it into triangles"
                + " (Blender: Triangulate)"), warnings(star + "f 1 5 9 3 7\n"));
    }

    /**
     * A flat dart (an arrowhead of four vertices) listed from its tip or from its notch is filled exactly by
     * its fan: not named. Listed from either of its other two corners, one fan triangle lies in the notch and
     * turns against the face (lit from behind, where it is the first): named, as a face of five or more is.
     * The same dart with its notch lifted out of plane, twisted as the course's dummy.obj's ten quads are
     * (its fan is drawn as the course draws it), is not named.
     */
    @Test
    void aFlatDartIsNamedWhenItsFanLeavesTheOutlineButATwistedQuadIsNot() throws SceneException {
        String dart = "v 0 -1 0\nv 1 1 0\nv 0 0 0\nv -1 1 0\n";
        String named = "model.obj:5: this face of 4 vertices is not convex, and SPEC fills a face as a fan from its"
                + " first vertex, which covers what its outline leaves out: split it into triangles (Blender:"
                + " Triangulate)";
        assertEquals(List.of(), warnings(dart + "f 1 2 3 4\n"), "from its tip");
        assertEquals(List.of(), warnings(dart + "f 3 4 1 2\n"), "from its notch");
        assertEquals(List.of(named), warnings(dart + "f 2 3 4 1\n"), "from a side corner");
        assertEquals(List.of(named + " (and 1 more face like it)"), warnings(dart + "f 4 1 2 3\nf 2 3 4 1\n"));
        // The dart turned about two axes and moved, written with six decimals as exporters write: out of plane
        // by rounding alone (1e-7 of the measure), still flat enough to be named.
        assertEquals(List.of(named), warnings("v 3.729426 -2.171212 0.184646\nv 3.648157 -0.462103 1.624209\n"
                + "v 3.250000 -1.500000 0.750000\nv 1.892992 -1.195473 1.006500\nf 2 3 4 1\n"));
        String twisted = "v 0 -1 0\nv 1 1 0\nv 0 0 0.1\nv -1 1 0\n";
        assertEquals(List.of(), warnings(twisted + "f 2 3 4 1\n"), "out of plane");
    }

    /**
     * An L is not convex, but its fan from the outer corner (or from the notch's corner, which sees all of
     * it) covers exactly the L: not named. From a corner beside the notch its second fan triangle lies in
     * the notch: named. A convex face, either way round and from any vertex, is never named.
     */
    @Test
    void anLIsNamedOnlyWhenItsFanFromTheFirstVertexLeavesTheOutline() throws SceneException {
        String l = "v -80 -80 -50\nv 80 -80 -50\nv 80 -20 -50\nv -20 -20 -50\nv -20 80 -50\nv -80 80 -50\n";
        assertEquals(List.of(), warnings(l + "f 1 2 3 4 5 6\n"), "from the outer corner: the fan is the L");
        assertEquals(List.of(), warnings(l + "f 4 5 6 1 2 3\n"), "from the notch: the fan is the L");
        assertEquals(List.of(), warnings(l + "f 1 6 5 4 3 2\n"), "clockwise, from the outer corner");
        assertEquals(List.of("model.obj:7: this face of 6 vertices is not convex, and SPEC fills a face as a fan"
                + " from its first vertex, which covers what its outline leaves out: split it into triangles"
                + " (Blender: Triangulate)"), warnings(l + "f 3 4 5 6 1 2\n"));
        assertEquals(List.of("model.obj:7: this face of 6 vertices is not convex, and SPEC fills a face as a fan"
                + " from its first vertex, which covers what its outline leaves out: split it into triangles"
                + " (Blender: Triangulate) (and 2 more faces like it)"),
                warnings(l + "f 5 6 1 2 3 4\nf 2 1 6 5 4 3\nf 6 5 4 3 2 1\n"));
        // A regular hexagon, tilted out of the xy plane: convex, from every vertex and either way round.
        StringBuilder hexagon = new StringBuilder();
        for (int k = 0; k < 6; k++) {
            double a = Math.toRadians(60 * k + 10);
            hexagon.append("v ").append(Math.cos(a)).append(' ').append(Math.sin(a)).append(' ')
                    .append(0.3 * Math.cos(a)).append('\n');
        }
        for (int first = 0; first < 6; first++) {
            StringBuilder f = new StringBuilder("f");
            StringBuilder back = new StringBuilder("f");
            for (int k = 0; k < 6; k++) {
                f.append(' ').append((first + k) % 6 + 1);
                back.append(' ').append((first + 6 - k) % 6 + 1);
            }
            assertEquals(List.of(), warnings(hexagon + f.toString() + "\n" + back + "\n"), f + " and " + back);
        }
    }

    // ---- a file without faces -------------------------------------------------------------------

    /** A file that gives no face is named, with what it held, so that an empty picture is explained. */
    @Test
    void aFileWithoutFacesSaysSoAndWhatItHeld() throws SceneException {
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (the file is empty)"), warnings(""));
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (3 lines read: only blank lines and"
                + " comments)"), warnings("# exported by hand\n\n   # nothing yet\n"));
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (5 lines read: 3 v lines, 1 vn line,"
                + " 1 other line (the first, line 5, starts with 'vt'))"),
                warnings("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"));
    }

    /**
     * A control character in an ignored line, after kilobytes of text, is no
     * longer let by as part of a word to show escaped: every line is checked
     * as it is read, so the file is not text, at that line (docs/simp.md).
     */
    @Test
    void aControlCharacterInAnIgnoredLineFarOnIsNotText() {
        String text = "v 0 0 0\n" + "#".repeat(5000) + "\n";
        SceneException e = org.junit.jupiter.api.Assertions.assertThrows(SceneException.class,
                () -> warnings(text + "x\u0000y\u001b\n"));
        assertEquals("not a text file: byte 0x00 at offset 5010 (line 3); an .obj file is lines of text", e.problem());
    }

    /** A lines-only model: its l lines are named, since other programs draw them. */
    @Test
    void aModelOfLinesOnlySaysThatLLinesAreNotDrawn() throws SceneException {
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (4 lines read: 3 v lines, 1 other line"
                + " (the first, line 4, starts with 'l')); l lines (polylines) are not drawn: a model is drawn by"
                + " its faces, f lines"), warnings("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3 1\n"));
    }

    /** A scene's commands saved as .obj: its first word shows what it is. */
    @Test
    void sceneCommandsSavedAsObjNameTheirFirstWord() throws SceneException {
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (3 lines read: 2 other lines (the first,"
                + " line 2, starts with 'camera'))"),
                warnings("# a scene\ncamera -1 -1 1 1 -1 -100\npolygon (0, 0, -5) (1, 0, -5) (0, 1, -5)\n"));
    }

    /** A points-only model (a scan's cloud, as MeshLab writes it) names its p lines, and both kinds together. */
    @Test
    void aModelOfPointsOnlySaysThatPLinesAreNotDrawn() throws SceneException {
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (5 lines read: 3 v lines, 2 other lines"
                + " (the first, line 4, starts with 'p')); p lines (points) are not drawn: a model is drawn by its"
                + " faces, f lines"), warnings("v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2\nP 3\n"));
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (5 lines read: 3 v lines, 2 other lines"
                + " (the first, line 4, starts with 'l')); l lines (polylines) and p lines (points) are not drawn:"
                + " a model is drawn by its faces, f lines"), warnings("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 3\n"));
    }

    /**
     * A model of faces that also holds l and p lines (an outline or a marker drawn in the modeller): its faces
     * are drawn, and one warning names the first l or p line and how many were passed over, however many
     * there are.
     */
    @Test
    void polylinesAndPointsBesideFacesAreNamedOnce() throws SceneException {
        String triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        assertEquals(List.of("model.obj:5: l lines (polylines) are not drawn: a model is drawn by its faces, f lines"
                + " (1000 l lines passed over, this the first; the 1 face drawn)"),
                warnings(triangle + "l 1 2 3 1\n".repeat(1000)));
        assertEquals(List.of("model.obj:2: l lines (polylines) and p lines (points) are not drawn: a model is drawn"
                + " by its faces, f lines (2 l lines and 1 p line passed over, this the first; the 2 faces drawn)"),
                warnings("v 0 0 0\np 1\nv 1 0 0\nv 0 1 0\nL 1 2\nf 1 2 3\nl 2 3\nf 3 2 1\n"));
    }

    /** Lines of other kinds beside a face are passed over without a word: vt, g, o, s, usemtl, mtllib. */
    @Test
    void aFileWithAFaceWarnsOfNothing() throws SceneException {
        assertEquals(List.of(), warnings("mtllib a.mtl\no Cube\ng box\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                + "usemtl red\ns 1\nf 1/1 2/1 3/1\n"));
    }

    /** A page break an editor left on a line of its own is a blank line, as in a scene, not a line of another kind. */
    @Test
    void aLineOfFormFeedsIsBlank() throws SceneException {
        assertEquals(List.of("model.obj: no f lines, so nothing is drawn (3 lines read: only blank lines and"
                + " comments)"), warnings("\f\n# page two\n \f\t\f\n"));
    }

    // ---- models inside out -----------------------------------------------------------------------

    /** A tetrahedron, (0, 0, 0) and the three unit points, and its normals pointing out of it. */
    private static final String TETRA = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
            + "vn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 1 1 1\n";
    /** Its faces counter-clockwise seen from outside, each vertex with the face's normal (lines 9 to 12). */
    private static final String OUTWARD = "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\nf 1//3 4//3 3//3\nf 2//4 3//4 4//4\n";
    /** The same faces listed clockwise. */
    private static final String CLOCKWISE = "f 1//1 2//1 3//1\nf 1//2 4//2 2//2\nf 1//3 3//3 4//3\nf 2//4 4//4 3//4\n";
    private static final String DARK = "so point lights outside it light nothing there: it shows black, or the ambient"
            + " light alone: ";

    private static String negated(String model) {
        return model.replace("vn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 1 1 1", "vn 0 0 1\nvn 0 1 0\nvn 1 0 0\nvn -1 -1 -1");
    }

    private static String withoutNormals(String faces) {
        return faces.replaceAll("//[0-9]", "");
    }

    /**
     * A closed model whose vn normals point into it, its faces wound as seen from outside: every face has its
     * normals against its front, so point lights outside light nothing; one warning names the first face and says
     * to negate the normals. Not when its normals point out, nor when one face of many has a normal turned.
     */
    @Test
    void aModelWhoseNormalsPointIntoItIsNamedOnce() throws SceneException {
        assertEquals(List.of("model.obj:9: the model is inside out: its vn normals point against the front of 4 of"
                + " the 4 faces whose vertices all have one (this face the first), the side from which a face's"
                + " vertices run counter-clockwise, and SPEC lights a face by its normals, " + DARK + "negate the vn"
                + " lines (vn x y z becomes vn -x -y -z)"), warnings(negated(TETRA) + OUTWARD));
        assertEquals(List.of(), warnings(TETRA + OUTWARD));
        assertEquals(List.of(), warnings(TETRA + OUTWARD.replace("f 1//1 3//1 2//1", "f 1//4 3//4 2//4")));
    }

    /**
     * A closed model whose faces are listed clockwise as seen from outside and that has no normals: each face is
     * lit on its front, its inside; one warning names the first face and says to reverse the faces. With vn
     * normals pointing out it is lit right, and not named; with normals pointing in along the faces, both are
     * to be turned. A flat model, which has no inside, is not named either way round.
     */
    @Test
    void aModelListedClockwiseIsNamedOnce() throws SceneException {
        assertEquals(List.of("model.obj:9: the model is inside out: its faces are listed clockwise as seen from"
                + " outside (the fronts of 100 % of its surface, weighted by distance from its centre, face inward;"
                + " this face the first), and a face without vn normals is lit on its front, the side from which its"
                + " vertices run counter-clockwise, " + DARK + "reverse the order of each f line's vertices"
                + " (f 1 2 3 becomes f 3 2 1)"), warnings(TETRA + withoutNormals(CLOCKWISE)));
        assertEquals(List.of(), warnings(TETRA + withoutNormals(OUTWARD)));
        assertEquals(List.of(), warnings(TETRA + CLOCKWISE));
        assertEquals(List.of("model.obj:9: the model is inside out: its faces are listed clockwise as seen from"
                + " outside (the fronts of 100 % of its surface, weighted by distance from its centre, face inward;"
                + " this face the first), and its vn normals point inward with them, " + DARK + "reverse the order of"
                + " each f line's vertices and negate the vn lines (vn x y z becomes vn -x -y -z)"),
                warnings(negated(TETRA) + CLOCKWISE));
        String square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
        assertEquals(List.of(), warnings(square + "f 1 2 3\nf 1 3 4\n"));
        assertEquals(List.of(), warnings(square + "f 3 2 1\nf 4 3 1\n"));
    }
}
