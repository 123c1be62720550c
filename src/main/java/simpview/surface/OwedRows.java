package simpview.surface;

/**
 * Rows of the panel that a page canvas's clear left owed, handed to a
 * picture's band drawers ({@link PageCanvas#owedPanelRows}): each makes its
 * own band's rows before it first draws there, on its own thread, instead
 * of the reading thread making every row before any band can start.
 */
@FunctionalInterface
public interface OwedRows {

    /** Nothing owed. */
    OwedRows NONE = (from, to) -> { };

    /** Panel rows from &lt;= y &lt; to (y up) made as the clear left them; each row by one thread. */
    void make(int from, int to);
}
