package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import simpview.scene.SceneException;
import simpview.scene.text.TrailingComment;

/**
 * Every error of the .obj subset: the obj file, line and column, the line as
 * written and the problem. The model's last line is the bad one; a column is
 * 1-based, and one past the line's end when something is missing there.
 */
class ObjErrorsTest {

    private static final String TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

    private static SceneException fails(String text) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        SceneException streamed = assertThrows(SceneException.class,
                () -> ObjReader.stream(ObjReaderTest.NAME, bytes, face -> { }));
        SceneException modelled = assertThrows(SceneException.class, () -> ObjModel.of(ObjReaderTest.NAME, bytes));
        assertEquals(streamed.getMessage(), modelled.getMessage());
        assertEquals(ObjReaderTest.NAME, streamed.file());
        return streamed;
    }

    /** A file whose lines end in CR alone reads as one line: its error says so. */
    @Test
    void linesEndingInACarriageReturnAloneAreNamedSo() {
        SceneException e = fails("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
        assertEquals("expected a number, found '0 v' (this file's lines end in a carriage return alone, so it reads "
                + "as one line: save it with LF or CR LF line ends)", e.problem());
        assertEquals(7, e.column());
        assertTrue(e.getMessage().endsWith("\n    v 0 0 0 v 1 0 0 v 0 1 0 f 1 2 3\n          ^"), e.getMessage());
    }

    private static void assertError(String model, int line, int column, String problem) {
        SceneException e = fails(model);
        assertEquals(problem, e.problem(), "problem");
        assertEquals(line, e.line(), "line");
        assertEquals(column, e.column(), "column");
        String[] lines = model.split("\n", -1);
        assertEquals(lines[line - 1], e.lineText(), "line text");
        assertTrue(e.getMessage().startsWith("model.obj:" + line + ":" + column + ": " + problem), e.getMessage());
    }

    private static final String V_TAKES = "wrong count of numbers: v takes 3, 4, 6 or 7 numbers"
            + " (x y z, x y z w, x y z r g b or x y z w r g b), found ";

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "v|2|0",
        "v 1|4|1",
        "v 1 2|6|2",
        "v 1 2 3 4 5|12|5",
        "v (1, 2, 3, 4, 5)|18|5",
    })
    void aVertexOfAWrongCount(String line, int column, int found) {
        assertError("v 0 0 0\n" + line, 2, column, V_TAKES + found);
    }

    /** A comment after a line's numbers or references is read as part of them (SPEC: lines split as SIMP's). */
    @Test
    void aCommentAfterTheNumbersIsNamedForWhatItIs() {
        assertError("v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1, 9,
                "expected a number, found '#'" + TrailingComment.HINT);
        assertError(TRIANGLE + "f 1 2 3 # the front\n", 4, 9,
                "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found '#'" + TrailingComment.HINT);
        assertError(TRIANGLE + "f 1 2 x\n", 4, 7, "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found 'x'");
    }

    /** "v 0,5 0 0" is x y z w with w = 0: the error names the decimal comma that made it so. */
    /** A '\\' ending a line, Wavefront's continuation, is named: simpview reads a model line by line. */
    @Test
    void aLineContinuationIsNamed() {
        String hint = " (simpview does not join a line ending in '\\' to the next: write the whole line on one line)";
        assertError("v 0 0 \\\n 1\n", 1, 7, "expected a number, found '\\'" + hint);
        assertError(TRIANGLE + "f 1 2 \\ \n 3\n", 4, 7, "expected a vertex reference (v, v/vt, v//vn or v/vt/vn),"
                + " found '\\'" + hint);
        assertError("v 0 \\ 0 1\n", 1, 5, "expected a number, found '\\'");
    }

    /** A '\\' glued to the line's last number or reference is Wavefront's continuation too. */
    @Test
    void aLineContinuationGluedToANumberIsNamed() {
        String hint = " (simpview does not join a line ending in '\\' to the next: write the whole line on one line)";
        assertError("v 1 0 0\\\n0\n", 1, 7, "expected a number, found '0\\'" + hint);
        assertError(TRIANGLE + "f 1 2 3\\ \n", 4, 7, "expected a vertex reference (v, v/vt, v//vn or v/vt/vn),"
                + " found '3\\'" + hint);
        assertError("v 1 0\\ 0\n", 1, 5, "expected a number, found '0\\'");
    }

    /**
     * A v, vn, vt or f line whose first word holds a character that shows
     * nothing, or a look-alike, is an error naming it: passed over as a kind
     * of line simpview does not read, it left a vertex or a face silently
     * missing (and a later index naming nothing).
     */
    @Test
    void aKeywordHoldingAnInvisibleCharacterIsNamed() {
        String passed = " (as it is, the word is not '%s', and the line would be passed over as one simpview does not"
                + " read)";
        String nbsp = ", which holds a non-breaking space (U+00A0 NO-BREAK SPACE) after '%s': use a plain space";
        assertError("v 0 0 0\nv\u00A01 0 0\n", 2, 1, "this line's first word reads 'v\u00A01'"
                + String.format(nbsp + passed, "v", "v"));
        assertError(TRIANGLE + "v 1 1 0\nf 1 2 3\nf\u00A02 4 3\n", 6, 1, "this line's first word reads 'f\u00A02'"
                + String.format(nbsp + passed, "f", "f"));
        assertError("vn\u00A00 0 1\n", 1, 1, "this line's first word reads 'vn\u00A00'"
                + String.format(nbsp + passed, "vn", "vn"));
        assertError("vt\u00A00 0\n", 1, 1, "this line's first word reads 'vt\u00A00'"
                + String.format(nbsp + passed, "vt", "vt"));
        assertError("v 0 0 0\n\uFEFFv 1 0 0\n", 2, 1, "this line's first word reads '\uFEFFv', which holds a byte"
                + " order mark (U+FEFF ZERO WIDTH NO-BREAK SPACE) before 'v': delete it (a file's byte order mark is"
                + " left there when files are joined, as cat a.simp b.simp joins them)" + String.format(passed, "v"));
        assertError("v\u22121 0 0\n", 1, 1, "this line's first word reads 'v\u22121', whose '\u2212' is U+2212 MINUS"
                + " SIGN, not ASCII: the word and what follows it are written in ASCII, a plain space between them"
                + " (text copied from a PDF or a word processor often looks right and is not)"
                + String.format(passed, "v"));
    }

    /**
     * A form feed (a page break) stuck to a keyword, before it or after it, is named as in a scene: passed over,
     * the line left its vertex silently missing.
     */
    @Test
    void aFormFeedStuckToAKeywordIsNamed() {
        String passed = " (as it is, the word is not 'v', and the line would be passed over as one simpview does not"
                + " read)";
        assertError("v 0 0 0\n\fv 1 0 0\n", 2, 1, "this line's first word reads '\\x0Cv', which holds a form feed"
                + " (U+000C FORM FEED (FF)) before 'v': use a plain space" + passed);
        assertError("v 0 0 0\nv\f1 0 0\n", 2, 1, "this line's first word reads 'v\\x0C1', which holds a form feed"
                + " (U+000C FORM FEED (FF)) after 'v': use a plain space" + passed);
    }

    /** A look-alike character stuck to a face's reference is named, as one stuck to a number is. */
    @Test
    void anInvisibleCharacterInAReferenceIsNamed() {
        assertError(TRIANGLE + "f 1 2 3\u200B\n", 4, 7, "expected a vertex reference (v, v/vt, v//vn or v/vt/vn),"
                + " found '3\u200B', which holds a zero-width space (U+200B ZERO WIDTH SPACE) after '3': delete it");
        assertError(TRIANGLE + "f 1 2 \u200B3\n", 4, 7, "expected a vertex reference (v, v/vt, v//vn or v/vt/vn),"
                + " found '\u200B3', which holds a zero-width space (U+200B ZERO WIDTH SPACE) before '3': delete it");
    }

    /** Words beyond ASCII that are no keyword stay other lines, passed over: a group or an object's name. */
    @Test
    void otherLinesBeyondAsciiArePassedOver() throws Exception {
        byte[] bytes = ("g caf\u00E9\no \u00E9t\u00E9\nvertex\u00A01\n" + TRIANGLE + "f 1 2 3\n")
                .getBytes(StandardCharsets.UTF_8);
        assertEquals(1, ObjModel.of(ObjReaderTest.NAME, bytes).faceCount());
    }

    @Test
    void aDecimalCommaThatMakesWZeroIsNamed() {
        assertError("v 0,5 0 0\n", 1, 9, "w is 0: the point (x/w, y/w, z/w) is undefined (a comma separates two"
                + " numbers: one and a half is 1.5, not 1,5)");
        assertError("v 0.5 0 0 0\n", 1, 11, "w is 0: the point (x/w, y/w, z/w) is undefined");
    }

    @Test
    void aVertexOfMoreThanSevenNumbers() {
        assertError("v 1 2 3 4 5 6 7 8 9", 1, 17, V_TAKES + "more than 7");
    }

    /**
     * A line of a wrong count whose commas between digits, read as decimal
     * points, would make a count it takes: the SIMP reader's hint. Commas
     * that cannot be decimal ones, or within parentheses, get none.
     */
    @Test
    void decimalCommasThatMakeAWrongCountGetTheHint() {
        String hint = " (a comma separates two numbers: one and a half is 1.5, not 1,5)";
        assertError("v 0,5 1,5 2", 1, 12, V_TAKES + 5 + hint);
        assertError("v 1,0 2,0 3,0 0,5 0,5 0,5", 1, 17, V_TAKES + "more than 7" + hint);
        assertError("vn 0,5 0,5 0,5", 1, 10, "wrong count of numbers: vn takes 3 numbers (x y z), found 6" + hint);
        assertError("v 1,2,3,4,5", 1, 12, V_TAKES + 5);
        assertError("v (1,5 2 3 4)", 1, 14, V_TAKES + 5);
    }

    /**
     * Java's memory running out while a model is read or its faces drawn (a
     * sink that runs out stands for both): an error at the line, with how
     * much was read and how to give Java more, never the OutOfMemoryError.
     */
    @Test
    void memoryRunningOutIsAnErrorAtTheLineSayingWhatToDo() {
        byte[] model = (TRIANGLE + "# the first face\nf 1 2 3\n").getBytes(StandardCharsets.UTF_8);
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.stream(ObjReaderTest.NAME, model,
                face -> {
                    throw new OutOfMemoryError("Java heap space");
                }));
        assertEquals(5, e.line());
        assertEquals(0, e.column());
        assertEquals("", e.lineText());
        assertTrue(e.problem().startsWith("out of memory reading this model, at 3 vertices and 1 face so far (Java may"
                + " use at most "), e.problem());
        assertTrue(e.problem().endsWith(" MB here): give Java more, e.g. JAVA_OPTS=-Xmx2g before the simpview start"
                + " script, or java -Xmx2g -jar simpview.jar"), e.problem());
    }

    @Test
    void aNormalOfAWrongCount() {
        assertError("vn 1 2", 1, 7, "wrong count of numbers: vn takes 3 numbers (x y z), found 2");
        assertError("vn 1 2 3 4 5", 1, 10, "wrong count of numbers: vn takes 3 numbers (x y z), found 5");
        assertError("VN", 1, 3, "wrong count of numbers: vn takes 3 numbers (x y z), found 0");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "v 1 2 x|7|x",
        "v 1 2 3.4.5|7|3.4.5",
        "v 1 2 3x|7|3x",
        "v 1 2 0x10|7|0x10",
        "vn 1 - 2|6|-",
        "v 1 2 3 1 e 0 0|11|e",
    })
    void aNumberThatDoesNotParse(String line, int column, String token) {
        assertError(line, 1, column, "expected a number, found '" + token + "'");
    }

    /**
     * What a program prints for a value it could not compute (C's "nan", "-nan", "inf", Java's "NaN" and
     * "Infinity", Windows' "1.#QNAN0" and "-1.#IND00") is said to be that, and where it comes from.
     */
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "v NaN 1 2|3|NaN|not a number",
        "v 1 Infinity 2|5|Infinity|infinite",
        "vn -nan -nan -nan|4|-nan|not a number",
        "vn 0 0 inf|8|inf|infinite",
        "vn 1.#QNAN0 0 1|4|1.#QNAN0|not a number",
        "v 0 -1.#IND00 0|5|-1.#IND00|not a number",
        "v 1 2 3 -1.#INF 0 0|9|-1.#INF|infinite",
    })
    void aValueThatIsNotFiniteIsNamedForWhatItIs(String line, int column, String token, String what) {
        assertError(line, 1, column, "expected a number, found '" + token + "' (" + what + ": the program that wrote"
                + " the file printed a value it could not compute, often the normal of a face of no area; every"
                + " number must be finite: remove that face, or give this line finite numbers)");
    }

    @Test
    void aMinusSignCopiedFromAPdfIsNamed() {
        assertError("v 1 \u22122 3", 1, 5, "expected a number, found '\u22122', whose '\u2212' is U+2212 MINUS SIGN,"
                + " not ASCII: a number is written with the ASCII digits, '-', '+', '.' and 'e' (text copied from a PDF"
                + " or a word processor often looks right and is not)");
    }

    @Test
    void aNumberOutOfRange() {
        assertError("v 1 2 1e999", 1, 7, "number out of range: '1e999'");
        assertError("vn -1e400 0 0", 1, 4, "number out of range: '-1e400'");
    }

    @Test
    void wOfZero() {
        assertError("v 1 2 3 0", 1, 9, "w is 0: the point (x/w, y/w, z/w) is undefined");
        assertError("v 1 2 3 -0.0 1 1 1", 1, 9, "w is 0: the point (x/w, y/w, z/w) is undefined");
    }

    @Test
    void aPointThatWOverflows() {
        assertError("v 1e300 1 1 1e-300", 1, 13, "the point (x/w, y/w, z/w) is out of range");
    }

    @Test
    void aFaceOfFewerThanThreeVertices() {
        assertError(TRIANGLE + "f 1 2", 4, 6, "a face takes at least 3 vertices, found 2");
        assertError(TRIANGLE + "f 1", 4, 4, "a face takes at least 3 vertices, found 1");
        assertError(TRIANGLE + "F", 4, 2, "a face takes at least 3 vertices, found 0");
        assertError(TRIANGLE + "f (1, 2)  ", 4, 11, "a face takes at least 3 vertices, found 2");
    }

    @Test
    void anIndexOfZero() {
        assertError(TRIANGLE + "f 1 0 2", 4, 5, "vertex index 0: indices start at 1 (or count back from -1)");
        assertError(TRIANGLE + "vn 0 0 1\nf 1//1 2//0 3//1", 5, 11,
                "normal index 0: indices start at 1 (or count back from -1)");
    }

    @Test
    void textureIndicesNameNothingToCheck() throws SceneException {
        // vt lines are ignored (SPEC), so the index between the slashes is read and passed over.
        int[] faces = {0};
        ObjReader.stream(ObjReaderTest.NAME, (TRIANGLE + "f 1/1 2/0 3/7\nvn 0 0 1\nf 1/9/1 2/-3/1 3//1\n")
                .getBytes(StandardCharsets.UTF_8), face -> faces[0]++);
        assertEquals(2, faces[0]);
        assertError(TRIANGLE + "f 1/x 2 3", 4, 3, "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found '1/x'");
    }

    @Test
    void anIndexBeyondWhatIsDefinedSoFar() {
        assertError(TRIANGLE + "f 1 2 4", 4, 7, "vertex index 4 names nothing: 3 vertices (v lines) defined so far");
        assertError(TRIANGLE + "f 1 2 -4", 4, 7,
                "vertex index -4 names nothing: 3 vertices (v lines) defined so far");
        assertError("f 1 2 3\n# no v lines\n", 1, 3,
                "vertex index 1 names nothing: 0 vertices (v lines) defined so far");
        assertError(TRIANGLE + "vn 0 0 1\nf 1//1 2//2 3//1", 5, 11,
                "normal index 2 names nothing: 1 normal (vn line) defined so far");
        assertError(TRIANGLE + "vn 0 0 1\nf 1//-2 2//1 3//1", 5, 6,
                "normal index -2 names nothing: 1 normal (vn line) defined so far");
        assertError(TRIANGLE + "f 1 2 99999999999999999999", 4, 7,
                "vertex index 99999999999999999999 names nothing: 3 vertices (v lines) defined so far");
    }

    /**
     * A face before the lines that define what it names (a student's file written faces first): the error
     * says where the file defines it, and that a face names only what stands above it.
     */
    @Test
    void anIndexDefinedFurtherDownSaysWhere() {
        assertError("f 1 2 3\n# the points\nV 0 0 0\nvn 0 0 1\nv 1 0 0\n\nv 0 1 0\n", 1, 3,
                "vertex index 1 names nothing: 0 vertices (v lines) defined so far; the file defines it further"
                + " down, at line 3, but a face names only the v lines above it: move the v lines before the f lines");
        assertError("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n", 2, 5, "vertex index 2 names nothing: 1 vertex (v line)"
                + " defined so far; the file defines it further down, at line 3, but a face names only the v lines"
                + " above it: move the v lines before the f lines");
        assertError(TRIANGLE + "vn 0 0 1\nf 1//1 2//2 3//1\nv 5 5 5\nvn 0 1 0\n", 5, 11, "normal index 2 names"
                + " nothing: 1 normal (vn line) defined so far; the file defines it further down, at line 7, but a"
                + " face names only the vn lines above it: move the vn lines before the f lines");
        // Defined nowhere further down: no more is said.
        assertError(TRIANGLE + "f 1 2 5\nv 1 1 1\n", 4, 7, "vertex index 5 names nothing: 3 vertices (v lines)"
                + " defined so far");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "f 1 2 x|7|x",
        "f 1.5 2 3|3|1.5",
        "f 1/ 2 3|3|1/",
        "f 1// 2 3|3|1//",
        "f 1/1/ 2 3|3|1/1/",
        "f 1/1/1/1 2 3|3|1/1/1/1",
        "f /1 2 3|3|/1",
        "f 1 2 --3|7|--3",
        "f 1 2 3a|7|3a",
    })
    void aReferenceThatDoesNotParse(String line, int column, String token) {
        assertError(TRIANGLE + "vt 0 0\nvn 0 0 1\n" + line, 6, column,
                "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found '" + token + "'");
    }

    @Test
    void aReferenceOfFourPartsIsToldSoWhetherOrNotItsNormalIsDefined() {
        // without vn lines its third part names nothing, but its form is what is wrong
        assertError(TRIANGLE + "f 1/1/1/1 2 3", 4, 3,
                "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found '1/1/1/1'");
    }

    @Test
    void theColumnCountsCharactersNotBytes() {
        String problem = "expected a number, found '\u00e9', whose '\u00e9' is U+00E9 LATIN SMALL LETTER E WITH ACUTE,"
                + " not ASCII: a number is written with the ASCII digits, '-', '+', '.' and 'e' (text copied from a PDF"
                + " or a word processor often looks right and is not)";
        assertError("vn \u00e9 1 2", 1, 4, problem);
        assertError("# caf\u00e9\nv 1 \u00e9 2", 2, 5, problem);
    }

    @Test
    void theMessageShowsTheLineAndPointsAtTheColumn() {
        SceneException e = fails(TRIANGLE + "f 1 2 7");
        assertEquals("model.obj:4:7: vertex index 7 names nothing: 3 vertices (v lines) defined so far\n"
                + "    f 1 2 7\n"
                + "          ^", e.getMessage());
    }

    @Test
    void aMissingFileIsNamed(@TempDir Path dir) {
        Path missing = dir.resolve("gone.obj");
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.stream(missing, face -> { }));
        assertEquals(missing, e.file());
        assertTrue(e.problem().startsWith("cannot open the obj file " + missing.toAbsolutePath().normalize()
                + ": file not found"), e.problem());
    }

    @Test
    void aLineTooLongForMemoryIsAnError(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("long.obj");
        StringBuilder text = new StringBuilder(TRIANGLE).append("f");
        while (text.length() < (1 << 21)) {
            text.append(" 1 2 3");
        }
        Files.writeString(file, text.append('\n'));
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.stream(file, face -> { }));
        assertEquals(4, e.line());
        assertEquals(1048577, e.column(), "the first character past the limit");
        // the SIMP reader says it in the same form (ScenePipelineTest): the limit, and what to do
        assertEquals("line is too long: over 1048576 bytes (1 MiB), the most a line may hold. Put one v, vn or f on "
                + "each line of an .obj file; a file saved without its line ends is one long line: save it again "
                + "with them", e.problem());
        assertTrue(e.getMessage().startsWith(file + ":4:1048577: line is too long: "), e.getMessage());
    }
}
