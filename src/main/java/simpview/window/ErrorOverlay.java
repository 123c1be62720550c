package simpview.window;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.ArrayList;
import java.util.List;

/**
 * A scene error drawn over the bottom of the page: a box with the message in
 * a fixed-width font, so the caret under the bad line still points at the
 * right column.
 */
public final class ErrorOverlay {

    static final String HEADING = "Scene error — the page shows what was drawn before it (E hides this):";
    /** When the scene drew nothing at all, e.g. its file is missing. */
    static final String HEADING_NOTHING_DRAWN = "Scene error — nothing was drawn (E hides this):";
    static final Font FONT = new Font(Font.MONOSPACED, Font.PLAIN, 13);
    private static final Color BOX = new Color(70, 0, 0, 225);
    private static final Color BORDER = new Color(255, 120, 120);
    private static final int PAD = 10;

    private ErrorOverlay() {
    }

    static void paint(Graphics2D g, String heading, String message, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        FontMetrics metrics = g.getFontMetrics();
        int boxWidth = width - 2 * PAD;
        List<String> lines = new ArrayList<>(headingLines(heading, metrics, width));
        int headingCount = lines.size();
        lines.addAll(wrap(message, Math.max(20, (boxWidth - 2 * PAD) / metrics.charWidth('m'))));
        int boxHeight = lines.size() * metrics.getHeight() + 2 * PAD;
        int top = Math.max(0, height - PAD - boxHeight);
        g.setColor(BOX);
        g.fillRect(PAD, top, boxWidth, boxHeight);
        g.setColor(BORDER);
        g.drawRect(PAD, top, boxWidth - 1, boxHeight - 1);
        int baseline = top + PAD + metrics.getAscent();
        for (int i = 0; i < lines.size(); i++) {
            g.setColor(i < headingCount ? BORDER : Color.WHITE);
            g.drawString(lines.get(i), 2 * PAD, baseline);
            baseline += metrics.getHeight();
        }
    }

    /**
     * The heading as the box in a view {@code width} pixels wide shows it, in {@code metrics}' font: whole on one
     * line where it fits, else broken at spaces into lines that each fit the box (a window 320 pixels wide cut
     * "Scene error — the page shows what was" at its right edge), so every word of it is read.
     */
    static List<String> headingLines(String heading, FontMetrics metrics, int width) {
        int room = width - 4 * PAD;
        List<String> lines = new ArrayList<>();
        String line = "";
        for (String word : heading.split(" ")) {
            String longer = line.isEmpty() ? word : line + " " + word;
            if (!line.isEmpty() && metrics.stringWidth(longer) > room) {
                lines.add(line);
                line = word;
            } else {
                line = longer;
            }
        }
        lines.add(line);
        return lines;
    }

    /**
     * Splits the message into lines of at most {@code columns} characters,
     * breaking at a space where one is near. A source line followed by its
     * caret line is cut at the same columns, and the caret goes under the
     * piece that holds its character.
     */
    public static List<String> wrap(String message, int columns) {
        List<String> lines = new ArrayList<>();
        String[] given = message.split("\n", -1);
        for (int i = 0; i < given.length; i++) {
            if (i + 1 < given.length && isCaretUnder(given[i + 1], given[i]) && given[i].length() > columns) {
                wrapWithCaret(given[i], given[i + 1].indexOf('^'), columns, lines);
                i++;
            } else {
                wrapText(given[i], columns, lines);
            }
        }
        return lines;
    }

    private static boolean isCaretUnder(String caretLine, String sourceLine) {
        return caretLine.matches(" *\\^") && sourceLine.startsWith(INDENT);
    }

    private static final String INDENT = "    ";

    private static void wrapWithCaret(String source, int caret, int columns, List<String> lines) {
        String text = source.substring(INDENT.length());
        int piece = Math.max(1, columns - INDENT.length());
        int caretAt = caret - INDENT.length();
        for (int from = 0; from < text.length(); from += piece) {
            int to = Math.min(text.length(), from + piece);
            lines.add(INDENT + text.substring(from, to));
            if (caretAt >= from && (caretAt < to || to == text.length())) {
                lines.add(INDENT + " ".repeat(caretAt - from) + "^");
            }
        }
    }

    private static void wrapText(String line, int columns, List<String> lines) {
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
}
