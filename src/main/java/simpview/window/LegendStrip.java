package simpview.window;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import javax.swing.JComponent;
import simpview.window.instruments.Legend;

/**
 * What an overlay's colours mean, in one line under the page (never over
 * it): the legend's title, then a swatch and its words for each colour.
 * Hidden while there is no legend. On the EDT.
 */
final class LegendStrip extends JComponent {

    private static final long serialVersionUID = 1L;
    private static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 12);
    private static final int PAD = 4;

    private transient Legend legend;

    LegendStrip() {
        setName("legend");
        setVisible(false);
        setFont(FONT);
    }

    /** Shows a legend, or hides the strip (null). */
    void show(Legend shown) {
        legend = shown;
        setVisible(shown != null);
        revalidate();
        repaint();
    }

    Legend legend() {
        return legend;
    }

    /** The legend as words, for tests and for copying: "title · [colour] words · ...". */
    String text() {
        if (legend == null) {
            return "";
        }
        StringBuilder text = new StringBuilder(legend.title());
        for (Legend.Entry entry : legend.entries()) {
            text.append(" · ").append(String.format("#%06x", entry.rgb())).append(' ').append(entry.means());
        }
        return text.toString();
    }

    @Override
    public Dimension getPreferredSize() {
        FontMetrics metrics = getFontMetrics(FONT);
        return new Dimension(100, metrics.getHeight() + 2 * PAD);
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        if (legend == null) {
            return;
        }
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(new Color(32, 32, 48));
            g.fillRect(0, 0, getWidth(), getHeight());
            g.setFont(FONT);
            FontMetrics metrics = g.getFontMetrics();
            int baseline = PAD + metrics.getAscent();
            int swatch = metrics.getAscent();
            int x = PAD;
            g.setColor(Color.WHITE);
            g.drawString(legend.title() + ":", x, baseline);
            x += metrics.stringWidth(legend.title() + ":") + 2 * PAD;
            for (Legend.Entry entry : legend.entries()) {
                g.setColor(new Color(entry.rgb()));
                g.fillRect(x, PAD + 1, swatch, swatch);
                g.setColor(Color.GRAY);
                g.drawRect(x, PAD + 1, swatch, swatch);
                x += swatch + PAD;
                g.setColor(Color.WHITE);
                g.drawString(entry.means(), x, baseline);
                x += metrics.stringWidth(entry.means()) + 3 * PAD;
            }
        } finally {
            g.dispose();
        }
    }
}
