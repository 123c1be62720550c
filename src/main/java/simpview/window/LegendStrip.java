package simpview.window;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.accessibility.AccessibleContext;
import javax.accessibility.AccessibleRole;
import javax.swing.JComponent;
import simpview.window.instruments.Legend;

/**
 * What an overlay's colours mean, in one line at the menu bar's right end
 * (never over the page, and taking no height from it): the legend's title,
 * then a swatch and its words for each colour. Hidden while there is no
 * legend. On the EDT.
 */
final class LegendStrip extends JComponent {

    private static final long serialVersionUID = 1L;
    private static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 12);
    /** What the legend is drawn in when the menu bar leaves it less room than it wants. */
    private static final Font SMALL = FONT.deriveFont(10f);
    private static final int PAD = 4;

    /** The legends shown, by the overlay that shows each, in the order they came. */
    private final transient Map<String, Legend> legends = new LinkedHashMap<>();

    LegendStrip() {
        setName("legend");
        setVisible(false);
        setFont(FONT);
    }

    /** Shows the legend of the overlay {@code of}, or takes it away (null); the strip hides when it has none. */
    void show(String of, Legend shown) {
        if (shown == null) {
            legends.remove(of);
        } else {
            legends.put(of, shown);
        }
        setVisible(!legends.isEmpty());
        // however little room the menu bar leaves it, the whole legend shows on hovering
        setToolTipText(legends.isEmpty() ? null : words());
        revalidate();
        repaint();
    }

    /** A screen reader's view of the strip: named "legend", described by the legends in words. */
    @Override
    public AccessibleContext getAccessibleContext() {
        if (accessibleContext == null) {
            accessibleContext = new AccessibleJComponent() {
                private static final long serialVersionUID = 1L;

                @Override
                public String getAccessibleName() {
                    return accessibleName != null ? accessibleName : "legend";
                }

                @Override
                public String getAccessibleDescription() {
                    return legends.isEmpty() ? "no overlay shown" : words();
                }

                @Override
                public AccessibleRole getAccessibleRole() {
                    return AccessibleRole.LABEL;
                }
            };
        }
        return accessibleContext;
    }

    /** Takes every legend away. */
    void clear() {
        legends.clear();
        setToolTipText(null);
        setVisible(false);
        revalidate();
        repaint();
    }

    boolean empty() {
        return legends.isEmpty();
    }

    /** The legends as words, for tests and for copying: "title · #rrggbb words · ... | title ...". */
    String text() {
        StringBuilder text = new StringBuilder();
        for (Legend legend : legends.values()) {
            text.append(text.length() == 0 ? "" : " | ").append(legend.title());
            for (Legend.Entry entry : legend.entries()) {
                text.append(" · ").append(String.format("#%06x", entry.rgb())).append(' ').append(entry.means());
            }
        }
        return text.toString();
    }

    /** The legends in words alone: "heat map: same, only 1 px off, ...". */
    private String words() {
        StringBuilder words = new StringBuilder();
        for (Legend legend : legends.values()) {
            words.append(words.length() == 0 ? "" : " | ").append(legend.title()).append(": ");
            words.append(String.join(", ", legend.entries().stream().map(Legend.Entry::means).toList()));
        }
        return words.toString();
    }

    @Override
    public Dimension getPreferredSize() {
        return size(FONT);
    }

    /** The room the legends want in {@code font}: as high as the font's line, so that the menu bar keeps its height. */
    private Dimension size(Font font) {
        FontMetrics metrics = getFontMetrics(font);
        int width = 2 * PAD;
        for (Legend legend : legends.values()) {
            int swatch = metrics.getAscent();
            width += metrics.stringWidth(legend.title() + ":") + 2 * PAD;
            for (Legend.Entry entry : legend.entries()) {
                width += swatch + PAD + metrics.stringWidth(entry.means()) + 3 * PAD;
            }
        }
        return new Dimension(width, metrics.getHeight());
    }

    @Override
    public Dimension getMaximumSize() {
        return getPreferredSize();
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        if (legends.isEmpty()) {
            return;
        }
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(new Color(32, 32, 48));
            g.fillRect(0, 0, getWidth(), getHeight());
            // the room to the menu bar's end, which may be less than the strip was laid out with
            int room = getParent() == null ? getWidth() : Math.min(getWidth(), getParent().getWidth() - getX());
            boolean small = size(FONT).width > room;
            boolean titled = !small || size(SMALL).width <= room;
            g.setFont(small ? SMALL : FONT);
            FontMetrics metrics = g.getFontMetrics();
            int baseline = (getHeight() - metrics.getHeight()) / 2 + metrics.getAscent();
            int swatch = metrics.getAscent();
            int swatchTop = baseline - swatch + 1;
            int x = PAD;
            for (Legend legend : legends.values()) {
                if (titled) {
                    g.setColor(Color.WHITE);
                    g.drawString(legend.title() + ":", x, baseline);
                    x += metrics.stringWidth(legend.title() + ":") + 2 * PAD;
                }
                for (Legend.Entry entry : legend.entries()) {
                    g.setColor(new Color(entry.rgb()));
                    g.fillRect(x, swatchTop, swatch, swatch);
                    g.setColor(Color.GRAY);
                    g.drawRect(x, swatchTop, swatch, swatch);
                    x += swatch + PAD;
                    g.setColor(Color.WHITE);
                    g.drawString(entry.means(), x, baseline);
                    x += metrics.stringWidth(entry.means()) + 3 * PAD;
                }
            }
        } finally {
            g.dispose();
        }
    }
}
