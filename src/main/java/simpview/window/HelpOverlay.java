package simpview.window;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;

/** The key help (F1), drawn in a box over the page. */
public final class HelpOverlay {

    private static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 13);
    private static final Color BOX = new Color(20, 20, 40, 230);
    private static final Color HEADING = new Color(160, 200, 255);
    private static final int PAD = 12;

    private HelpOverlay() {
    }

    static void paint(Graphics2D g, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        FontMetrics metrics = g.getFontMetrics();
        int inputWidth = 0;
        int doesWidth = 0;
        for (KeyHelp.Row row : KeyHelp.ROWS) {
            inputWidth = Math.max(inputWidth, metrics.stringWidth(row.input()));
            doesWidth = Math.max(doesWidth, metrics.stringWidth(row.does()));
        }
        int line = metrics.getHeight();
        int boxWidth = Math.min(width - 2 * PAD, inputWidth + doesWidth + 5 * PAD);
        int boxHeight = Math.min(height - 2 * PAD, (KeyHelp.ROWS.size() + 1) * line + 2 * PAD);
        int left = Math.max(0, (width - boxWidth) / 2);
        int top = Math.max(0, (height - boxHeight) / 2);
        g.setColor(BOX);
        g.fillRect(left, top, boxWidth, boxHeight);
        int baseline = top + PAD + metrics.getAscent();
        g.setColor(HEADING);
        g.drawString("simpview — keys and gestures (F1 hides this)", left + PAD, baseline);
        for (KeyHelp.Row row : KeyHelp.ROWS) {
            baseline += line;
            g.setColor(HEADING);
            g.drawString(row.input(), left + PAD, baseline);
            g.setColor(Color.WHITE);
            g.drawString(row.does(), left + 3 * PAD + inputWidth, baseline);
        }
    }
}
