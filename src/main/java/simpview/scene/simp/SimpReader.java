package simpview.scene.simp;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import simpview.geometry.Axis;
import simpview.scene.simp.Command.Kind;

/**
 * Reads the commands of one SIMP file, line by line, straight from the bytes
 * of its buffer: no regular expressions, no splitting, no String per number.
 *
 * <p>Blank lines and comment lines (first non-blank character '#') are
 * skipped. Blanks are spaces and tabs. Between numbers, in points and in
 * command arguments alike, any mix of blanks and commas separates. A vertex
 * may be followed by a colour tuple, and then every vertex of the command
 * must be. Anything else is a {@link SceneException} that points at the
 * offending token.
 */
public final class SimpReader implements AutoCloseable {

    /** Axis.values() copies its array on every call; this copy is made once. */
    private static final Axis[] AXES = Axis.values();

    private final LineSource source;
    private final DecimalParser decimal = new DecimalParser();
    /** The tuples of a line command: up to a point and a colour per vertex. */
    private final double[] tuples = new double[6 * Command.MAX_VERTICES];
    private final int[] tupleStarts = new int[2 * Command.MAX_VERTICES];
    /** The commands read so far, kept to be replayed (small files only), or those being replayed. */
    private Recording recording;
    private boolean replaying;
    /** Commands replayed so far. */
    private int replayed;
    /** False only in tests that check the quick path against the careful one. */
    private boolean quick = true;
    private byte[] b;
    private int end;
    private long linesRead;

    private SimpReader(LineSource source) {
        this.source = source;
    }

    /** Opens a file, to be read in chunks. */
    public static SimpReader open(Path file) throws SceneException {
        try {
            return new SimpReader(LineSource.open(file));
        } catch (IOException e) {
            throw new SceneException(file, 0, 0, "", "cannot open the file: " + describe(e));
        }
    }

    /** Reads a SIMP text held in memory, named {@code file} in messages. */
    public static SimpReader of(Path file, byte[] content) {
        return new SimpReader(LineSource.of(file, content));
    }

    /** This reader, reading every line the careful way (for tests of the quick path). */
    SimpReader carefulOnly() {
        quick = false;
        return this;
    }

    /** Reads a small file's text and records its commands, to be replayed on later includes. */
    static SimpReader recording(Path file, byte[] content) {
        SimpReader r = of(file, content);
        r.recording = new Recording(lineCount(content));
        return r;
    }

    private static int lineCount(byte[] content) {
        int lines = 1;
        for (int i = LineSource.indexOfNewline(content, 0, content.length); i >= 0;
                i = LineSource.indexOfNewline(content, i + 1, content.length)) {
            lines++;
        }
        return lines;
    }

    /** Replays the commands of {@code content}, recorded from a full reading of it. */
    static SimpReader replaying(Path file, byte[] content, Recording recording) {
        SimpReader r = of(file, content);
        r.recording = recording;
        r.replaying = true;
        return r;
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
        return source.lineNumber;
    }

    /** Physical lines read so far, blank and comment lines included. */
    public long linesRead() {
        return linesRead;
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
                    recording.finish(source.lineNumber);
                }
                return false;
            }
            int i = skipBlanks(source.lineStart);
            if (i < end && b[i] != '#') {
                parse(i, into);
                if (recording != null) {
                    recording.add(into, source.lineNumber, source.lineStart, end);
                }
                return true;
            }
        }
    }

    /** The next recorded command, standing where it stood: line number, line text and columns as when read. */
    private boolean replay(Command into) {
        if (replayed == recording.size()) {
            source.lineNumber = recording.lines();
            linesRead = recording.lines();
            return false;
        }
        int k = replayed++;
        recording.get(k, into);
        source.lineNumber = recording.place(k, 0);
        source.lineStart = recording.place(k, 1);
        end = recording.place(k, 2);
        b = source.buffer();
        linesRead = source.lineNumber;
        return true;
    }

    private boolean readLine() throws SceneException {
        try {
            if (!source.nextLine()) {
                return false;
            }
        } catch (LineSource.LineTooLongException e) {
            throw new SceneException(file(), source.lineNumber + 1, 0, "", "line is too long (over "
                    + LineSource.MAX_LINE + " bytes)");
        } catch (IOException e) {
            throw new SceneException(file(), source.lineNumber, 0, "", "cannot read the file: " + describe(e));
        }
        linesRead++;
        b = source.buffer();
        end = source.lineEnd;
        if (source.lineNumber == 1) {
            skipByteOrderMark();
        }
        return true;
    }

    /** A UTF-8 byte order mark is not part of the first line's text. */
    private void skipByteOrderMark() {
        int s = source.lineStart;
        if (end - s >= 3 && b[s] == (byte) 0xEF && b[s + 1] == (byte) 0xBB && b[s + 2] == (byte) 0xBF) {
            source.lineStart += 3;
        }
    }

    /** Closes the file but remembers the place; reading on reopens it. */
    void suspend() throws SceneException {
        try {
            source.suspend();
        } catch (IOException e) {
            throw new SceneException(file(), source.lineNumber, 0, "", "cannot close the file: " + describe(e));
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
            throw error(start, "unknown command '" + (wordEnd > start ? text(start, wordEnd) : token(start))
                    + "'; expected {, }, scale, translate, rotate, line, polygon, file, wire or filled");
        }
        c.kind = kind;
        switch (kind) {
            case WIRE, FILLED -> expectEnd(wordEnd);
            case SCALE, TRANSLATE -> expectEnd(numbers(arguments(wordEnd, c), c, 3));
            case ROTATE -> expectEnd(rotation(arguments(wordEnd, c), c));
            case LINE -> points(wordEnd, c, 2);
            case POLYGON -> points(wordEnd, c, 3);
            case FILE -> expectEnd(fileName(arguments(wordEnd, c), c));
            default -> throw new IllegalStateException(kind.name());
        }
    }

    /** A command word with arguments is followed by at least one blank. */
    private int arguments(int wordEnd, Command c) throws SceneException {
        int i = skipBlanks(wordEnd);
        if (i == end) {
            throw error(i, "wrong number of arguments: " + keyword(c.kind) + " takes " + takes(c.kind)
                    + ", found none");
        }
        if (i == wordEnd) {
            throw error(i, "expected a blank after '" + keyword(c.kind) + "', found '" + token(i) + "'");
        }
        c.argumentIndex = i;
        return i;
    }

    /** Reads n numbers into c.xyz[0..n), separated by blanks and commas. */
    private int numbers(int from, Command c, int n) throws SceneException {
        int i = from;
        for (int k = 0; k < n; k++) {
            if (k > 0) {
                i = separator(i);
                if (i == end) {
                    throw error(i, wrongCount(c.kind, k));
                }
            }
            i = number(i);
            c.xyz[k] = decimal.value();
        }
        int next = skipSeparators(i);
        if (next < end && startsArgument(b[next])) {
            throw error(next, wrongCount(c.kind, n + 1));
        }
        return i;
    }

    private int rotation(int from, Command c) throws SceneException {
        int axisEnd = from;
        while (axisEnd < end && !isBlank(b[axisEnd]) && b[axisEnd] != ',') {
            axisEnd++;
        }
        if (axisEnd - from != 1 || b[from] < 'X' || b[from] > 'Z') {
            throw error(from, "expected an axis X, Y or Z (upper case), found '" + text(from, axisEnd) + "'");
        }
        c.axis = AXES[b[from] - 'X'];
        int i = separator(axisEnd);
        if (i == end) {
            throw error(i, "rotate takes an axis and an angle in degrees, found no angle");
        }
        i = number(i);
        c.angle = decimal.value();
        int next = skipSeparators(i);
        if (next < end && startsArgument(b[next])) {
            throw error(next, "rotate takes an axis and one angle, found more: '" + token(next) + "'");
        }
        return i;
    }

    /**
     * The points of a line or polygon, nearly every line of a real file: first
     * a quick reading that only accepts well-formed points; when it meets
     * anything else it has decided nothing, and the careful reading below goes
     * over the arguments again and words the error, if there is one.
     */
    private void points(int wordEnd, Command c, int n) throws SceneException {
        if (!quick || !quickVertices(wordEnd, c, n)) {
            expectEnd(vertices(arguments(wordEnd, c), c, n));
        }
    }

    /**
     * Accepts exactly what {@link #vertices} followed by {@link #expectEnd}
     * accepts without an error, or a part of it; false for anything it does
     * not accept, before any of its findings reach the command.
     */
    private boolean quickVertices(int wordEnd, Command c, int n) {
        if (wordEnd == end || !isBlank(b[wordEnd])) {
            return false;
        }
        int i = skipBlanks(wordEnd);
        int argumentStart = i;
        int count = 0;
        while (true) {
            if (i == end || b[i] != '(' || count == 2 * n) {
                return false;
            }
            i = quickTuple(i, 3 * count++);
            if (i < 0) {
                return false;
            }
            int next = skipSeparators(i);
            if (next == end) {
                break;
            }
            i = next;
        }
        if (skipBlanks(i) != end || (count != n && count != 2 * n)) {
            return false;
        }
        c.argumentIndex = argumentStart;
        store(c, n, count);
        return true;
    }

    /** "(a, b, c)" at open into tuples[at..at+3), as {@link #tuple} reads it; -1 where that would fail. */
    private int quickTuple(int open, int at) {
        int i = skipBlanks(open + 1);
        for (int k = 0; k < 3; k++) {
            if (k > 0) {
                int j = skipSeparators(i);
                if (j == i) {
                    return -1;
                }
                i = j;
            }
            int after = decimal.scan(b, i, end);
            if (after < 0 || !endsNumber(after) || !Double.isFinite(decimal.value())) {
                return -1;
            }
            tuples[at + k] = decimal.value();
            i = after;
        }
        i = skipBlanks(i);
        return i < end && b[i] == ')' ? i + 1 : -1;
    }

    /**
     * Reads the points of a line or polygon: n tuples, or 2n when each point
     * is followed by its colour.
     */
    private int vertices(int from, Command c, int n) throws SceneException {
        int count = 0;
        int i = from;
        while (true) {
            int next = count == 0 ? i : skipSeparators(i);
            if (next == end || b[next] != '(') {
                if (next < end && count < n) {
                    throw error(next, "expected '(' starting a point, found '" + token(next) + "'");
                }
                break;
            }
            if (count == 2 * n) {
                throw error(next, wrongCount(c.kind, count + 1));
            }
            tupleStarts[count] = next;
            i = tuple(next, 3 * count);
            count++;
        }
        if (count < n) {
            throw error(i, wrongCount(c.kind, count));
        }
        if (count != n && count != 2 * n) {
            throw error(tupleStarts[n], "points with and without colours: give every vertex of '"
                    + keyword(c.kind) + "' a colour (r, g, b) after its point, or none");
        }
        store(c, n, count);
        return i;
    }

    /** Moves the tuples read into the command: n points, each followed by its colour when there are 2n. */
    private void store(Command c, int n, int count) {
        c.colored = count == 2 * n;
        int stride = c.colored ? 6 : 3;
        for (int k = 0; k < n; k++) {
            System.arraycopy(tuples, stride * k, c.xyz, 3 * k, 3);
            if (c.colored) {
                System.arraycopy(tuples, stride * k + 3, c.rgb, 3 * k, 3);
            }
        }
    }

    /** Reads "(a, b, c)" into tuples[at..at+3). */
    private int tuple(int open, int at) throws SceneException {
        int i = skipBlanks(open + 1);
        for (int k = 0; k < 3; k++) {
            if (k > 0) {
                i = separator(i);
            }
            if (i == end) {
                throw error(i, "expected a number, found the end of the line");
            }
            i = number(i);
            tuples[at + k] = decimal.value();
        }
        i = skipBlanks(i);
        if (i == end || b[i] != ')') {
            throw error(i, "expected ')' closing the point after three numbers, found " + found(i));
        }
        return i + 1;
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
                throw error(from, "the file name has no closing '\"'");
            }
            after = nameEnd + 1;
        } else {
            nameStart = from;
            nameEnd = from;
            while (nameEnd < end && !isBlank(b[nameEnd])) {
                nameEnd++;
            }
            after = nameEnd;
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
            throw error(j, "expected the end of the line, found '" + text(j, Math.min(end, j + 30)) + "'");
        }
    }

    /** A number ending at a blank, comma, ')' or the end of the line. */
    private int number(int i) throws SceneException {
        int after = decimal.scan(b, i, end);
        if (after < 0 || !endsNumber(after)) {
            throw error(i, "expected a number, found " + found(i));
        }
        if (!Double.isFinite(decimal.value())) {
            throw error(i, "number out of range: '" + token(i) + "'");
        }
        return after;
    }

    /** Blanks and commas between two numbers: at least one of them (a ')' is left to the caller). */
    private int separator(int i) throws SceneException {
        int j = skipSeparators(i);
        if (j == i && i < end && b[i] != ')') {
            throw error(i, "expected a blank or ',' between numbers, found '" + token(i) + "'");
        }
        return j;
    }

    /** A number ends at a blank, comma, ')' or the end of the line. */
    private boolean endsNumber(int after) {
        return after == end || isBlank(b[after]) || b[after] == ',' || b[after] == ')';
    }

    private int skipBlanks(int i) {
        while (i < end && isBlank(b[i])) {
            i++;
        }
        return i;
    }

    private int skipSeparators(int i) {
        while (i < end && (isBlank(b[i]) || b[i] == ',')) {
            i++;
        }
        return i;
    }

    private static boolean isBlank(byte c) {
        return c == ' ' || c == '\t';
    }

    private static boolean startsArgument(byte c) {
        return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == '(';
    }

    // ---- messages ----------------------------------------------------------------------------

    private static String takes(Kind kind) {
        return switch (kind) {
            case SCALE, TRANSLATE -> "3 numbers";
            case ROTATE -> "an axis and an angle";
            case LINE -> "2 points";
            case POLYGON -> "3 points";
            case FILE -> "a file name";
            default -> "no arguments";
        };
    }

    private static String wrongCount(Kind kind, int found) {
        String unit = kind == Kind.LINE || kind == Kind.POLYGON ? "point" : "number";
        int most = kind == Kind.LINE ? 4 : kind == Kind.POLYGON ? 6 : 3;
        String got = found > most ? "more" : found + " " + unit + (found == 1 ? "" : "s");
        return "wrong number of arguments: " + keyword(kind) + " takes " + takes(kind) + ", found " + got;
    }

    private static String keyword(Kind kind) {
        return Keywords.spelling(kind);
    }

    private String found(int i) {
        return i >= end ? "the end of the line" : "'" + token(i) + "'";
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
        return source.suspended() ? "" : text(source.lineStart, end);
    }

    /** An error at byte index i of the current line. */
    SceneException error(int i, String problem) {
        int column = text(source.lineStart, Math.min(i, end)).length() + 1;
        return new SceneException(file(), source.lineNumber, column, lineText(), problem);
    }

    private static String describe(IOException e) {
        String m = e.getMessage();
        return e.getClass().getSimpleName() + (m == null ? "" : ": " + m);
    }
}
