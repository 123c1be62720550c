package simpview.scene;

import java.nio.file.Path;

/**
 * Bad input in a SIMP scene: where it is (file, 1-based line and column), the
 * line as written, and what was expected there. Its message is meant for a
 * person and is complete on its own; no stack trace is ever shown for it.
 */
public final class SceneException extends Exception {

    private static final long serialVersionUID = 1L;
    /** The most characters of a line an error shows. */
    private static final int SHOWN = 120;

    private final Path file;
    private final int line;
    private final int column;
    private final String lineText;
    private final String problem;
    /** "page4.simp:12", the lines that included the file at fault, innermost first; null for a top file. */
    private final String includedFrom;

    /**
     * @param file the file at fault (may be null when there is none)
     * @param line 1-based; 0 when the problem is the file as a whole
     * @param column 1-based; 0 when the problem is the line as a whole
     * @param lineText the line as written, or "" when there is none
     * @param problem what is wrong and what was expected, e.g. "expected a number, found 'x'"
     */
    public SceneException(Path file, int line, int column, String lineText, String problem) {
        // a carriage return inside a line (a file of CR line ends) or a form feed quoted in the problem would move a
        // terminal's cursor
        this(file, line, column, lineText, problem.replace('\r', ' ').replace('\f', ' '), null);
    }

    private SceneException(Path file, int line, int column, String lineText, String problem, String includedFrom) {
        super(format(file, line, column, lineText, problem, includedFrom));
        this.file = file;
        this.line = line;
        this.column = column;
        this.lineText = lineText == null ? "" : lineText;
        this.problem = problem;
        this.includedFrom = includedFrom;
    }

    /**
     * The same error, saying which lines included the file at fault:
     * "cube.simp:3:1, included from page4.simp:12: ...". An error that
     * already says so is returned as it is.
     *
     * @param chain the including lines, innermost first, e.g. "b.simp:5, included from page4.simp:12"
     */
    public SceneException includedFrom(String chain) {
        if (includedFrom != null || chain == null || chain.isEmpty()) {
            return this;
        }
        SceneException placed = new SceneException(file, line, column, lineText, problem, chain);
        placed.setStackTrace(getStackTrace());
        return placed;
    }

    /** The including lines, or null when the error is in the top file. */
    public String includedFrom() {
        return includedFrom;
    }

    private static String format(Path file, int line, int column, String lineText, String problem,
            String includedFrom) {
        StringBuilder sb = new StringBuilder();
        // named without "." parts: a scene of the folder "." is bad.simp, not ./bad.simp
        sb.append(file == null ? "<scene>" : PlainPath.of(file).toString());
        if (line > 0) {
            sb.append(':').append(line);
            if (column > 0) {
                sb.append(':').append(column);
            }
        }
        if (includedFrom != null) {
            sb.append(", included from ").append(includedFrom);
        }
        sb.append(": ").append(problem);
        if (line > 0 && lineText != null && !lineText.isEmpty()) {
            // a tab, a form feed, or a carriage return inside the line, as one blank: each keeps the caret's column
            String text = lineText.replace('\t', ' ').replace('\r', ' ').replace('\f', ' ');
            int caret = Math.min(Math.max(column - 1, 0), text.length());
            // A long line is shown around the caret, its cut ends marked.
            int from = Math.max(0, Math.min(caret - SHOWN / 2, text.length() - SHOWN));
            int to = Math.min(text.length(), from + SHOWN);
            String shown = (from > 0 ? "…" : "") + text.substring(from, to) + (to < text.length() ? "…" : "");
            sb.append('\n').append("    ").append(shown);
            if (column > 0) {
                sb.append('\n').append("    ").append(" ".repeat(caret - from + (from > 0 ? 1 : 0))).append('^');
            }
        }
        return sb.toString();
    }

    /** The file at fault; null when there is none. */
    public Path file() {
        return file;
    }

    /** The line at fault, from 1; 0 when the problem is the file as a whole (not there, not text). */
    public int line() {
        return line;
    }

    /** The column at fault, from 1; 0 when the problem is the line (or the file) as a whole. */
    public int column() {
        return column;
    }

    /** The line at fault as written; "" when there is none. */
    public String lineText() {
        return lineText;
    }

    /** What is wrong, without the location: "expected a number, found 'x'". */
    public String problem() {
        return problem;
    }
}
