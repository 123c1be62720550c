package simpview.window;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.accessibility.AccessibleContext;
import javax.accessibility.AccessibleRole;
import javax.swing.JComponent;

/**
 * The key help (F1), drawn in a box over the whole window (its glass pane:
 * over the page and the inspector panel; a click on it hides it, and does
 * nothing to the page it hides): in the fewest columns in which each row's keys, then what they
 * do wrapped to the column's width, fit the window; in a window too small
 * for that, as many columns as its height needs and its width holds, the
 * words cut short with "…", and what no column holds named at the bottom.
 */
public final class HelpOverlay extends JComponent {

    private static final long serialVersionUID = 1L;

    HelpOverlay() {
        setName("key help");
        getAccessibleContext().setAccessibleName("keys, menus and gestures");
        getAccessibleContext().setAccessibleDescription("every key and menu entry with what it does, as the menus "
                + "list them; F1, Escape or a click hides this");
        setOpaque(false);
        setVisible(false);
        // A click meant to close the help must not step the page behind it, unseen.
        addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                setVisible(false);
            }
        });
    }

    /** A screen reader's view of the help: a JComponent has none of its own. */
    @Override
    public AccessibleContext getAccessibleContext() {
        if (accessibleContext == null) {
            accessibleContext = new AccessibleJComponent() {
                private static final long serialVersionUID = 1L;

                @Override
                public AccessibleRole getAccessibleRole() {
                    return AccessibleRole.PANEL;
                }
            };
        }
        return accessibleContext;
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            paint(g, getWidth(), getHeight());
        } finally {
            g.dispose();
        }
    }

    private static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 12);
    private static final Color BOX = new Color(20, 20, 40, 235);
    private static final Color HEADING = new Color(255, 220, 140);
    private static final Color KEYS = new Color(160, 200, 255);
    private static final int PAD = 10;
    /** The widest a column's "does" text is drawn: wrapped beyond it, or cut when the window is too small. */
    private static final int DOES_WIDTH = 440;
    /** The narrowest a column's "does" text is wrapped to; narrower, it is cut instead. */
    private static final int MIN_DOES_WIDTH = 160;

    /** One text drawn: where, and how wide. */
    record Drawn(String text, int x, int baseline, int width) {
    }

    /** The help's texts as drawn on {@code g}, and a list of them (for the tests: what shows, and where). */
    private static final class Writing {
        private final Graphics2D g;
        private final FontMetrics metrics;
        private final List<Drawn> drawn = new ArrayList<>();

        Writing(Graphics2D g) {
            this.g = g;
            this.metrics = g.getFontMetrics();
        }

        void text(String text, int x, int baseline, Color colour) {
            g.setColor(colour);
            g.drawString(text, x, baseline);
            drawn.add(new Drawn(text, x, baseline, metrics.stringWidth(text)));
        }
    }

    /** Draws the help over a window of {@code width} x {@code height}; returns the texts drawn. */
    static List<Drawn> paint(Graphics2D g, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        Writing writing = new Writing(g);
        if (!paintWrapped(writing, width, height)) {
            paintCut(writing, width, height);
        }
        return List.copyOf(writing.drawn);
    }

    /**
     * The rows in the fewest columns (up to four) in which each row's words,
     * wrapped to the column's width, fit the window's height; false when
     * none does (a small window), with nothing drawn.
     */
    private static boolean paintWrapped(Writing g, int width, int height) {
        FontMetrics metrics = g.metrics;
        int line = metrics.getHeight();
        List<KeyHelp.Row> rows = KeyHelp.ROWS;
        int keys = 0;
        for (KeyHelp.Row row : rows) {
            keys = row.heading() ? keys : Math.max(keys, metrics.stringWidth(row.input()));
        }
        int room = Math.max(1, (height - 3 * PAD) / line - 1);
        for (int columns = 1; columns <= 4; columns++) {
            int doesRoom = Math.min(DOES_WIDTH, (width - PAD - columns * (keys + 3 * PAD)) / columns);
            if (doesRoom < MIN_DOES_WIDTH) {
                return false;
            }
            List<List<String>> wrapped = new ArrayList<>();
            for (KeyHelp.Row row : rows) {
                wrapped.add(row.heading() ? List.of(row.does()) : wrap(row.does(), metrics, doesRoom));
            }
            // rows in order, a column full when the next row's lines would pass the bottom
            List<Integer> starts = new ArrayList<>(List.of(0));
            int used = 0;
            int tallest = 0;
            for (int r = 0; r < rows.size(); r++) {
                int lines = wrapped.get(r).size();
                if (used > 0 && used + lines > room) {
                    starts.add(r);
                    used = 0;
                }
                used += lines;
                tallest = Math.max(tallest, used);
            }
            if (starts.size() > columns || tallest > room) {
                continue;
            }
            int boxWidth = Math.min(width, PAD + starts.size() * (keys + 3 * PAD + doesRoom));
            int boxHeight = Math.min(height, (tallest + 1) * line + 2 * PAD);
            int left = Math.max(0, (width - boxWidth) / 2);
            int top = Math.max(0, (height - boxHeight) / 2);
            box(g, left, top, boxWidth, boxHeight, HEADING_TEXT);
            starts.add(rows.size());
            for (int c = 0; c + 1 < starts.size(); c++) {
                int x = left + PAD + c * (keys + 3 * PAD + doesRoom);
                int baseline = top + PAD + metrics.getAscent();
                for (int r = starts.get(c); r < starts.get(c + 1); r++) {
                    KeyHelp.Row shown = rows.get(r);
                    baseline = row(g, shown, shown.heading() ? shown.does() : shown.input(), wrapped.get(r), x,
                            x + keys + PAD, baseline + line, line);
                }
            }
            return true;
        }
        return false;
    }

    private static final String HEADING_TEXT = "simpview — keys, menus and gestures (F1, Esc or a click hides this)";

    /**
     * One row from {@code baseline} down: a heading, or its keys at {@code x}
     * and the lines of what they do at {@code wordsX}; returns the baseline
     * of its last line.
     */
    private static int row(Writing g, KeyHelp.Row row, String input, List<String> words, int x, int wordsX,
            int baseline, int line) {
        if (row.heading()) {
            g.text(input, x, baseline, HEADING);
            return baseline;
        }
        g.text(input, x, baseline, KEYS);
        int at = baseline;
        for (int k = 0; k < words.size(); k++) {
            g.text(words.get(k), wordsX, at, Color.WHITE);
            at += k + 1 < words.size() ? line : 0;
        }
        return at;
    }

    /** The help's box and its heading (cut with "…" at the box's edge). */
    private static void box(Writing g, int left, int top, int width, int height, String heading) {
        g.g.setColor(BOX);
        g.g.fillRect(left, top, width, height);
        g.text(cut(heading, g.metrics, width - 2 * PAD), left + PAD, top + PAD + g.metrics.getAscent(), HEADING);
    }

    /** {@code text} in lines of at most {@code room} pixels, broken between words (a word wider than that alone). */
    static List<String> wrap(String text, FontMetrics metrics, int room) {
        List<String> lines = new ArrayList<>();
        StringBuilder current = new StringBuilder();
        for (String word : text.split(" ")) {
            String longer = current.length() == 0 ? word : current + " " + word;
            if (current.length() > 0 && metrics.stringWidth(longer) > room) {
                lines.add(current.toString());
                current.setLength(0);
                current.append(word);
            } else {
                current.setLength(0);
                current.append(longer);
            }
        }
        lines.add(current.toString());
        return lines;
    }

    /** The narrowest the words of a column are cut to when the window holds more than one column. */
    private static final int MIN_CUT_WIDTH = 80;

    /**
     * A window too small for the words wrapped: as many columns as its
     * height needs, as far as its width holds them, the keys and the words
     * cut with "…" at the column's edge; the rows no column holds are named
     * at the bottom, by their sections, never left out unsaid.
     */
    private static void paintCut(Writing g, int width, int height) {
        FontMetrics metrics = g.metrics;
        int line = metrics.getHeight();
        List<KeyHelp.Row> rows = KeyHelp.ROWS;
        int room = Math.max(1, (height - 3 * PAD) / line - 1);
        int noteWidth = width - 2 * PAD;
        // Lines kept at the bottom to say what is left out: as many as the saying needs, found in turn.
        List<String> note = List.of();
        List<List<KeyHelp.Row>> columns = List.of();
        for (int kept = 0; kept <= room; kept++) {
            columns = columns(rows, metrics, width, Math.max(1, room - kept));
            int shown = 0;
            for (List<KeyHelp.Row> column : columns) {
                shown += column.size();
            }
            note = shown == rows.size() ? List.of() : wrap(leftOut(rows, shown), metrics, noteWidth);
            if (note.size() <= kept) {
                break;
            }
        }
        int count = columns.size();
        int[] keyWidths = new int[count];
        int keys = 0;
        for (int c = 0; c < count; c++) {
            keyWidths[c] = keyWidth(columns.get(c), metrics, width);
            keys += keyWidths[c] + 3 * PAD;
        }
        // What is left of the width goes to the words, evenly.
        int doesRoom = Math.max(1, Math.min(DOES_WIDTH, (width - PAD - keys) / count));
        int[] doesWidths = new int[count];
        boolean cutShort = !note.isEmpty();
        int boxWidth = PAD;
        int perColumn = 0;
        for (int c = 0; c < count; c++) {
            for (KeyHelp.Row row : columns.get(c)) {
                // a heading is written across its column's keys and words
                int does = metrics.stringWidth(row.does()) - (row.heading() ? keyWidths[c] + PAD : 0);
                cutShort |= does > doesRoom || !row.heading() && metrics.stringWidth(row.input()) > keyWidths[c];
                doesWidths[c] = Math.max(doesWidths[c], Math.min(doesRoom, does));
            }
            boxWidth += keyWidths[c] + doesWidths[c] + 3 * PAD;
            perColumn = Math.max(perColumn, columns.get(c).size());
        }
        if (!note.isEmpty()) {
            boxWidth = width;
        }
        boxWidth = Math.min(width, boxWidth);
        int boxHeight = Math.min(height, (perColumn + note.size() + 1) * line + 2 * PAD);
        int left = Math.max(0, (width - boxWidth) / 2);
        int top = Math.max(0, (height - boxHeight) / 2);
        box(g, left, top, boxWidth, boxHeight, cutShort
                ? HEADING_TEXT + " · cut short: a larger window shows it whole" : HEADING_TEXT);
        int x = left + PAD;
        for (int c = 0; c < count; c++) {
            int baseline = top + PAD + metrics.getAscent();
            for (KeyHelp.Row row : columns.get(c)) {
                String first = row.heading() ? cut(row.does(), metrics, keyWidths[c] + PAD + doesWidths[c])
                        : cut(row.input(), metrics, keyWidths[c]);
                List<String> words = row.heading() ? List.of() : List.of(cut(row.does(), metrics, doesWidths[c]));
                baseline = row(g, row, first, words, x, x + keyWidths[c] + PAD, baseline + line, line);
            }
            x += keyWidths[c] + doesWidths[c] + 3 * PAD;
        }
        int baseline = top + PAD + metrics.getAscent() + (perColumn + 1) * line;
        for (String noteLine : note) {
            g.text(cut(noteLine, metrics, noteWidth), left + PAD, baseline, HEADING);
            baseline += line;
        }
    }

    /**
     * The rows in columns of {@code perColumn} rows, as many columns as the
     * rows need and the width holds (at least one); when they all fit, the
     * rows spread evenly over the columns.
     */
    private static List<List<KeyHelp.Row>> columns(List<KeyHelp.Row> rows, FontMetrics metrics, int width,
            int perColumn) {
        int needed = (rows.size() + perColumn - 1) / perColumn;
        for (int count = needed; count > 1; count--) {
            int each = count == needed ? (rows.size() + count - 1) / count : perColumn;
            List<List<KeyHelp.Row>> columns = new ArrayList<>();
            int used = PAD;
            for (int c = 0; c < count; c++) {
                List<KeyHelp.Row> column = rows.subList(Math.min(rows.size(), c * each),
                        Math.min(rows.size(), (c + 1) * each));
                if (!column.isEmpty()) {
                    columns.add(column);
                    used += keyWidth(column, metrics, width) + 3 * PAD + MIN_CUT_WIDTH;
                }
            }
            if (used <= width) {
                return count == needed ? columns : withoutLastHeading(columns);
            }
        }
        List<List<KeyHelp.Row>> one = List.of(rows.subList(0, Math.min(rows.size(), perColumn)));
        return needed == 1 ? one : withoutLastHeading(one);
    }

    /** Columns cut short end on a row, not on a heading whose rows none of them holds. */
    private static List<List<KeyHelp.Row>> withoutLastHeading(List<List<KeyHelp.Row>> columns) {
        List<KeyHelp.Row> last = columns.get(columns.size() - 1);
        if (last.size() < 2 || !last.get(last.size() - 1).heading()) {
            return columns;
        }
        List<List<KeyHelp.Row>> kept = new ArrayList<>(columns);
        kept.set(kept.size() - 1, last.subList(0, last.size() - 1));
        return kept;
    }

    /** The keys' width of a column: its widest keys, but never more than a third of the window. */
    private static int keyWidth(List<KeyHelp.Row> column, FontMetrics metrics, int width) {
        int widest = 0;
        for (KeyHelp.Row row : column) {
            widest = row.heading() ? widest : Math.max(widest, metrics.stringWidth(row.input()));
        }
        return Math.min(widest, Math.max(1, width / 3));
    }

    /** What the help leaves out when it shows only its first {@code shown} rows: by their sections. */
    static String leftOut(List<KeyHelp.Row> rows, int shown) {
        List<String> sections = new ArrayList<>();
        for (int r = shown; r < rows.size(); r++) {
            if (rows.get(r).heading()) {
                sections.add(section(rows.get(r).does()));
            } else if (r == shown) {
                String within = "";
                for (int h = r - 1; h >= 0 && within.isEmpty(); h--) {
                    within = rows.get(h).heading() ? rows.get(h).does() : "";
                }
                sections.add("the rest of " + section(within));
            }
        }
        return "Not shown, for want of room (a larger window shows them): " + String.join(", ", sections) + ".";
    }

    /** A heading as the note names its section: "the View menu", "the pointer's gestures". */
    private static String section(String heading) {
        return heading.endsWith(" menu") ? "the " + heading : "the " + heading.toLowerCase(Locale.ROOT) + "'s gestures";
    }

    private static String cut(String text, FontMetrics metrics, int room) {
        if (metrics.stringWidth(text) <= room) {
            return text;
        }
        String shorter = text;
        while (!shorter.isEmpty() && metrics.stringWidth(shorter + "…") > room) {
            shorter = shorter.substring(0, shorter.length() - 1);
        }
        return shorter + "…";
    }
}
