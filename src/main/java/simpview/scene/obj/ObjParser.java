package simpview.scene.obj;

import simpview.stage.ObjFace;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.IntPredicate;
import simpview.scene.FileChecksum;
import simpview.scene.FileProblem;
import simpview.scene.MemoryAdvice;
import simpview.scene.SceneException;
import simpview.scene.text.CopiedText;
import simpview.scene.text.DecimalCommas;
import simpview.scene.text.DecimalParser;
import simpview.scene.text.LineSource;
import simpview.scene.text.NotText;
import simpview.scene.text.TrailingComment;
import java.util.Locale;

/**
 * Reads the lines of one .obj file straight from the bytes of its buffer (no
 * regular expressions, no String per number) and hands each face to a sink
 * as soon as its line is read; optionally records the faces for a model.
 *
 * <p>Lines are split as SIMP lines are: blanks (spaces, tabs), commas and
 * parentheses all separate. The keyword (the first word, any case) decides:
 * {@code v}, {@code vn} and {@code f} are read, every other line ({@code vt}
 * included) is ignored, unless its word is one of those with a character
 * beyond ASCII stuck to it (an error naming it); a face's texture index is
 * read but names nothing to check.
 */
final class ObjParser {

    private static final int MOST_NUMBERS = 7;
    private static final String VERTEX_FORMS = "v takes 3, 4, 6 or 7 numbers (x y z, x y z w, x y z r g b"
            + " or x y z w r g b)";
    private static final String REFERENCE_FORMS = "a vertex reference (v, v/vt, v//vn or v/vt/vn)";
    private static final ObjSink NOWHERE = face -> { };
    /** What an .obj file is, for {@link NotText}'s messages. */
    private static final String KIND = "an .obj file";
    /** More digits than this name nothing (an array holds fewer than 10^10 elements). */
    private static final int MOST_INDEX_DIGITS = 12;

    private final LineSource source;
    private final DecimalParser decimal = new DecimalParser();
    private final ObjVertices vertices = new ObjVertices();
    private final ObjFace face = new ObjFace();
    private final double[] numbers = new double[MOST_NUMBERS];
    private final int[] numberStarts = new int[MOST_NUMBERS];
    private ObjFaceList recorder;
    private int[] vertexRefs = new int[16];
    private int[] normalRefs = new int[16];
    private int faceCount;
    /** True when a number of the line just read is followed straight by a comma (maybe a decimal comma). */
    private boolean commaAfterNumber;
    /** The warning for the first v line whose commas look like decimal commas, or null. */
    private String decimalCommas;
    /** Lines that are neither blank, a comment, v, vn nor f (ignored): for the warning of a file without faces. */
    private int otherLines;
    /** The first of them: its line and first word. */
    private int firstOtherLine;
    private String firstOtherWord;
    /** The l lines (polylines) and p lines (points) among them, and the first one's line. */
    private int polylines;
    private int points;
    private int firstUndrawnLine;
    /** Faces of 4 vertices or more, some without vn, whose first three lie on one line; the first one's line. */
    private int inLineStarts;
    private int firstInLineStart;
    /** Faces whose vertices lie on one line or coincide (no area); the first one's line. */
    private int flatFaces;
    private int firstFlatFace;
    /** Faces that use a normal of zero length (vn 0 0 0); the first one's line, and that normal's number (from 1). */
    private int zeroNormalFaces;
    private int firstZeroNormalFace;
    private int firstZeroNormal;
    /** Faces of 5 vertices or more that are not convex; the first one's line and size. */
    private int concaveFaces;
    private int firstConcaveFace;
    private int firstConcaveSize;
    /** Whether the model is inside out: its normals against its faces' fronts, or its fronts facing inward. */
    private final Orientation orientation = new Orientation();
    /** The value of the index just read (capped, so that it never overflows). */
    private long index;
    private byte[] b;
    private int lineStart;
    private int end;

    private ObjParser(LineSource source) {
        this.source = source;
    }

    static ObjParser open(Path file) throws SceneException {
        try {
            return new ObjParser(LineSource.open(file));
        } catch (IOException e) {
            throw new SceneException(file, 0, 0, "", "cannot open the obj file "
                    + file.toAbsolutePath().normalize() + ": " + FileProblem.of(file, e));
        }
    }

    static ObjParser of(Path file, byte[] content) {
        return new ObjParser(LineSource.of(file, content));
    }

    /** Reads a whole file into a model, with no budget. */
    static ObjModel model(ObjParser parser) throws SceneException {
        parser.record(Long.MAX_VALUE).run(NOWHERE);
        return parser.model();
    }

    /** Keeps the CRC-32C of the bytes read: the file's checksum once {@link #run} read it all. */
    ObjParser checksummed() {
        source.checksummed();
        return this;
    }

    /**
     * The checksum of the file's bytes, after a {@link #run} of a
     * {@link #checksummed} parser that read it to its end; else
     * {@link FileChecksum#NONE}.
     */
    long checksum() {
        return source.checksumOfWhole();
    }

    /** Records the faces too, up to {@code budget} bytes of arrays with the vertices. */
    ObjParser record(long budget) {
        recorder = new ObjFaceList(budget);
        return this;
    }

    /** The recorded model after a {@link #run}; null when not recording or over the budget. */
    ObjModel model() {
        return recorder != null && recorder.kept() ? recorder.model(vertices, warnings()) : null;
    }

    /**
     * Reads every line, handing each face to the sink; closes the file. A
     * line holding a byte that no UTF-8 text holds is an error
     * ({@link NotText}); a file that gave no face, a warning.
     */
    ObjCounts run(ObjSink sink) throws SceneException {
        try {
            while (source.nextLine()) {
                b = source.buffer();
                lineStart = source.lineStart();
                end = source.lineEnd();
                line(sink);
                if (source.lineNumber() % ObjReader.PROGRESS_LINES == 0) {
                    sink.progress(source.lineNumber());
                }
            }
        } catch (LineSource.LineTooLongException e) {
            throw new SceneException(file(), source.lineNumber() + 1, e.column(), "",
                    e.problem(KIND, "one v, vn or f"));
        } catch (LineSource.NotTextException e) {
            // a picture or a program renamed .obj, or text saved as UTF-16 or Latin-1: none of its bytes is shown
            NotText found = e.notText(KIND);
            throw new SceneException(file(), found.line(), found.column(), "", found.problem());
        } catch (IOException e) {
            throw new SceneException(file(), 0, 0, "", "cannot read the obj file: " + FileProblem.of(file(), e));
        } catch (OutOfMemoryError e) {
            throw outOfMemory();
        } finally {
            close();
        }
        return new ObjCounts(vertices.vertexCount, vertices.normalCount, faceCount, vertices.firstClampedColour,
                vertices.firstClampedChannel, warnings());
    }

    /** What the reading noticed that is worth a warning, each naming the file. */
    private List<String> warnings() {
        List<String> warnings = new ArrayList<>(1);
        if (decimalCommas != null) {
            warnings.add(decimalCommas);
        }
        if (faceCount == 0) {
            warnings.add(noFaces());
        } else if (polylines + points > 0) {
            warnings.add(file().getFileName() + ":" + firstUndrawnLine + ": " + undrawnKinds()
                    + " are not drawn: a model is drawn by its faces, f lines (" + undrawnCounts()
                    + " passed over, this the first; the " + count(faceCount, "face") + " drawn)");
        }
        if (flatFaces > 0) {
            warnings.add(file().getFileName() + ":" + firstFlatFace + ": this face has no area (its vertices lie on "
                    + "one line, or coincide), so, as SPEC fills a triangle of no area, it fills no pixel (in wire "
                    + "style only its edges show, along that line): remove it, or check which v lines it names"
                    + more(flatFaces));
        }
        if (zeroNormalFaces > 0) {
            warnings.add(file().getFileName() + ":" + firstZeroNormalFace + ": this face uses a normal of zero length "
                    + "(vn 0 0 0, normal " + firstZeroNormal + " as f lines number the vn lines), which SPEC cannot "
                    + "make unit length, and a zero normal gives only the ambient term, so where it is used the face "
                    + "is lit by the ambient light alone: give that vn a direction, or leave it out of the face (its "
                    + "face normal is then used)" + more(zeroNormalFaces));
        }
        if (inLineStarts > 0) {
            warnings.add(file().getFileName() + ":" + firstInLineStart + ": this face's first three vertices lie on one "
                    + "line, so its face normal, (p2 - p1) x (p3 - p1) by SPEC, is zero or made of rounding errors, and "
                    + "where a vertex has no vn it is lit by the ambient light alone or wrongly: start the face at a "
                    + "corner, or give its vertices vn normals" + more(inLineStarts));
        }
        String insideOut = orientation.warning(file().getFileName().toString());
        if (insideOut != null) {
            warnings.add(insideOut);
        }
        if (concaveFaces > 0) {
            warnings.add(file().getFileName() + ":" + firstConcaveFace + ": this face of " + firstConcaveSize
                    + " vertices is not convex, and SPEC fills a face as a fan from its first vertex, which covers "
                    + "what its outline leaves out: split it into triangles (Blender: Triangulate)" + more(concaveFaces));
        }
        return warnings;
    }

    /** "cube.obj: no f lines, so nothing is drawn (12 lines read: 8 v lines, ...)". */
    private String noFaces() {
        int lines = source.lineNumber();
        String read;
        if (lines == 0) {
            read = "the file is empty";
        } else {
            List<String> held = new ArrayList<>();
            if (vertices.vertexCount > 0) {
                held.add(count(vertices.vertexCount, "v line"));
            }
            if (vertices.normalCount > 0) {
                held.add(count(vertices.normalCount, "vn line"));
            }
            if (otherLines > 0) {
                held.add(count(otherLines, "other line") + " (the first, line " + firstOtherLine + ", starts with '"
                        + firstOtherWord + "')");
            }
            read = count(lines, "line") + " read: " + (held.isEmpty() ? "only blank lines and comments"
                    : String.join(", ", held));
        }
        return file().getFileName() + ": no f lines, so nothing is drawn (" + read + ")"
                + (polylines + points > 0 ? "; " + undrawnKinds() + " are not drawn: a model is drawn by its faces,"
                + " f lines" : "");
    }

    /** "l lines (polylines)", "p lines (points)" or both, as the file holds them. */
    private String undrawnKinds() {
        String l = "l lines (polylines)";
        String p = "p lines (points)";
        return polylines == 0 ? p : points == 0 ? l : l + " and " + p;
    }

    /** "3 l lines and 1 p line", "1 l line". */
    private String undrawnCounts() {
        List<String> kinds = new ArrayList<>(2);
        if (polylines > 0) {
            kinds.add(count(polylines, "l line"));
        }
        if (points > 0) {
            kinds.add(count(points, "p line"));
        }
        return String.join(" and ", kinds);
    }

    /** " (and 3 more faces like it)" after a warning about the first of n faces. */
    private static String more(int n) {
        return n == 1 ? "" : " (and " + (n - 1) + " more " + (n == 2 ? "face" : "faces") + " like it)";
    }

    private static String count(int n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }

    /**
     * The error when Java's memory ran out on the current line (reading the
     * model, or drawing its faces as they came): the recorded faces are let
     * go first, so that the message can be made.
     */
    private SceneException outOfMemory() {
        recorder = null;
        String soFar = counted(vertices.vertexCount, "vertex", "vertices") + " and " + counted(faceCount, "face", "faces");
        return new SceneException(file(), source.lineNumber(), 0, "",
                MemoryAdvice.outOfMemory("reading this model, at " + soFar + " so far"));
    }

    /** "1,020,100 vertices". */
    private static String counted(int n, String one, String many) {
        return String.format("%,d %s", n, n == 1 ? one : many);
    }

    private void close() {
        try {
            source.close();
        } catch (IOException e) {
            // Read only: nothing is lost.
        }
    }

    private Path file() {
        return source.path();
    }

    // ---- one line ------------------------------------------------------------------------------

    private void line(ObjSink sink) throws SceneException {
        int i = skipBlanks(lineStart);
        if (i == end) {
            return;
        }
        if (b[i] == '\f' && onlyFormFeedsAndBlanks(i)) {
            return; // a page break an editor left on a line of its own: a blank line, as in a scene
        }
        int first = b[i] | 0x20; // lower case for letters
        if (first != 'v' && first != 'f') {
            if (b[i] != '#') {
                other(i);
            }
            return;
        }
        int wordEnd = i + 1;
        while (wordEnd < end && !isSeparator(b[wordEnd])) {
            wordEnd++;
        }
        int length = wordEnd - i;
        if (length == 1) {
            if (first == 'v') {
                vertex(wordEnd);
            } else {
                face(wordEnd, sink);
            }
        } else if (length == 2 && first == 'v' && (b[i + 1] | 0x20) == 'n') {
            normal(wordEnd);
        } else {
            other(i);
        }
    }

    /** Notes an ignored line whose word starts at i (not a comment): for the warning of a file without faces. */
    private void other(int i) throws SceneException {
        copiedKeyword(i);
        otherLines++;
        if (firstOtherLine == 0) {
            firstOtherLine = source.lineNumber();
            firstOtherWord = printable(token(i));
        }
        int kind = b[i] | 0x20;
        if ((kind == 'l' || kind == 'p') && (i + 1 == end || isSeparator(b[i + 1]))) {
            if (kind == 'l') {
                polylines++;
            } else {
                points++;
            }
            if (firstUndrawnLine == 0) {
                firstUndrawnLine = source.lineNumber();
            }
        }
    }

    /** Whether the line from i on holds only form feeds and blanks (a page break on a line of its own). */
    private boolean onlyFormFeedsAndBlanks(int i) {
        while (i < end && (b[i] == '\f' || b[i] == ' ' || b[i] == '\t')) {
            i++;
        }
        return i == end;
    }

    /**
     * An error for a first word that is v, vn, vt or f with a character beyond ASCII or a form feed stuck to
     * it: "v" and a non-breaking space before the numbers, a byte order mark before "f" where two files were
     * joined, a form feed (a page break) before "v". The line looks right, and would be passed over as a kind
     * simpview does not read, leaving a vertex or a face silently missing (and a later face's index naming
     * nothing). Only a word holding such a byte is looked at, so the vt lines of a big model cost no String.
     */
    private void copiedKeyword(int i) throws SceneException {
        int wordEnd = i;
        boolean beyondAscii = false;
        while (wordEnd < end && !isSeparator(b[wordEnd])) {
            beyondAscii |= b[wordEnd] < 0 || b[wordEnd] == '\f';
            wordEnd++;
        }
        if (!beyondAscii) {
            return;
        }
        String word = text(i, wordEnd);
        int start = 0;
        while (start < word.length() && CopiedText.isInvisible(word.codePointAt(start))) {
            start += Character.charCount(word.codePointAt(start));
        }
        int letters = start;
        while (letters < word.length() && word.charAt(letters) < 0x80 && Character.isLetter(word.charAt(letters))) {
            letters++;
        }
        String keyword = word.substring(start, letters);
        boolean stuck = start > 0 || letters < word.length()
                && (word.charAt(letters) >= 0x80 || word.charAt(letters) == '\f');
        if (stuck && List.of("v", "vn", "vt", "f").contains(keyword.toLowerCase(Locale.ROOT))) {
            throw error(i, "this line's first word reads '" + printable(word) + "'"
                    + CopiedText.hint(word, "the word and what follows it are written in ASCII, a plain space between them") + " (as it is, the word is not '"
                    + keyword + "', and the line would be passed over as one simpview does not read)");
        }
    }

    private void vertex(int from) throws SceneException {
        int n = numbers(from, VERTEX_FORMS, ObjParser::vertexTakes);
        double w = 1;
        int colour = 3;
        switch (n) {
            case 3, 6 -> { }
            case 4, 7 -> {
                w = numbers[3];
                colour = 4;
            }
            default -> throw error(end, "wrong count of numbers: " + VERTEX_FORMS + ", found " + n
                    + decimalCommaHint(from, n, ObjParser::vertexTakes));
        }
        if (commaAfterNumber && decimalCommas == null) {
            noteDecimalCommas(from, n);
        }
        double x = numbers[0];
        double y = numbers[1];
        double z = numbers[2];
        if (w != 1) {
            if (w == 0) {
                throw error(numberStarts[3], "w is 0: the point (x/w, y/w, z/w) is undefined"
                        + decimalCommaHint(from, n, ObjParser::vertexTakes));
            }
            x /= w;
            y /= w;
            z /= w;
            if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
                throw error(numberStarts[3], "the point (x/w, y/w, z/w) is out of range");
            }
        }
        if (n > 4) {
            vertices.addVertex(x, y, z, numbers[colour], numbers[colour + 1], numbers[colour + 2], source.lineNumber());
        } else {
            vertices.addVertex(x, y, z);
        }
    }

    private void normal(int from) throws SceneException {
        String takes = "vn takes 3 numbers (x y z)";
        int n = numbers(from, takes, ObjParser::normalTakes);
        if (n != 3) {
            throw error(n < 3 ? end : numberStarts[3], "wrong count of numbers: " + takes + ", found " + n
                    + decimalCommaHint(from, n, ObjParser::normalTakes));
        }
        vertices.addNormal(numbers[0], numbers[1], numbers[2]);
    }

    private static boolean vertexTakes(int n) {
        return n == 3 || n == 4 || n == 6 || n == 7;
    }

    private static boolean normalTakes(int n) {
        return n == 3;
    }

    /**
     * Reads the numbers up to the end of the line into {@link #numbers}; more
     * than 7 is an error ({@code counts}: the counts the line's keyword takes,
     * for the decimal-comma hint).
     */
    private int numbers(int from, String takes, IntPredicate counts) throws SceneException {
        int n = 0;
        commaAfterNumber = false;
        for (int i = skipSeparators(from); i < end; i = skipSeparators(i)) {
            if (n == MOST_NUMBERS) {
                throw error(i, "wrong count of numbers: " + takes + ", found more than " + MOST_NUMBERS
                        + decimalCommaHint(from, n + DecimalCommas.words(b, i, end), counts));
            }
            numberStarts[n] = i;
            i = number(i);
            commaAfterNumber |= i < end && b[i] == ',';
            numbers[n++] = decimal.value();
        }
        return n;
    }


    /**
     * The SIMP reader's hint for a line of {@code found} numbers from
     * {@code from} on whose commas between digits, read as decimal points,
     * would make a count the keyword takes; else "".
     */
    private String decimalCommaHint(int from, int found, IntPredicate counts) {
        if (!commaAfterNumber) {
            return "";
        }
        int commas = DecimalCommas.count(b, from, end);
        return commas > 0 && counts.test(found - commas) ? " (" + DecimalCommas.HINT + ")" : "";
    }

    /**
     * A v line of a count it takes, whose commas between digits, read as
     * decimal points, would make another count it takes ("v 0,5 -1,0 -4,0",
     * six numbers, a position and a colour, or three): SPEC reads the line as
     * written, so this is a warning, kept for the first such line, with the
     * column of the first such number.
     */
    private void noteDecimalCommas(int from, int n) {
        int commas = DecimalCommas.count(b, from, end);
        if (commas == 0 || !vertexTakes(n - commas)) {
            return;
        }
        int comma = DecimalCommas.first(b, from, end);
        int start = comma;
        while (start > from && !isSeparator(b[start - 1])) {
            start--;
        }
        int after = comma + 1;
        while (after < end && !isSeparator(b[after])) {
            after++;
        }
        String numbersAre = switch (n) {
            case 4 -> "x y z w";
            case 6 -> "x y z r g b";
            default -> "x y z w r g b";
        };
        decimalCommas = file().getFileName() + ":" + source.lineNumber() + ":" + column(start) + ": '"
                + text(start, after) + "' is read as two numbers, so this v line's " + n + " numbers are "
                + numbersAre + " (" + DecimalCommas.HINT + "); this is the first such line";
    }

    /** A number ending at a separator or the end of the line. */
    private int number(int i) throws SceneException {
        int after = decimal.scan(b, i, end);
        if (after < 0 || (after < end && !isSeparator(b[after]))) {
            throw error(i, "expected a number, found '" + token(i) + "'" + DecimalParser.nonAsciiHint(token(i))
                    + TrailingComment.hint(b[i]) + continuationHint(i) + notFiniteHint(token(i)));
        }
        if (!Double.isFinite(decimal.value())) {
            throw error(i, "number out of range: '" + token(i) + "'");
        }
        return after;
    }

    /**
     * For a word that is how a program prints a value that is not a number or is infinite ("nan", "-nan",
     * "inf", "Infinity", and Windows' "1.#QNAN", "-1.#IND", "1.#INF"): what it means; else "". An exporter
     * writes one for a normal it could not compute (that of a face of no area) or a point gone wrong.
     */
    private static String notFiniteHint(String word) {
        String w = word.toLowerCase(Locale.ROOT);
        if (w.startsWith("-") || w.startsWith("+")) {
            w = w.substring(1);
        }
        boolean nan = w.equals("nan") || w.startsWith("1.#qnan") || w.startsWith("1.#snan") || w.startsWith("1.#ind");
        boolean inf = w.equals("inf") || w.equals("infinity") || w.startsWith("1.#inf");
        if (!nan && !inf) {
            return "";
        }
        return " (" + (nan ? "not a number" : "infinite") + ": the program that wrote the file printed a value it"
                + " could not compute, often the normal of a face of no area; every number must be finite: remove"
                + " that face, or give this line finite numbers)";
    }

    // ---- faces ---------------------------------------------------------------------------------

    private void face(int from, ObjSink sink) throws SceneException {
        int n = 0;
        boolean anyNormal = false;
        boolean everyNormal = true;
        for (int i = skipSeparators(from); i < end; i = skipSeparators(i)) {
            if (n == vertexRefs.length) {
                vertexRefs = Arrays.copyOf(vertexRefs, 2 * n);
                normalRefs = Arrays.copyOf(normalRefs, 2 * n);
            }
            int start = i;
            i = reference(i, n);
            if (i < end && !isSeparator(b[i])) {
                throw error(start, "expected " + REFERENCE_FORMS + ", found '" + token(start) + "'"
                    + TrailingComment.hint(b[start]) + copiedHint(start) + continuationHint(start));
            }
            anyNormal |= normalRefs[n] >= 0;
            everyNormal &= normalRefs[n] >= 0;
            n++;
        }
        if (n < 3) {
            throw error(end, "a face takes at least 3 vertices, found " + n);
        }
        faceCount++;
        int line = source.lineNumber();
        if (anyNormal) {
            noteZeroNormal(n, line);
        }
        if (FaceShape.noArea(vertices.positions, vertexRefs, n)) {
            if (flatFaces++ == 0) {
                firstFlatFace = line;
            }
        } else if (n > 3) {
            noteShape(n, everyNormal, line);
        }
        orientation.face(vertices.positions, vertices.vertexCount, vertices.normals, vertexRefs, normalRefs, n,
                everyNormal, line);
        if (recorder != null) {
            recorder.add(vertexRefs, normalRefs, n, anyNormal, line, vertices.modelBytes());
        }
        face.bind(vertices.positions, vertices.colours, vertices.normals, vertexRefs, normalRefs);
        face.select(0, n, line);
        sink.face(face);
    }

    /** Counts a face that uses a normal of zero length (vn 0 0 0) at one of its n vertices or more. */
    private void noteZeroNormal(int n, int line) {
        double[] normals = vertices.normals;
        for (int k = 0; k < n; k++) {
            int i = 3 * normalRefs[k];
            if (i >= 0 && normals[i] == 0 && normals[i + 1] == 0 && normals[i + 2] == 0) {
                if (zeroNormalFaces++ == 0) {
                    firstZeroNormalFace = line;
                    firstZeroNormal = normalRefs[k] + 1;
                }
                return;
            }
        }
    }

    /** Counts a face of n > 3 vertices that SPEC draws otherwise than its outline suggests ({@link FaceShape}). */
    private void noteShape(int n, boolean everyNormal, int line) {
        if (!everyNormal && FaceShape.firstThreeInLine(vertices.positions, vertexRefs)) {
            if (inLineStarts++ == 0) {
                firstInLineStart = line;
            }
        }
        if (FaceShape.namedForFan(vertices.positions, vertexRefs, n)) {
            if (concaveFaces++ == 0) {
                firstConcaveFace = line;
                firstConcaveSize = n;
            }
        }
    }

    /** Reads v, v/vt, v//vn or v/vt/vn at i into the n-th reference; returns the index just past it. */
    private int reference(int i, int n) throws SceneException {
        int start = i;
        i = index(i, start);
        vertexRefs[n] = resolve(start, i, vertices.vertexCount, "vertex", "vertices (v lines)", "vertex (v line)");
        normalRefs[n] = -1;
        if (i < end && b[i] == '/') {
            i++;
            if (i >= end || b[i] != '/') {
                i = index(i, start); // a texture index: vt lines are ignored, so it names nothing to check
                if (i >= end || b[i] != '/') {
                    return i;
                }
            }
            int vn = ++i;
            i = index(i, start);
            if (i < end && b[i] == '/') {
                // a fourth part: the form is wrong whatever the indices name, so that is said first
                throw error(start, "expected " + REFERENCE_FORMS + ", found '" + token(start) + "'");
            }
            normalRefs[n] = resolve(vn, i, vertices.normalCount, "normal", "normals (vn lines)",
                    "normal (vn line)");
        }
        return i;
    }

    /** Reads [+-]digits at i into {@link #index}; a reference starting at {@code start} without one is an error. */
    private int index(int i, int start) throws SceneException {
        boolean negative = i < end && b[i] == '-';
        if (i < end && (b[i] == '-' || b[i] == '+')) {
            i++;
        }
        int digits = i;
        long value = 0;
        for (int d; i < end && (d = b[i] - '0') >= 0 && d <= 9; i++) {
            value = 10 * value + d;
        }
        if (i == digits) {
            throw error(start, "expected " + REFERENCE_FORMS + ", found '" + token(start) + "'"
                    + TrailingComment.hint(b[start]) + copiedHint(start) + continuationHint(start));
        }
        if (i - digits > MOST_INDEX_DIGITS) {
            value = Long.MAX_VALUE; // names nothing in any file; and 19 digits could overflow
        }
        index = negative ? -value : value;
        return i;
    }

    /** The 0-based element that {@link #index}, written at b[from, to), names among {@code count} defined so far. */
    private int resolve(int from, int to, int count, String what, String defined, String one)
            throws SceneException {
        if (index == 0) {
            throw error(from, what + " index 0: indices start at 1 (or count back from -1)");
        }
        long zeroBased = index > 0 ? index - 1 : count + index;
        if (zeroBased < 0 || zeroBased >= count) {
            SceneException e = error(from, what + " index " + text(from, to) + " names nothing: " + count + " "
                    + (count == 1 ? one : defined) + " defined so far");
            if (index > count) {
                int later = definedLater(index - count, what.equals("normal"));
                if (later > 0) {
                    String keyword = what.equals("normal") ? "vn" : "v";
                    e = new SceneException(e.file(), e.line(), e.column(), e.lineText(), e.problem() + "; the file"
                            + " defines it further down, at line " + later + ", but a face names only the "
                            + keyword + " lines above it: move the " + keyword + " lines before the f lines");
                }
            }
            throw e;
        }
        return (int) zeroBased;
    }

    /**
     * For a face naming a vertex (or a normal) that is not defined yet: reads on through the rest of the file
     * to the {@code ahead}-th v (or vn) line after this one, and returns its line number; 0 when the file
     * holds none so far down, or cannot be read on. Only on the way to an error: the file is not read further.
     */
    private int definedLater(long ahead, boolean normal) {
        long found = 0;
        try {
            while (source.nextLine()) {
                b = source.buffer();
                lineStart = source.lineStart();
                end = source.lineEnd();
                int i = skipBlanks(lineStart);
                int length = 0;
                while (i + length < end && !isSeparator(b[i + length])) {
                    length++;
                }
                boolean v = (length == 1 || length == 2 && (b[i + 1] | 0x20) == 'n') && (b[i] | 0x20) == 'v';
                if (v && (length == 2) == normal && ++found == ahead) {
                    return source.lineNumber();
                }
            }
        } catch (IOException e) {
            return 0; // a line too long or not text further down: the error at hand is told without the hint
        }
        return 0;
    }

    // ---- bytes and messages --------------------------------------------------------------------

    private int skipBlanks(int i) {
        while (i < end && (b[i] == ' ' || b[i] == '\t')) {
            i++;
        }
        return i;
    }

    private int skipSeparators(int i) {
        while (i < end && isSeparator(b[i])) {
            i++;
        }
        return i;
    }

    /** Blanks, commas and parentheses separate numbers and references (digits fail the first test). */
    private static boolean isSeparator(byte c) {
        return c <= ',' && (c == ' ' || c == ',' || c == '\t' || c == '(' || c == ')');
    }

    /**
     * For an error at a word that ends the line with a '\\', alone or glued to a number ("0\\"): Wavefront
     * lets such a line go on on the next, and simpview does not (SPEC reads a model line by line, and places
     * every error on one line), so the message says so; else "".
     */
    private String continuationHint(int i) {
        int wordEnd = i;
        while (wordEnd < end && !isSeparator(b[wordEnd])) {
            wordEnd++;
        }
        return wordEnd > i && b[wordEnd - 1] == '\\' && skipBlanks(wordEnd) == end ? " (simpview does not join a"
                + " line ending in '\\' to the next: write the whole line on one line)" : "";
    }

    /** For an error at a vertex reference holding a character beyond ASCII (a zero-width space after it), its name. */
    private String copiedHint(int i) {
        return CopiedText.hint(token(i), "a vertex reference is written with the ASCII digits, '-' and '/'");
    }

    /** The token at i: up to the next separator, at most 30 bytes. */
    private String token(int i) {
        int j = i;
        while (j < end && j - i < 30 && !isSeparator(b[j])) {
            j++;
        }
        return text(i, j);
    }

    /** The text with each control character written as \\xNN: a warning never prints a NUL or an escape. */
    private static String printable(String text) {
        StringBuilder out = new StringBuilder(text.length());
        for (char c : text.toCharArray()) {
            if (c < 0x20 || c == 0x7F) {
                out.append(String.format("\\x%02X", (int) c));
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }

    private String text(int from, int to) {
        return new String(b, from, to - from, StandardCharsets.UTF_8);
    }

    /**
     * An error at byte index i of the current line (a line of UTF-8 text: a
     * file that is not is stopped as its line is read, {@link NotText}).
     */
    private SceneException error(int i, String problem) {
        return new SceneException(file(), source.lineNumber(), column(i), text(lineStart, end),
                problem + source.lineEndHint());
    }

    /** The 1-based column of byte index i of the current line (one past its end at most). */
    private int column(int i) {
        return text(lineStart, Math.min(i, end)).length() + 1;
    }

}
