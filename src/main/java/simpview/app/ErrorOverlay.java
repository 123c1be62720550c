package simpview.app;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.ArrayList;
import java.util.List;
import simpview.surface.PageCanvas;

/**
 * A scene error drawn over the bottom of the page: a box with the message in
 * a fixed-width font, so the caret under the bad line still points at the
 * right column.
 */
final class ErrorOverlay {

    static final String HEADING = "Scene error — the page shows what was drawn before it:";
    private static final Font FONT = new Font(Font.MONOSPACED, Font.PLAIN, 13);
    private static final Color BOX = new Color(70, 0, 0, 225);
    private static final Color BORDER = new Color(255, 120, 120);
    private static final int PAD = 10;

    private ErrorOverlay() {
    }

    static void paint(Graphics2D g, String message, int width) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        FontMetrics metrics = g.getFontMetrics();
        int boxWidth = width - 2 * PAD;
        List<String> lines = new ArrayList<>();
        lines.add(HEADING);
        lines.addAll(wrap(message, Math.max(20, (boxWidth - 2 * PAD) / metrics.charWidth('m'))));
        int boxHeight = lines.size() * metrics.getHeight() + 2 * PAD;
        int top = PageCanvas.SIZE - PAD - boxHeight;
        g.setColor(BOX);
        g.fillRect(PAD, top, boxWidth, boxHeight);
        g.setColor(BORDER);
        g.drawRect(PAD, top, boxWidth - 1, boxHeight - 1);
        int baseline = top + PAD + metrics.getAscent();
        for (int i = 0; i < lines.size(); i++) {
            g.setColor(i == 0 ? BORDER : Color.WHITE);
            g.drawString(lines.get(i), 2 * PAD, baseline);
            baseline += metrics.getHeight();
        }
    }

    /** Splits the message into lines of at most {@code columns} characters, breaking at a space where one is near. */
    static List<String> wrap(String message, int columns) {
        List<String> lines = new ArrayList<>();
        for (String line : message.split("\n", -1)) {
            String rest = line;
            while (rest.length() > columns) {
                int cut = rest.lastIndexOf(' ', columns);
                if (cut < columns / 2) {
                    cut = columns;
                }
                lines.add(rest.substring(0, cut));
                rest = rest.substring(cut).stripLeading();
            }
            lines.add(rest);
        }
        return lines;
    }
}
