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
 * through): as many columns as the window's height needs, each row's keys,
 * then what they do, cut short with "…" only where the window is too narrow
 * for the whole text.
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
    /** The widest a column's "does" text is drawn before it is cut. */
    private static final int DOES_WIDTH = 440;

    static void paint(Graphics2D g, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        FontMetrics metrics = g.getFontMetrics();
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
        g.setColor(BOX);
        g.fillRect(left, top, boxWidth, boxHeight);
        g.setColor(HEADING);
        g.drawString("simpview — keys, menus and gestures (F1 hides this)", left + PAD, top + PAD + metrics.getAscent());
        int x = left + PAD;
        for (int c = 0; c < columns; c++) {
            int baseline = top + PAD + metrics.getAscent();
            for (KeyHelp.Row row : split.get(c)) {
                baseline += line;
                if (row.heading()) {
                    g.setColor(HEADING);
                    g.drawString(row.does(), x, baseline);
                    continue;
                }
                g.setColor(KEYS);
                g.drawString(row.input(), x, baseline);
                g.setColor(Color.WHITE);
                g.drawString(cut(row.does(), metrics, doesRoom), x + inputWidths[c] + PAD, baseline);
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
