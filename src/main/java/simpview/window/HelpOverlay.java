package simpview.window;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.ArrayList;
import java.util.List;

/**
 * The key help (F1), drawn in a box over the whole window (its glass pane:
 * over the page and the inspector panel, the pointer's events passing
 * through): in the fewest columns in which each row's keys, then what they
 * do wrapped to the column's width, fit the window; in a window too small
 * for that, as many columns as its height needs, the words cut short with
 * "…".
 */
public final class HelpOverlay extends javax.swing.JComponent {

    private static final long serialVersionUID = 1L;

    HelpOverlay() {
        setName("key help");
        setOpaque(false);
        setVisible(false);
    }

    @Override
    protected void paintComponent(java.awt.Graphics graphics) {
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

    static void paint(Graphics2D g, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        FontMetrics metrics = g.getFontMetrics();
        if (!paintWrapped(g, metrics, width, height)) {
            paintCut(g, metrics, width, height);
        }
    }

    /**
     * The rows in the fewest columns (up to four) in which each row's words,
     * wrapped to the column's width, fit the window's height; false when
     * none does (a small window), with nothing drawn.
     */
    private static boolean paintWrapped(Graphics2D g, FontMetrics metrics, int width, int height) {
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
            box(g, metrics, left, top, boxWidth, boxHeight, HEADING_TEXT);
            starts.add(rows.size());
            for (int c = 0; c + 1 < starts.size(); c++) {
                int x = left + PAD + c * (keys + 3 * PAD + doesRoom);
                int baseline = top + PAD + metrics.getAscent();
                for (int r = starts.get(c); r < starts.get(c + 1); r++) {
                    baseline = row(g, rows.get(r), wrapped.get(r), x, x + keys + PAD, baseline + line, line);
                }
            }
            return true;
        }
        return false;
    }

    private static final String HEADING_TEXT = "simpview — keys, menus and gestures (F1 hides this)";

    /**
     * One row from {@code baseline} down: a heading, or its keys at {@code x}
     * and the lines of what they do at {@code wordsX}; returns the baseline
     * of its last line.
     */
    private static int row(Graphics2D g, KeyHelp.Row row, List<String> words, int x, int wordsX, int baseline,
            int line) {
        if (row.heading()) {
            g.setColor(HEADING);
            g.drawString(row.does(), x, baseline);
            return baseline;
        }
        g.setColor(KEYS);
        g.drawString(row.input(), x, baseline);
        g.setColor(Color.WHITE);
        int at = baseline;
        for (int k = 0; k < words.size(); k++) {
            g.drawString(words.get(k), wordsX, at);
            at += k + 1 < words.size() ? line : 0;
        }
        return at;
    }

    /** The help's box and its heading. */
    private static void box(Graphics2D g, FontMetrics metrics, int left, int top, int width, int height,
            String heading) {
        g.setColor(BOX);
        g.fillRect(left, top, width, height);
        g.setColor(HEADING);
        g.drawString(heading, left + PAD, top + PAD + metrics.getAscent());
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

    /** A window too small for the words wrapped: as many columns as its height needs, the words cut with "…". */
    private static void paintCut(Graphics2D g, FontMetrics metrics, int width, int height) {
        int line = metrics.getHeight();
        List<KeyHelp.Row> rows = KeyHelp.ROWS;
        int perColumn = Math.max(1, (height - 3 * PAD) / line - 1);
        int columns = (rows.size() + perColumn - 1) / perColumn;
        perColumn = (rows.size() + columns - 1) / columns;
        List<List<KeyHelp.Row>> split = new ArrayList<>();
        for (int c = 0; c < columns; c++) {
            split.add(rows.subList(c * perColumn, Math.min(rows.size(), (c + 1) * perColumn)));
        }
        int[] inputWidths = new int[columns];
        int[] doesWidths = new int[columns];
        int inputs = 0;
        for (int c = 0; c < columns; c++) {
            for (KeyHelp.Row row : split.get(c)) {
                if (!row.heading()) {
                    inputWidths[c] = Math.max(inputWidths[c], metrics.stringWidth(row.input()));
                }
            }
            inputs += inputWidths[c] + 3 * PAD;
        }
        // What is left of the width goes to the words, evenly; a narrow window cuts them (the keys stay whole).
        int doesRoom = Math.max(80, Math.min(DOES_WIDTH, (width - PAD - inputs) / columns));
        boolean cutShort = false;
        for (KeyHelp.Row row : rows) {
            cutShort |= !row.heading() && metrics.stringWidth(row.does()) > doesRoom;
        }
        int boxWidth = PAD;
        for (int c = 0; c < columns; c++) {
            for (KeyHelp.Row row : split.get(c)) {
                doesWidths[c] = Math.max(doesWidths[c], Math.min(doesRoom, metrics.stringWidth(row.does())));
            }
            boxWidth += inputWidths[c] + doesWidths[c] + 3 * PAD;
        }
        boxWidth = Math.min(width, boxWidth);
        int boxHeight = Math.min(height, (perColumn + 1) * line + 2 * PAD);
        int left = Math.max(0, (width - boxWidth) / 2);
        int top = Math.max(0, (height - boxHeight) / 2);
        box(g, metrics, left, top, boxWidth, boxHeight, cutShort
                ? HEADING_TEXT + " · cut short: a larger window shows it whole" : HEADING_TEXT);
        int x = left + PAD;
        for (int c = 0; c < columns; c++) {
            int baseline = top + PAD + metrics.getAscent();
            for (KeyHelp.Row row : split.get(c)) {
                baseline = row(g, row, List.of(cut(row.does(), metrics, doesRoom)), x, x + inputWidths[c] + PAD,
                        baseline + line, line);
            }
            x += inputWidths[c] + doesWidths[c] + 3 * PAD;
        }
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
