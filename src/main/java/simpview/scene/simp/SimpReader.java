package simpview.scene.simp;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import simpview.geometry.Axis;
import simpview.scene.FileChecksum;
import simpview.scene.FileProblem;
import simpview.scene.SceneException;
import simpview.scene.simp.Command.Kind;
import simpview.scene.simp.Command.Shape;
import simpview.scene.text.CopiedText;
import simpview.scene.text.DecimalCommas;
import simpview.scene.text.DecimalParser;
import simpview.scene.text.LineSource;
import simpview.scene.text.NotText;
import simpview.scene.text.StuckUnit;
import simpview.scene.text.TrailingComment;

/**
 * Reads the commands of one SIMP file, line by line, straight from the bytes
 * of its buffer: no regular expressions, no splitting, no String per number.
 *
 * <p>Blank lines and comment lines (first non-blank character '#') are
 * skipped. Blanks are spaces and tabs; a line of nothing else but form
 * feeds is blank too (SPEC ignores blank lines, and a form feed shows
 * nothing), while a form feed in a command is named, as other characters
 * that show nothing are ({@link CopiedText}). What follows the command word is read
 * by the shape its {@link Kind} gives. Between numbers, in points and in
 * command arguments alike, any mix of blanks, commas and parentheses
 * separates, as in the course's own reader: {@code (x, y, z, r, g, b)},
 * {@code (x, y, z) (r, g, b)} and {@code (x, y, z, (r, g, b))} are the same
 * six numbers. Anything else is a {@link SceneException} that points at the
 * offending token.
 */
public final class SimpReader implements AutoCloseable {

    /** Axis.values() copies its array on every call; this copy is made once. */
    private static final Axis[] AXES = Axis.values();
    /** What a file this reads should be, as its messages say. */
    private static final String KIND = "a SIMP file";

    private final LineSource source;
    private final DecimalParser decimal = new DecimalParser();
    /** The commands read so far, kept to be replayed (small files only), or those being replayed. */
    private Recording recording;
    private boolean replaying;
    /** The bytes a recording or replaying reader reads; null when streamed. */
    private byte[] content;
    /** The checksum of {@link #content} ({@link FileChecksum}), or NONE. */
    private long contentChecksum = FileChecksum.NONE;
    /** Commands replayed so far. */
    private int replayed;
    private byte[] b;
    private int end;
    private long linesRead;
    /** Whether a command of this file was read: a file whose first command is 'v' or 'f' is an .obj model. */
    private boolean commandRead;

    private SimpReader(LineSource source) {
        this.source = source;
    }

    /** Opens a file, to be read in chunks. */
    public static SimpReader open(Path file) throws SceneException {
        try {
            return new SimpReader(LineSource.open(file));
        } catch (IOException e) {
            throw new SceneException(file, 0, 0, "", "cannot open the file "
                    + file.toAbsolutePath().normalize() + ": " + FileProblem.of(file, e));
        }
    }

    /** Reads a SIMP text held in memory, named {@code file} in messages. */
    public static SimpReader of(Path file, byte[] content) {
        return new SimpReader(LineSource.of(file, content));
    }

    /**
     * Reads a small file's text, just read whole, and records its commands, to be replayed on later includes; its
     * checksum is taken from these bytes.
     */
    static SimpReader recording(Path file, byte[] content) {
        SimpReader r = of(file, content);
        r.recording = new Recording(lineCount(content));
        r.content = content;
        r.contentChecksum = FileChecksum.of(content);
        return r;
    }

    /**
     * From now on (before the first line) takes the checksum of the bytes of
     * the file it streams, as it reads them ({@link #checksumAsRead}).
     */
    SimpReader checksummed() {
        source.checksummed();
        return this;
    }

    private static int lineCount(byte[] content) {
        int lines = 1;
        for (int i = LineSource.indexOfNewline(content, 0, content.length); i >= 0;
                i = LineSource.indexOfNewline(content, i + 1, content.length)) {
            lines++;
        }
        return lines;
    }

    /**
     * Replays the commands of {@code content}, recorded from a full reading of it; {@code checksum} is the one taken
     * of those bytes then.
     */
    static SimpReader replaying(Path file, byte[] content, Recording recording, long checksum) {
        SimpReader r = of(file, content);
        r.recording = recording;
        r.replaying = true;
        r.content = content;
        r.contentChecksum = checksum;
        return r;
    }

    /** This file's bytes and commands, once it has been read (not replayed) to its end without an error; else null. */
    SimpLibrary.Read newlyRecorded() {
        return replaying || finishedRecording() == null ? null
                : new SimpLibrary.Read(content, recording, contentChecksum);
    }

    /**
     * The checksum of the bytes this reader read ({@link FileChecksum}): of
     * a small file's, read whole (or kept from when they were); of a
     * {@link #checksummed} streamed file's once it was read to its end; else
     * {@link FileChecksum#NONE}.
     */
    long checksumAsRead() {
        return content != null ? contentChecksum : source.checksumOfWhole();
    }

    /** The recording of this file, once it has been read to its end without an error; else null. */
    Recording finishedRecording() {
        return recording != null && recording.finished() ? recording : null;
    }

    public Path file() {
        return source.path();
    }

    /** The 1-based number of the line last read. */
    public int lineNumber() {
        return source.lineNumber();
    }

    /** Physical lines read so far, blank and comment lines included. */
    public long linesRead() {
        return linesRead;
    }

    /** Where the line last read starts in the file, in bytes: how far the reading has come. */
    long bytesRead() {
        return source.lineOffset();
    }

    /**
     * Reads the next command into {@code into}.
     *
     * @return false at the end of the file
     */
    public boolean next(Command into) throws SceneException {
        if (replaying) {
            return replay(into);
        }
        while (true) {
            if (!readLine()) {
                if (recording != null) {
                    recording.finish(source.lineNumber());
                }
                return false;
            }
            int i = skipBlanks(source.lineStart());
            if (i < end && b[i] != '#' && !(b[i] == '\f' && onlyFormFeedsAndBlanks(i))) {
                parse(i, into);
                commandRead = true;
                if (recording != null) {
                    recording.add(into, source.lineNumber(), source.lineStart(), end);
                }
                return true;
            }
        }
    }

    /** The next recorded command, standing where it stood: line number, line text and columns as when read. */
    private boolean replay(Command into) {
        if (replayed == recording.size()) {
            source.standOn(recording.lines(), source.lineStart(), source.lineEnd());
            linesRead = recording.lines();
            return false;
        }
        int k = replayed++;
        recording.get(k, into);
        source.standOn(recording.place(k, 0), recording.place(k, 1), recording.place(k, 2));
        end = recording.place(k, 2);
        b = source.buffer();
        linesRead = source.lineNumber();
        return true;
    }

    private boolean readLine() throws SceneException {
        try {
            if (!source.nextLine()) {
                return false;
            }
        } catch (LineSource.LineTooLongException e) {
            throw new SceneException(file(), source.lineNumber() + 1, e.column(), "",
                    e.problem(KIND, "one command"));
        } catch (LineSource.NotTextException e) {
            // a program or a picture renamed .simp, or text saved as UTF-16 or Latin-1: none of its bytes is shown
            NotText found = e.notText(KIND);
            throw new SceneException(file(), found.line(), found.column(), "", found.problem());
        } catch (IOException e) {
            throw new SceneException(file(), source.lineNumber(), 0, "", "cannot read the file: " + FileProblem.of(file(), e));
        }
        linesRead++;
        b = source.buffer();
        end = source.lineEnd();
        return true;
    }

    /** Closes the file but remembers the place; reading on reopens it. */
    void suspend() throws SceneException {
        try {
            source.suspend();
        } catch (IOException e) {
            throw new SceneException(file(), source.lineNumber(), 0, "", "cannot close the file: " + FileProblem.of(file(), e));
        }
    }

    boolean holdsFile() {
        return source.holdsFile();
    }

    boolean suspended() {
        return source.suspended();
    }

    @Override
    public void close() {
        try {
            source.close();
        } catch (IOException e) {
            // Read-only file: nothing was lost, and the scene has what it needs.
        }
    }

    // ---- parsing one line ------------------------------------------------------------------

    private void parse(int start, Command c) throws SceneException {
        c.commandIndex = start;
        c.colored = false;
        c.clamped = false;
        c.count = 0;
        if (b[start] == '{' || b[start] == '}') {
            c.kind = b[start] == '{' ? Kind.PUSH : Kind.POP;
            expectEnd(start + 1);
            return;
        }
        int wordEnd = start;
        while (wordEnd < end && !isBlank(b[wordEnd]) && b[wordEnd] != '(' && b[wordEnd] != ',') {
            wordEnd++;
        }
        Kind kind = Keywords.kind(b, start, wordEnd);
        if (kind == null) {
            String word = wordEnd > start ? text(start, wordEnd) : token(start);
            // a non-breaking space or a byte order mark inside the word: named, since the word looks right
            String invisible = CopiedText.hasInvisible(word) ? CopiedText.hint(word, "") : "";
            throw error(start, "unknown command '" + word + "'" + (!invisible.isEmpty() ? invisible
                    : readsAModel(word) ? modelHint() : (numbersWithoutCommand(start) ? NO_COMMAND
                    : Keywords.suggestion(word, skipBlanks(wordEnd) < end)) + "; expected " + Keywords.all()));
        }
        c.kind = kind;
        // An expression, so that a new Shape does not build until it is read here.
        expectEnd(switch (kind.shape) {
            case NONE -> wordEnd;
            case NUMBERS -> numbers(arguments(wordEnd, c), c);
            case AXIS_ANGLE -> rotation(arguments(wordEnd, c), c);
            case NAME -> fileName(arguments(wordEnd, c), c);
        });
        if (kind.vertices() > 0) {
            c.splitVertices();
        }
    }

    /**
     * Where the arguments start: after the word, past blanks; a number list
     * may also open with '(' straight after the word.
     */
    private int arguments(int wordEnd, Command c) throws SceneException {
        int i = c.kind.shape == Shape.NUMBERS ? skipSeparators(wordEnd) : skipBlanks(wordEnd);
        if (i == end) {
            throw error(i, "wrong number of arguments: " + c.kind.spelling + " takes " + c.kind.takesText()
                    + ", found none");
        }
        if (i == wordEnd) {
            throw error(i, "expected a blank after '" + c.kind.spelling + "', found '" + token(i) + "'");
        }
        c.argumentIndex = i;
        return i;
    }

    /**
     * The numbers of the line to its end: blanks, commas and parentheses only
     * separate them, however they are grouped. Their count must be one the
     * command takes.
     *
     * @return the end of the line
     */
    private int numbers(int from, Command c) throws SceneException {
        Kind kind = c.kind;
        int most = kind.mostNumbers();
        int n = 0;
        int i = from;
        while (i < end) {
            if (!startsNumber(b[i])) {
                throw error(i, kind.takes(n) ? endExpected(i) : numberExpected(i));
            }
            if (n == most) {
                int found = n + DecimalCommas.words(b, i, end);
                String comma = decimalCommaHint(from, kind, found);
                throw error(i, wrongCount(kind, found) + (comma.isEmpty() ? countHint(from, kind, found) : comma));
            }
            i = number(i);
            c.numbers[n++] = decimal.value();
            i = skipSeparators(i);
        }
        if (!kind.takes(n)) {
            throw error(end, wrongCount(kind, n) + countHint(from, kind, n));
        }
        c.count = n;
        return end;
    }

    private int rotation(int from, Command c) throws SceneException {
        int axisEnd = from;
        while (axisEnd < end && !isBlank(b[axisEnd]) && b[axisEnd] != ',') {
            axisEnd++;
        }
        if (axisEnd - from != 1 || b[from] < 'X' || b[from] > 'Z') {
            // 'X' then a non-breaking space reads as one word with the angle: the space is what is wrong
            String found = text(from, axisEnd);
            throw error(from, "expected an axis X, Y or Z (upper case), found '" + found + "'"
                    + CopiedText.invisibleHint(found) + angleStuckHint(from, axisEnd));
        }
        c.axis = AXES[b[from] - 'X'];
        int i = skipSeparators(axisEnd);
        if (i == end) {
            throw error(i, "rotate takes an axis and an angle in degrees, found no angle");
        }
        i = number(i);
        c.angle = decimal.value();
        int next = skipSeparators(i);
        if (next < end && startsNumber(b[next])) {
            throw error(next, "rotate takes an axis and one angle, found more: '" + token(next) + "'");
        }
        return i;
    }

    /**
     * For an axis with the angle stuck to it, "Y30" in b[from, axisEnd): that they are two words; else "".
     */
    private String angleStuckHint(int from, int axisEnd) {
        int axis = Character.toUpperCase(b[from]);
        boolean stuck = axisEnd - from > 1 && axis >= 'X' && axis <= 'Z' && startsNumber(b[from + 1]);
        return stuck ? ": the axis and the angle are two words, with a blank between them: write rotate " + (char) axis
                + " " + text(from + 1, axisEnd) : "";
    }

    private int fileName(int from, Command c) throws SceneException {
        int nameStart;
        int nameEnd;
        int after;
        if (b[from] == '"') {
            nameStart = from + 1;
            nameEnd = nameStart;
            while (nameEnd < end && b[nameEnd] != '"') {
                nameEnd++;
            }
            if (nameEnd == end) {
                // file "cube” closes with a curly quote, which a copied line or a word processor puts there
                String rest = text(nameStart, end);
                throw error(from, "the file name has no closing '\"'" + (CopiedText.hasCurlyQuote(rest)
                        ? " (the name" + CopiedText.hint(rest, "") + ": write " + c.kind.spelling + " \""
                        + CopiedText.withoutQuotes(rest).strip() + "\")" : ""));
            }
            after = nameEnd + 1;
        } else {
            nameStart = from;
            nameEnd = from;
            while (nameEnd < end && !isBlank(b[nameEnd])) {
                nameEnd++;
            }
            after = nameEnd;
            int more = skipBlanks(after);
            if (more < end && b[more] != '#') {
                // file my cube: a bare name ends at a blank, so the rest reads as text after the command
                throw error(more, endExpected(more) + " (a name with blanks in it is quoted: " + c.kind.spelling
                        + " \"" + text(nameStart, end).strip() + "\")");
            }
        }
        if (nameEnd == nameStart) {
            throw error(from, "expected a file name, found an empty one");
        }
        c.fileName = new String(b, nameStart, nameEnd - nameStart, StandardCharsets.UTF_8);
        return after;
    }

    /** After a complete command only blanks may follow. */
    private void expectEnd(int i) throws SceneException {
        int j = skipBlanks(i);
        if (j < end) {
            throw error(j, endExpected(j));
        }
    }

    /**
     * "expected the end of the line, found ..." for what stands at i after a complete command: a comment is
     * told to go on a line of its own, and a character that shows nothing (a non-breaking space, a form feed
     * after the last number) is named, since the quoted text looks like a blank.
     */
    private String endExpected(int i) {
        String found = text(i, Math.min(end, i + 30));
        return "expected the end of the line, found '" + found + "'" + TrailingComment.hint(b[i])
                + CopiedText.invisibleHint(found) + StuckUnit.alone(found);
    }

    /** A number ending at a blank, comma, parenthesis or the end of the line. */
    private int number(int i) throws SceneException {
        int after = decimal.scan(b, i, end);
        if (after < 0 || !endsNumber(after)) {
            throw error(i, after >= 0 ? "expected a number, found " + found(i) + stuckUnit(i, after)
                    : numberExpected(i));
        }
        if (!Double.isFinite(decimal.value())) {
            throw error(i, "number out of range: '" + token(i) + "'");
        }
        return after;
    }

    /** "expected a number, found ..." for what stands at i, no number: a unit word after a number is told so. */
    private String numberExpected(int i) {
        return "expected a number, found " + found(i) + (i < end && afterANumber(i) ? StuckUnit.alone(token(i)) : "")
                + (i < end ? bracketHint(b[i]) : "");
    }

    /** For a bracket of another kind where a number was expected, "[0, 0, 0]": how a point is written. */
    private static String bracketHint(byte c) {
        return c == '[' || c == ']' || c == '{' || c == '}' || c == '<' || c == '>'
                ? " (a point is written in parentheses, (x, y, z): '" + (char) c + "' is no separator)" : "";
    }

    /**
     * Whether what stands at i follows a number, past blanks and commas: '10 px' in 'translate 10 px 0 0', or
     * '-50 deg' inside a polygon's brackets, where a unit word is told as after the last number of a line.
     */
    private boolean afterANumber(int i) {
        int j = i - 1;
        int start = source.lineStart();
        while (j >= start && (isBlank(b[j]) || b[j] == ',')) {
            j--;
        }
        return j >= start && (b[j] >= '0' && b[j] <= '9' || b[j] == '.');
    }

    /** For a number at i read up to {@code after}, where more stands stuck to it: a unit or a ';'. */
    private String stuckUnit(int i, int after) {
        String whole = token(i);
        String number = text(i, after);
        return whole.length() > number.length() && whole.startsWith(number)
                ? StuckUnit.afterNumber(number, whole.substring(number.length())) : "";
    }

    /** A number ends at a blank, comma, parenthesis or the end of the line. */
    private boolean endsNumber(int after) {
        return after == end || isSeparator(b[after]);
    }

    private int skipBlanks(int i) {
        while (i < end && isBlank(b[i])) {
            i++;
        }
        return i;
    }

    /**
     * Whether the line from i on holds only form feeds and blanks: a page break an editor left on a line of its
     * own, a blank line, which the .obj reader passes over too.
     */
    private boolean onlyFormFeedsAndBlanks(int i) {
        while (i < end && (b[i] == '\f' || isBlank(b[i]))) {
            i++;
        }
        return i == end;
    }

    /** Blanks, commas and parentheses: what stands between numbers. */
    private int skipSeparators(int i) {
        while (i < end && isSeparator(b[i])) {
            i++;
        }
        return i;
    }

    private static boolean isBlank(byte c) {
        return c == ' ' || c == '\t';
    }

    /** Whether c separates a command's numbers: a blank, a comma or a parenthesis. */
    static boolean isSeparator(byte c) {
        return c == ' ' || c == '\t' || c == ',' || c == '(' || c == ')';
    }

    private static boolean startsNumber(byte c) {
        return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+';
    }

    // ---- messages ----------------------------------------------------------------------------

    /** For numbers or points where a command should stand. */
    private static final String NO_COMMAND = " (these numbers have no command: a line starts with its command, as"
            + " polygon (x, y, z) (x, y, z) (x, y, z) does)";

    /** Whether the line starts, at {@code start}, with a number or a point, where its command should stand. */
    private boolean numbersWithoutCommand(int start) {
        int i = b[start] == '(' ? skipSeparators(start) : start;
        int digit = i < end && (b[i] == '-' || b[i] == '+' || b[i] == '.') ? i + 1 : i;
        return digit < end && b[digit] >= '0' && b[digit] <= '9';
    }

    /**
     * Whether the unknown command {@code word} shows this file to be an .obj
     * model given where a scene is wanted (render --scene t1.obj): the file
     * is named .obj, or its first command is one a model's lines start with.
     */
    private boolean readsAModel(String word) {
        return file().toString().toLowerCase(Locale.ROOT).endsWith(".obj")
                || !commandRead && Keywords.startsModelLine(word);
    }

    /** What to do with a model read as a scene: draw it from a scene's obj line, in a lit scene. */
    private String modelHint() {
        String name = file().getFileName().toString();
        boolean obj = name.toLowerCase(Locale.ROOT).endsWith(".obj");
        String stem = name.contains(".") ? name.substring(0, name.lastIndexOf('.')) : name;
        // obj "up" looks for up.obj, names being case-sensitive: up.OBJ is found only once renamed
        String rename = obj && !name.endsWith(".obj") ? " (once the file is renamed " + stem + ".obj: obj adds .obj in"
                + " lower case, and names are case-sensitive)" : "";
        return (obj ? ": " + name + " is an .obj model, not a scene" : ": this file holds an .obj model's lines, not a"
                + " scene's (save it as " + stem + ".obj)") + "; a model is drawn from a scene file, a .simp file"
                + " holding the line obj \"" + stem + "\"" + rename + " after the camera, light and surface lines a lit"
                + " scene needs (docs/simp.md, Lit scenes)";
    }

    private static String wrongCount(Kind kind, int found) {
        String got = found == 0 ? "none" : found + (found == 1 ? " number" : " numbers");
        return "wrong number of arguments: " + kind.spelling + " takes " + kind.takesText() + ", found " + got;
    }

    /**
     * For a line or polygon given a count of numbers it does not take, from
     * its arguments at {@code from} on: what each of its points holds, when
     * it writes as many points as it takes; else, for a polygon given more
     * numbers than a triangle's, what a polygon is.
     */
    private String countHint(int from, Kind kind, int found) {
        int afterWord = from;
        while (afterWord > source.lineStart() && isSeparator(b[afterWord - 1])) {
            afterWord--; // the arguments start past the first point's '('
        }
        String points = kind.vertices() > 0 ? PointGroups.hint(b, afterWord, end, kind.vertices()) : "";
        return points.isEmpty() ? triangleHint(kind, found) : points;
    }

    /** For a polygon given more numbers than a triangle's, what a polygon is. */
    private static String triangleHint(Kind kind, int found) {
        return kind == Kind.POLYGON && found > 9 ? " (a polygon is one triangle: draw a shape of more points as several"
                + " triangles, or as faces of an .obj model)" : "";
    }


    /**
     * A hint when the commas that stand between two digits (from {@code from}
     * on, outside parentheses, where a point's numbers are written so) look
     * like decimal commas: read as decimal points, the line would have a count
     * of numbers the command takes. SIMP reads each as two numbers.
     */
    private String decimalCommaHint(int from, Kind kind, int found) {
        int commas = DecimalCommas.count(b, from, end);
        return commas > 0 && kind.takes(found - commas) ? " (" + DecimalCommas.HINT + ")" : "";
    }

    private String found(int i) {
        return i >= end ? "the end of the line"
                : "'" + token(i) + "'" + DecimalParser.nonAsciiHint(token(i)) + TrailingComment.hint(b[i]);
    }

    /** The token at i: up to the next blank, comma or parenthesis (at least one character). */
    private String token(int i) {
        if (b[i] == '(' || b[i] == ')' || b[i] == ',') {
            return text(i, i + 1);
        }
        int j = i + 1;
        while (j < end && j - i < 30 && !isBlank(b[j]) && b[j] != ',' && b[j] != ')' && b[j] != '(') {
            j++;
        }
        return text(i, Math.min(j, end));
    }

    private String text(int from, int to) {
        return new String(b, from, to - from, StandardCharsets.UTF_8);
    }

    /** The current line, as written. */
    public String lineText() {
        return source.suspended() ? "" : text(source.lineStart(), end);
    }

    /**
     * An error at number n (from 0) of the current line's command, whose
     * numbers start at byte index {@code from}: the caret under that number.
     */
    SceneException errorAtNumber(int from, int n, String problem) {
        int i = skipSeparators(from);
        for (int k = 0; k < n && i < end; k++) {
            while (i < end && !isSeparator(b[i])) {
                i++;
            }
            i = skipSeparators(i);
        }
        return error(i, problem);
    }

    /** An error at byte index i of the current line. */
    SceneException error(int i, String problem) {
        int column = text(source.lineStart(), Math.min(i, end)).length() + 1;
        return new SceneException(file(), source.lineNumber(), column, lineText(), problem + source.lineEndHint());
    }

}
