package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.geometry.Axis;
import simpview.scene.SceneException;
import simpview.scene.simp.Command.Kind;
import simpview.scene.text.TrailingComment;

class SimpReaderTest {

    private static final Path FILE = Path.of("scene.simp");
    /** What an unknown command's message ends with: every command the reader knows. */
    private static final String EXPECTED_COMMANDS = "; expected {, }, scale, translate, rotate, line, polygon, file,"
            + " wire, filled, camera, obj, ambient, surface, depth, light, flat, gouraud or phong";

    private static SimpReader reader(String text) {
        return SimpReader.of(FILE, text.getBytes(StandardCharsets.UTF_8));
    }

    /** The one command in the text. */
    private static Command parse(String text) throws SceneException {
        SimpReader r = reader(text);
        Command c = new Command();
        assertTrue(r.next(c), "expected a command in: " + text);
        assertFalse(r.next(new Command()), "expected only one command in: " + text);
        return c;
    }

    private static SceneException error(String text) {
        return assertThrows(SceneException.class, () -> {
            SimpReader r = reader(text);
            Command c = new Command();
            while (r.next(c)) {
                // read to the error
            }
        });
    }

    private static void assertError(String text, int line, int column, String problem) {
        SceneException e = error(text);
        assertEquals(FILE, e.file());
        assertEquals(line, e.line(), "line of: " + e.getMessage());
        assertEquals(column, e.column(), "column of: " + e.getMessage());
        assertEquals(problem, e.problem());
        String[] lines = text.split("\n", -1);
        assertEquals(lines[line - 1], e.lineText());
        assertTrue(e.getMessage().startsWith("scene.simp:" + line + ":" + column + ": " + problem), e.getMessage());
    }

    private static double[] triple(Command c) {
        return new double[] {c.number(0), c.number(1), c.number(2)};
    }

    // ---- accepted forms ------------------------------------------------------------------------

    @Test
    void bracesPushAndPop() throws SceneException {
        assertEquals(Kind.PUSH, parse("{").kind());
        assertEquals(Kind.POP, parse("}").kind());
        assertEquals(Kind.PUSH, parse("\t  {  \t").kind());
    }

    @ParameterizedTest
    @ValueSource(strings = {"translate 1 -2 3", "translate 1, -2, 3", "translate 1,-2,3", "translate\t1 ,\t-2,  3 \t",
        "translate 1.0 -2e0 +3", "translate 1 -2 3\r", "  translate 1 -2 3"})
    void translateAcceptsBlanksAndCommasMixed(String line) throws SceneException {
        Command c = parse(line);
        assertEquals(Kind.TRANSLATE, c.kind());
        assertArrayEquals(new double[] {1, -2, 3}, triple(c));
    }

    @Test
    void scaleReadsEveryNumberSpelling() throws SceneException {
        Command c = parse("scale -1.5 .3 2e3");
        assertEquals(Kind.SCALE, c.kind());
        assertArrayEquals(new double[] {-1.5, 0.3, 2000}, triple(c));
        assertArrayEquals(new double[] {4, 5, 120}, triple(parse("scale +4 5. 1.2E2")));
        assertArrayEquals(new double[] {0, -0.25, 1e-3}, triple(parse("scale 00 -.25e0 1e-3")));
    }

    @Test
    void rotateReadsAxisAndAngle() throws SceneException {
        Command c = parse("rotate Y -22.5");
        assertEquals(Kind.ROTATE, c.kind());
        assertEquals(Axis.Y, c.axis());
        assertEquals(-22.5, c.angle());
        assertEquals(Axis.X, parse("rotate X, 90").axis());
        assertEquals(Axis.Z, parse("\trotate\tZ\t45").axis());
    }

    @Test
    void lineReadsTwoPoints() throws SceneException {
        Command c = parse("line (1, 2, 3) (4, 5, 6)");
        assertEquals(Kind.LINE, c.kind());
        assertEquals(2, c.vertexCount());
        assertFalse(c.colored());
        assertEquals(3, c.coordinate(0, 2));
        assertEquals(4, c.coordinate(1, 0));
        assertEquals(1, c.color(1, 1), "a vertex without colour is white");
    }

    @Test
    void pointsMayBeSpacedOrPacked() throws SceneException {
        Command c = parse("polygon ( 1 , 2 , 3 )(4 5 6),(7,8,9)");
        assertEquals(Kind.POLYGON, c.kind());
        assertEquals(9, c.coordinate(2, 2));
        assertEquals(5, c.coordinate(1, 1));
    }

    @Test
    void polygonReadsThreePoints() throws SceneException {
        Command c = parse("polygon (0.0, 0.0, 1.0) (1.0, 1.0, 1.0) (0.0, 1.0, 1.0) ");
        assertEquals(3, c.vertexCount());
        assertEquals(1, c.coordinate(1, 0));
        assertEquals(1, c.coordinate(2, 1));
    }

    @Test
    void verticesMayCarryColours() throws SceneException {
        Command c = parse("polygon (0,0,0) (1,0,0) (1,0,0) (0,1,0) (0,1,0) (0,0,1)");
        assertTrue(c.colored());
        assertEquals(1, c.coordinate(1, 0));
        assertEquals(1, c.color(0, 0));
        assertEquals(1, c.color(1, 1));
        assertEquals(1, c.color(2, 2));
        assertEquals(0, c.color(2, 0));
        Command line = parse("line (0,0,0) (0.5,0.25,1) (1,1,1) (0,0,0)");
        assertEquals(0.25, line.color(0, 1));
        assertEquals(1, line.coordinate(1, 0));
    }

    @ParameterizedTest
    @ValueSource(strings = {"file \"cube\"", "file cube", "file \t\"cube\"  ", "file\tcube\t"})
    void fileTakesQuotedOrBareName(String line) throws SceneException {
        Command c = parse(line);
        assertEquals(Kind.FILE, c.kind());
        assertEquals("cube", c.fileName());
    }

    @Test
    void quotedFileNameMayHoldBlanks() throws SceneException {
        assertEquals("my cube", parse("file \"my cube\"").fileName());
    }

    @Test
    void styleCommands() throws SceneException {
        assertEquals(Kind.WIRE, parse("wire").kind());
        assertEquals(Kind.FILLED, parse("  filled \t").kind());
    }

    @Test
    void blankAndCommentLinesAreSkippedButCounted() throws SceneException {
        SimpReader r = reader("# comment\n\n   \t\n\t# indented comment\r\nwire\r\n\n");
        Command c = new Command();
        assertTrue(r.next(c));
        assertEquals(Kind.WIRE, c.kind());
        assertEquals(5, r.lineNumber());
        assertFalse(r.next(c));
        assertEquals(6, r.linesRead());
    }

    @Test
    void lastLineNeedsNoLineBreak() throws SceneException {
        SimpReader r = reader("{\n}");
        Command c = new Command();
        assertTrue(r.next(c));
        assertTrue(r.next(c));
        assertEquals(Kind.POP, c.kind());
        assertFalse(r.next(c));
    }

    @Test
    void byteOrderMarkIsIgnored() throws SceneException {
        byte[] text = "\uFEFFwire\n".getBytes(StandardCharsets.UTF_8);
        Command c = new Command();
        assertTrue(SimpReader.of(FILE, text).next(c));
        assertEquals(Kind.WIRE, c.kind());
    }

    @Test
    void readsEveryCommandOfALongFileInOrder() throws SceneException {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < 5000; i++) {
            sb.append("translate ").append(i).append(" 0 0\n");
        }
        SimpReader r = reader(sb.toString());
        Command c = new Command();
        List<Double> seen = new ArrayList<>();
        while (r.next(c)) {
            seen.add(c.number(0));
        }
        assertEquals(5000, seen.size());
        assertEquals(4999.0, seen.get(4999));
    }

    // ---- errors: each names file, line, column, the line and what was expected -------------------

    @Test
    void unknownCommand() {
        assertError("# c\n\n  scal 1 2 3", 3, 3, "unknown command 'scal' (did you mean 'scale'?)"
                + EXPECTED_COMMANDS);
    }

    @Test
    void commandsAreCaseSensitive() {
        assertError("Scale 1 2 3", 1, 1, "unknown command 'Scale' (did you mean 'scale'? commands are case-sensitive)"
                + EXPECTED_COMMANDS);
    }

    /** A bare name followed by more words, as a name with blanks written bare reads: it is told to quote them. */
    @Test
    void aBareNameWithBlanksIsToldToQuoteIt() {
        assertError("file my cube", 1, 9, "expected the end of the line, found 'cube' (a name with blanks in it is"
                + " quoted: file \"my cube\")");
        assertError("obj\tbig  teapot ", 1, 10, "expected the end of the line, found 'teapot ' (a name with blanks in"
                + " it is quoted: obj \"big  teapot\")");
    }

    /** Points or numbers on a line of their own, their command left out: told so, not "did you mean '{'". */
    @Test
    void numbersWithoutACommandAreToldSo() {
        String problem = " (these numbers have no command: a line starts with its command, as polygon (x, y, z)"
                + " (x, y, z) (x, y, z) does)" + EXPECTED_COMMANDS;
        assertError("(0,0,-10) (50,50,-10)", 1, 1, "unknown command '('" + problem);
        assertError("  -5 0 0", 1, 3, "unknown command '-5'" + problem);
        assertError("( 2.5, 0, 0)", 1, 1, "unknown command '('" + problem);
        assertError("(", 1, 1, "unknown command '(' (did you mean '{'?)" + EXPECTED_COMMANDS);
    }

    /** Another language's word for a command, near no SIMP word in spelling: the SIMP word is named. */
    @Test
    void anotherLanguagesWordForACommandIsToldTheSimpWord() {
        assertError("include \"cube\"", 1, 1, "unknown command 'include' (SIMP's word for that is 'file')"
                + EXPECTED_COMMANDS);
        assertError("  pushMatrix", 1, 3, "unknown command 'pushMatrix' (SIMP's word for that is '{')"
                + EXPECTED_COMMANDS);
        assertError("pop", 1, 1, "unknown command 'pop' (SIMP's word for that is '}')" + EXPECTED_COMMANDS);
        assertError("triangle (0,0,0) (1,0,0) (0,1,0)", 1, 1, "unknown command 'triangle' (SIMP's word for that is"
                + " 'polygon')" + EXPECTED_COMMANDS);
        assertError("// the house", 1, 1, "unknown command '//' (a comment starts with '#' here, not with '//')"
                + EXPECTED_COMMANDS);
        assertError("; the house", 1, 1, "unknown command ';' (a comment starts with '#' here, not with ';')"
                + EXPECTED_COMMANDS);
        assertError("color 1 0 0", 1, 1, "unknown command 'color' (a colour is no command: a vertex carries its own in"
                + " its point, (x, y, z, r, g, b), and in a lit scene surface r g b gives the colour of the vertices"
                + " after it)" + EXPECTED_COMMANDS);
    }

    @Test
    void aMistypedCommandGetsTheNearestOneSuggested() {
        assertError("Polygon (0, 0, 0) (1, 0, 0) (0, 1, 0)", 1, 1, "unknown command 'Polygon' (did you mean 'polygon'? "
                + "commands are case-sensitive)" + EXPECTED_COMMANDS);
        assertError("frobnicate 1", 1, 1, "unknown command 'frobnicate'" + EXPECTED_COMMANDS);
    }

    /**
     * A name is suggested only when it is plausibly what was meant: a short
     * word is near no command, and '{' or '}' are suggested only for another
     * bracket.
     */
    @Test
    void aSuggestionIsMadeOnlyForAPlausibleMiss() {
        assertError("wire\nx 1", 2, 1, "unknown command 'x'" + EXPECTED_COMMANDS);
        assertError("wire\n, 1", 2, 1, "unknown command ','" + EXPECTED_COMMANDS);
        assertError("wire\nl 1", 2, 1, "unknown command 'l'" + EXPECTED_COMMANDS);
        assertError("wire\nab", 2, 1, "unknown command 'ab'" + EXPECTED_COMMANDS);
        assertError("wire\n[", 2, 1, "unknown command '[' (did you mean '{'?)" + EXPECTED_COMMANDS);
        assertError("wire\n)", 2, 1, "unknown command ')' (did you mean '}'?)" + EXPECTED_COMMANDS);
        assertError("wire\nob \"m\"", 2, 1, "unknown command 'ob' (did you mean 'obj'?)" + EXPECTED_COMMANDS);
        assertError("wire\nfiel \"m\"", 2, 1, "unknown command 'fiel' (did you mean 'file'?)" + EXPECTED_COMMANDS);
    }

    /** A model given where a scene is wanted (render --scene t1.obj) is told how a model is drawn. */
    @Test
    void aModelReadAsASceneIsToldHowAModelIsDrawn() {
        SceneException e = assertThrows(SceneException.class, () -> {
            SimpReader r = SimpReader.of(Path.of("t1.obj"), "# a triangle\nv 0 0 0\nv 1 0 0\n".getBytes(StandardCharsets.UTF_8));
            while (r.next(new Command())) {
                // read to the error
            }
        });
        assertEquals("unknown command 'v': t1.obj is an .obj model, not a scene; a model is drawn from a scene file, a"
                + " .simp file holding the line obj \"t1\" after the camera, light and surface lines a lit scene needs"
                + " (docs/simp.md, Lit scenes)", e.problem());
        assertEquals(2, e.line());
        assertError("f 1 2 3", 1, 1, "unknown command 'f': this file holds an .obj model's lines, not a scene's (save it"
                + " as scene.obj); a model is drawn from a scene file, a .simp file holding the line obj \"scene\" after"
                + " the camera, light and surface lines a lit scene needs (docs/simp.md, Lit scenes)");
        // after a command of a scene, 'v' is a mistake in the scene
        assertTrue(error("wire\nv 1").problem().startsWith("unknown command 'v'; expected {"));
    }

    /**
     * A character that shows nothing is named where it stands: a byte order
     * mark inside a file (cat a.simp b.simp), a non-breaking space, a form
     * feed after a number.
     */
    @Test
    void invisibleCharactersAreNamed() {
        assertError("wire\n\uFEFFwire", 2, 1, "unknown command '\uFEFFwire', which holds a byte order mark (U+FEFF ZERO"
                + " WIDTH NO-BREAK SPACE) before 'wire': delete it (a file's byte order mark is left there when files are"
                + " joined, as cat a.simp b.simp joins them)");
        assertError("translate\u00A01 0 0", 1, 1, "unknown command 'translate\u00A01', which holds a non-breaking space"
                + " (U+00A0 NO-BREAK SPACE) after 'translate': use a plain space");
        SceneException e = error("translate 3\f 1 0");
        assertEquals("expected a number, found '3 ', which holds a form feed (U+000C FORM FEED (FF)) after '3': use a"
                + " plain space", e.problem());
        assertEquals(11, e.column());
        assertTrue(e.getMessage().contains("\n    translate 3  1 0\n"), "no form feed printed: " + e.getMessage());
        assertError("translate 1 0\u00A00", 1, 13, "expected a number, found '0\u00A00', which holds a non-breaking space"
                + " (U+00A0 NO-BREAK SPACE) after '0': use a plain space");
    }

    /**
     * After a complete command and after an axis, what looks like a blank
     * and is not is named too, not only quoted: the quote shows a space.
     */
    @Test
    void invisibleCharactersAfterACommandOrAnAxisAreNamed() {
        String nbsp = ", which holds a non-breaking space (U+00A0 NO-BREAK SPACE)";
        assertError("polygon (-50,-50,-50) (50,-50,-50) (0,50,-50)\u00A0", 1, 46,
                "expected the end of the line, found '\u00A0'" + nbsp + ": use a plain space");
        assertError("{\u00A0", 1, 2, "expected the end of the line, found '\u00A0'" + nbsp + ": use a plain space");
        assertError("file \"caf\u00E9\" \u00A0x", 1, 13, "expected the end of the line, found '\u00A0x'" + nbsp
                + " before 'x': use a plain space");
        assertError("translate 1 0 0 \u00A0", 1, 17, "expected the end of the line, found '\u00A0'" + nbsp
                + ": use a plain space");
        assertError("rotate X\u00A030", 1, 8, "expected an axis X, Y or Z (upper case), found 'X\u00A030'" + nbsp
                + " after 'X': use a plain space");
        assertError("polygon (0,0,0) (1,0,0) (0,1,0)\f", 1, 32, "expected the end of the line, found ' ', which holds"
                + " a form feed (U+000C FORM FEED (FF)): use a plain space");
    }

    /**
     * A line of nothing but form feeds and blanks (an editor's page break)
     * is blank, as SPEC ignores blank lines and the .obj reader passes it
     * over; within a command a form feed is still named.
     */
    @Test
    void aLineOfFormFeedsIsBlank() throws SceneException {
        SimpReader r = reader("\f\nwire\n \f\t\f \n\f\n");
        Command c = new Command();
        assertTrue(r.next(c));
        assertEquals(Kind.WIRE, c.kind());
        assertEquals(2, r.lineNumber());
        assertFalse(r.next(c));
        assertEquals(4, r.linesRead());
        // the message shows the form feed as a space, so that no terminal moves its cursor
        assertError("\fwire", 1, 1, "unknown command ' wire', which holds a form feed (U+000C FORM FEED (FF)) before"
                + " 'wire': use a plain space");
    }

    /**
     * A word that is 'filled' misspelt or cut short alone on a line is told
     * 'filled', not 'file', which takes a name; with a name after it, 'file'.
     */
    @Test
    void aMisspeltStyleWordIsToldFilled() {
        String all = "; expected " + Keywords.all();
        assertError("fill", 1, 1, "unknown command 'fill' (did you mean 'filled'?)" + all);
        assertError("filed", 1, 1, "unknown command 'filed' (did you mean 'filled'?)" + all);
        assertError("fill \"cube\"", 1, 1, "unknown command 'fill' (did you mean 'file'?)" + all);
        assertError("lite 1 1 1 1 0", 1, 1, "unknown command 'lite' (did you mean 'line'?)" + all);
    }

    /** A name closed by a curly quote is told which character it is and what to write. */
    @Test
    void aNameClosedByACurlyQuoteIsNamed() {
        assertError("file \"cube\u201D", 1, 6, "the file name has no closing '\"' (the name, whose '\u201D' is U+201D"
                + " RIGHT DOUBLE QUOTATION MARK, not ASCII: a name is quoted with the ASCII '\"' (text copied from a PDF"
                + " or a word processor often looks right and is not): write file \"cube\")");
        assertError("file \"cube", 1, 6, "the file name has no closing '\"'");
    }

    /** up.OBJ read as a scene is told that obj "up" finds it only as up.obj. */
    @Test
    void aModelWithAnUpperCaseEndingIsToldToRenameIt() {
        SceneException e = assertThrows(SceneException.class, () -> SimpReader.of(Path.of("up.OBJ"),
                "v 0 0 0\n".getBytes(StandardCharsets.UTF_8)).next(new Command()));
        assertTrue(e.problem().contains("holding the line obj \"up\" (once the file is renamed up.obj: obj adds .obj"
                + " in lower case, and names are case-sensitive)"), e.problem());
    }

    /**
     * A carriage return alone inside a line of a file whose lines end in LF (pasted from another editor) is
     * named as the stray it is: the file's lines do not end in CR alone.
     */
    @Test
    void aStrayCarriageReturnInALineOfALineFeedFileIsNamedAsOne() {
        SceneException e = error("line (0,0,-10)\r(50,50,-10)\nwire\n");
        assertEquals(1, e.line());
        assertEquals("expected a number, found ' ' (a carriage return stands alone in this line, where it ends no line"
                + " (an LF ends this one): remove it)", e.problem());
        assertEquals("expected a number, found ' ' (a carriage return stands alone in this line, where it ends no line"
                + " (an LF ends this one): remove it)", error("wire\r\nline (0,0,-10)\r(50,50,-10)\r\n").problem());
    }

    @Test
    void linesEndingInACarriageReturnAloneAreNamedSo() {
        SceneException e = error("scale 1 2 3\rwire\r");
        assertEquals("expected a number, found '3 wire' (this file's lines end in a carriage return alone, so it reads "
                + "as one line: save it with LF or CR LF line ends)", e.problem());
        assertEquals(11, e.column());
        assertEquals(List.of("    scale 1 2 3 wire", "              ^"), e.getMessage().lines().skip(1).toList());
    }

    @Test
    void tooFewNumbers() {
        assertError("translate 1 2", 1, 14, "wrong number of arguments: translate takes 3 numbers, found 2 numbers");
    }

    @Test
    void tooManyNumbers() {
        assertError("scale 1 2 3 4", 1, 13, "wrong number of arguments: scale takes 3 numbers, found 4 numbers");
    }

    /**
     * Commas between digits outside a point's parentheses that, read as
     * decimal points, would make a count the command takes: a hint, as SIMP
     * reads each as two numbers. Commas within points get none.
     */
    @Test
    void aDecimalCommaGetsAHint() {
        assertError("translate 1,5 0 0", 1, 17, "wrong number of arguments: translate takes 3 numbers, found 4 numbers "
                + "(a comma separates two numbers: one and a half is 1.5, not 1,5)");
        assertError("translate 1,5 0 0 7", 1, 17, "wrong number of arguments: translate takes 3 numbers, found 5 numbers");
        assertError("polygon (0,0,-1) (1,0,-1) (0,1,-1) (1 1 -1) (2 2 -1) (3 3 -1) (4 4 -1)", 1, 64,
                "wrong number of arguments: polygon takes 9 numbers (3 points) or 18 (3 points, each followed by its "
                + "colour), found 21 numbers (a polygon is one triangle: draw a shape of more points as several "
                + "triangles, or as faces of an .obj model)");
    }

    @Test
    void noArguments() {
        assertError("scale   ", 1, 9, "wrong number of arguments: scale takes 3 numbers, found none");
    }

    @Test
    void tooFewPoints() {
        assertError("polygon (0,0,0) (1,0,0)", 1, 24, "wrong number of arguments: polygon takes 9 numbers (3 points) or 18 (3 points, each followed by its colour), found 6 numbers");
    }

    @Test
    void tooManyPoints() {
        assertError("line (0,0,0) (1,0,0) (1,1,1) (0,1,0) (2,2,2)", 1, 39, "wrong number of arguments: line takes 6 numbers (2 points) or 12 (2 points, each followed by its colour), found 15 numbers");
    }

    @Test
    void pointWithTwoNumbers() {
        assertError("line (0, 0) (1, 1, 1)", 1, 22, "wrong number of arguments: line takes 6 numbers (2 points) or 12 (2 points, each followed by its colour), found 5 numbers"
                + " (its 2 points hold 2 and 3 numbers: a point is 3 numbers, x y z, or 6 with its colour, x y z r g b)");
    }

    @Test
    void pointWithFourNumbers() {
        assertError("line (0 0 0 0) (1 1 1)", 1, 23, "wrong number of arguments: line takes 6 numbers (2 points) or 12 (2 points, each followed by its colour), found 7 numbers"
                + " (its 2 points hold 4 and 3 numbers: a point is 3 numbers, x y z, or 6 with its colour, x y z r g b)");
    }

    @Test
    void colourOnSomeVerticesOnly() {
        assertError("line (0,0,0) (1,0,0) (1,1,1)", 1, 29, "wrong number of arguments: line takes 6 numbers (2 points) or 12 (2 points, each followed by its colour), found 9 numbers");
    }

    @Test
    void numberThatDoesNotParse() {
        assertError("translate 1 x 3", 1, 13, "expected a number, found 'x'");
    }

    @Test
    void aNonAsciiCharacterInANumberIsNamed() {
        assertError("translate 1 \u20132 3", 1, 13, "expected a number, found '\u20132', whose '\u2013' is U+2013 EN DASH,"
                + " not ASCII: a number is written with the ASCII digits, '-', '+', '.' and 'e' (text copied from a PDF"
                + " or a word processor often looks right and is not)");
    }

    /**
     * A polygon of three points, only some with a colour, is told what each point holds, not that a polygon is
     * one triangle: its count of numbers is that of four points, but it writes three.
     */
    @Test
    void aPolygonOfThreePointsSomeColouredIsToldWhatEachHolds() {
        String takes = "wrong number of arguments: polygon takes 9 numbers (3 points) or 18 (3 points, each followed by"
                + " its colour), found ";
        String point = "numbers: a point is 3 numbers, x y z, or 6 with its colour, x y z r g b; either every point has"
                + " its colour or none has)";
        assertError("polygon (0,0,-10,1,0,0) (50,0,-10) (0,50,-10)", 1, 46, takes + "12 numbers (its 3 points hold 6,"
                + " 3 and 3 " + point);
        assertError("polygon (0,0,-10,(1,0,0)) (5,0,-10,(0,1,0)) (0,5,-10)", 1, 54, takes + "15 numbers (its 3 points"
                + " hold 6, 6 and 3 " + point);
        assertError("line (0,0,-10,1,0,0) (50,50,-10)", 1, 33, "wrong number of arguments: line takes 6 numbers"
                + " (2 points) or 12 (2 points, each followed by its colour), found 9 numbers (its 2 points hold 6 and 3 "
                + point);
    }

    /** Points in brackets of another kind, as other languages write lists: how a point is written. */
    @Test
    void aPointInSquareOrCurlyBracketsIsToldToUseParentheses() {
        assertError("polygon [0,0,-10] [50,0,-10] [0,50,-10]", 1, 9, "expected a number, found '[0' (a point is written"
                + " in parentheses, (x, y, z): '[' is no separator)");
        assertError("line {0,0,-10} {5,5,-10}", 1, 6, "expected a number, found '{0' (a point is written in parentheses,"
                + " (x, y, z): '{' is no separator)");
    }

    /** An angle written against its axis, "Y30": the two words are named, not only what an axis is. */
    @Test
    void anAngleStuckToItsAxisIsToldToStandApart() {
        assertError("rotate Y30", 1, 8, "expected an axis X, Y or Z (upper case), found 'Y30': the axis and the angle"
                + " are two words, with a blank between them: write rotate Y 30");
        assertError("rotate z-45.5", 1, 8, "expected an axis X, Y or Z (upper case), found 'z-45.5': the axis and the"
                + " angle are two words, with a blank between them: write rotate Z -45.5");
        assertError("rotate XY 30", 1, 8, "expected an axis X, Y or Z (upper case), found 'XY'");
    }

    @Test
    void aPolygonOfFourPointsIsToldItIsATriangle() {
        assertError("polygon (0,0,0) (1,0,0) (1,1,0) (0,1,0)", 1, 40, "wrong number of arguments: polygon takes 9 numbers"
                + " (3 points) or 18 (3 points, each followed by its colour), found 12 numbers (a polygon is one"
                + " triangle: draw a shape of more points as several triangles, or as faces of an .obj model)");
    }

    /** A unit on a number, as a student writes it: which number was meant, and that numbers take none. */
    @Test
    void aUnitStuckToANumberIsNamedAndTheNumberGiven() {
        String noUnit = "a number takes no unit (an angle is in degrees, a length in world units)";
        assertError("rotate Z 45deg", 1, 10, "expected a number, found '45deg', the number 45 with 'deg' stuck to it: "
                + noUnit + ": write 45");
        assertError("translate 10px 0 0", 1, 11, "expected a number, found '10px', the number 10 with 'px' stuck to"
                + " it: " + noUnit + ": write 10");
        assertError("rotate X 1.5rad", 1, 10, "expected a number, found '1.5rad', the number 1.5 with 'rad' stuck"
                + " to it: " + noUnit + ": 1.5 radians is 85.943669 degrees");
        assertError("rotate Y 30 degrees", 1, 13, "expected the end of the line, found 'degrees' (" + noUnit
                + ": leave 'degrees' out)");
        assertError("polygon (0;0;-1) (1;0;-1) (0;1;-1)", 1, 10, "expected a number, found '0;0;-1': ';' separates"
                + " nothing here; blanks, commas and parentheses separate numbers");
    }

    /**
     * A unit word standing after a number where another number is wanted (inside a point's brackets, between a
     * transform's numbers) is told as after the line's last number; a word that is no unit, or a unit word after
     * no number, is not.
     */
    @Test
    void aUnitWordBetweenNumbersIsToldToBeLeftOut() {
        String noUnit = "a number takes no unit (an angle is in degrees, a length in world units)";
        assertError("polygon (0 0 -50 deg) (10,0,-50) (0,10,-50)", 1, 18, "expected a number, found 'deg' (" + noUnit
                + ": leave 'deg' out)");
        assertError("translate 10 px 0 0", 1, 14, "expected a number, found 'px' (" + noUnit + ": leave 'px' out)");
        assertError("scale 2, 2., units 2", 1, 14, "expected a number, found 'units' (" + noUnit
                + ": leave 'units' out)");
        assertError("polygon (0,0,-50) (10,0,-50) (0,10,-50) (1,0,0) red", 1, 49, "expected a number, found 'red'");
        assertError("rotate Z deg", 1, 10, "expected a number, found 'deg'");
    }

    @Test
    void numberWithTwoPoints() {
        assertError("\ttranslate 1 2.3.4 3", 1, 14, "expected a number, found '2.3.4'");
    }

    @Test
    void notANumberIsRefused() {
        assertError("scale NaN 1 1", 1, 7, "expected a number, found 'NaN'");
    }

    @Test
    void infinityIsRefused() {
        assertError("scale 1 Infinity 1", 1, 9, "expected a number, found 'Infinity'");
    }

    @Test
    void overflowIsRefused() {
        assertError("scale 1e999 1 1", 1, 7, "number out of range: '1e999'");
    }

    @Test
    void numbersNeedSeparators() {
        assertError("translate 1 2-3", 1, 13, "expected a number, found '2-3'");
    }

    @Test
    void lowerCaseAxis() {
        assertError("rotate x 30", 1, 8, "expected an axis X, Y or Z (upper case), found 'x'");
    }

    @Test
    void unknownAxis() {
        assertError("rotate W 30", 1, 8, "expected an axis X, Y or Z (upper case), found 'W'");
    }

    @Test
    void rotateWithoutAngle() {
        assertError("rotate X", 1, 9, "rotate takes an axis and an angle in degrees, found no angle");
    }

    @Test
    void trailingTextAfterStyle() {
        assertError("wire x", 1, 6, "expected the end of the line, found 'x'");
    }

    @Test
    void trailingTextAfterPolygon() {
        assertError("polygon (0,0,0) (1,0,0) (0,1,0) junk", 1, 33, "expected the end of the line, found 'junk'");
    }

    /** A comment after a command, as many formats allow, is part of the command in SIMP: the error says so. */
    @Test
    void aCommentAfterACommandIsNamedForWhatItIs() {
        String hint = TrailingComment.HINT;
        assertError("polygon (0,0,0) (1,0,0) (0,1,0) # a triangle", 1, 33,
                "expected the end of the line, found '# a triangle'" + hint);
        assertError("wire # outlines", 1, 6, "expected the end of the line, found '# outlines'" + hint);
        assertError("translate 1 2 # and z", 1, 15, "expected a number, found '#'" + hint);
        assertError("polygon (0,0,0) (1,0,0) (0,1,0) junk", 1, 33, "expected the end of the line, found 'junk'");
    }

    @Test
    void trailingTextAfterBrace() {
        assertError("{ x", 1, 3, "expected the end of the line, found 'x'");
    }

    @Test
    void commasAndParenthesesOnlySeparate() throws SceneException {
        assertArrayEquals(new double[] {1, 2, 3}, triple(parse("translate 1 2 3,")));
        assertArrayEquals(new double[] {1, 2, 3}, triple(parse("translate (1, 2, 3)")));
        assertArrayEquals(new double[] {1, 2, 3}, triple(parse("translate(1,2,3)")));
    }

    @Test
    void theCourseWritesAColourInsideThePoint() throws SceneException {
        for (String line : new String[] {"polygon (0, 0, 0, 1, 0, 0) (1, 0, 0, 0, 1, 0) (0, 1, 0, 0, 0, 1)",
            "polygon (0, 0, 0, (1, 0, 0)) (1, 0, 0, (0, 1, 0)) (0, 1, 0, (0, 0, 1))",
            "polygon (0 0 0) (1 0 0) (1 0 0) (0 1 0) (0 1 0) (0 0 1)",
            "polygon 0 0 0 1 0 0 1 0 0 0 1 0 0 1 0 0 0 1"}) {
            Command c = parse(line);
            assertTrue(c.colored(), line);
            assertEquals(1, c.coordinate(1, 0), line);
            assertEquals(1, c.coordinate(2, 1), line);
            assertEquals(1, c.color(0, 0), line);
            assertEquals(1, c.color(1, 1), line);
            assertEquals(1, c.color(2, 2), line);
            assertEquals(0, c.color(2, 0), line);
        }
    }

    @Test
    void coloursOutsideZeroToOneAreClampedAndMarked() throws SceneException {
        Command c = parse("line (0, 0, 0, 2, -1, 0.5) (1, 1, 1, 0, 0, 0)");
        assertTrue(c.clamped);
        assertEquals(1, c.color(0, 0));
        assertEquals(0, c.color(0, 1));
        assertEquals(0.5, c.color(0, 2));
        assertFalse(parse("line (0, 0, 0, 1, 0, 0.5) (1, 1, 1, 0, 0, 0)").clamped);
    }

    @Test
    void litCommandsReadTheirNumbers() throws SceneException {
        Command camera = parse("camera -1 -1 1 1 -0.1 -200");
        assertEquals(Kind.CAMERA, camera.kind());
        assertEquals(6, camera.numberCount());
        assertEquals(-0.1, camera.number(4));
        assertEquals(5, parse("light 1, 1, 1, 1, 0").numberCount());
        assertEquals(0, parse("depth 0 -200 (0 0 0)").number(4));
        assertEquals(3, parse("surface 1 0.5 0.5").numberCount());
        assertEquals(5, parse("surface 1 0.5 0.5 0.4 16").numberCount());
        assertEquals("dummy", parse("obj \"dummy\"").fileName());
        assertEquals(Kind.GOURAUD, parse("gouraud").kind());
        assertError("surface 1 1 1 1", 1, 16, "wrong number of arguments: surface takes 3 or 5 numbers, found 4 numbers");
        assertError("camera -1 -1 1 1 -0.1", 1, 22, "wrong number of arguments: camera takes 6 numbers, found 5 numbers");
    }

    @Test
    void commandWordMustBeFollowedByBlank() {
        assertError("rotate(X 3)", 1, 7, "expected a blank after 'rotate', found '('");
    }

    @Test
    void unclosedQuote() {
        assertError("file \"cube", 1, 6, "the file name has no closing '\"'");
    }

    @Test
    void emptyFileName() {
        assertError("file \"\"", 1, 6, "expected a file name, found an empty one");
    }

    @Test
    void garbageInsteadOfAPoint() {
        assertError("line (0,0,0) x", 1, 14, "expected a number, found 'x'");
    }

    @Test
    void messageShowsTheLineAndACaret() {
        SceneException e = error("wire\n\ttranslate 1 x 3");
        assertEquals("scene.simp:2:14: expected a number, found 'x'\n"
                + "     translate 1 x 3\n"
                + "                 ^", e.getMessage());
    }
}
