package simpview.cli;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;
import simpview.surface.Colors;

/**
 * Several finished pages side by side at half size, each with its label:
 * the picture in the README. The pages come from our rasterizer; Java2D only
 * tiles them and writes the labels.
 */
public final class ContactSheet {

    static final int COLUMNS = 4;
    static final int TILE = 375;
    static final int LABEL_HEIGHT = 28;
    static final int GAP = 12;

    /** One page of the sheet, kept at the sheet's half size ({@link #of}): a sheet of many scenes holds no page whole. */
    record Tile(String label, BufferedImage half) {

        /** The tile of a finished page (750x750), halved now: the page may be drawn over after. */
        static Tile of(String label, BufferedImage page) {
            return new Tile(label, halved(page));
        }
    }

    private ContactSheet() {
    }

    static BufferedImage compose(List<Tile> tiles) {
        if (tiles.isEmpty()) {
            throw new IllegalArgumentException("a contact sheet needs at least one page");
        }
        int columns = Math.min(COLUMNS, tiles.size());
        int rows = (tiles.size() + COLUMNS - 1) / COLUMNS;
        int cellHeight = TILE + LABEL_HEIGHT;
        BufferedImage sheet = new BufferedImage(GAP + columns * (TILE + GAP), GAP + rows * (cellHeight + GAP),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = sheet.createGraphics();
        try {
            g.setColor(new Color(0xE8E8E8));
            g.fillRect(0, 0, sheet.getWidth(), sheet.getHeight());
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 15));
            for (int i = 0; i < tiles.size(); i++) {
                int x = GAP + (i % COLUMNS) * (TILE + GAP);
                int y = GAP + (i / COLUMNS) * (cellHeight + GAP);
                g.drawImage(tiles.get(i).half(), x, y, null);
                g.setColor(Color.BLACK);
                g.drawString(tiles.get(i).label(), x + 4, y + TILE + LABEL_HEIGHT - 9);
            }
        } finally {
            g.dispose();
        }
        return sheet;
    }

    /** Half size by averaging each 2x2 block: exact and the same on every machine. Two rows read at a time. */
    static BufferedImage halved(BufferedImage page) {
        int w = page.getWidth() / 2;
        int h = page.getHeight() / 2;
        BufferedImage small = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] rows = new int[4 * w]; // the block rows 2y and 2y + 1, 2w pixels each
        int[] out = new int[w];
        for (int y = 0; y < h; y++) {
            page.getRGB(0, 2 * y, 2 * w, 2, rows, 0, 2 * w);
            for (int x = 0; x < w; x++) {
                out[x] = average(rows[2 * x], rows[2 * x + 1], rows[2 * w + 2 * x], rows[2 * w + 2 * x + 1]);
            }
            small.setRGB(0, y, w, 1, out, 0, w);
        }
        return small;
    }

    /** The four pixels' mean, each channel rounded half up. */
    private static int average(int a, int b, int c, int d) {
        int r = Colors.red(a) + Colors.red(b) + Colors.red(c) + Colors.red(d);
        int g = Colors.green(a) + Colors.green(b) + Colors.green(c) + Colors.green(d);
        int bl = Colors.blue(a) + Colors.blue(b) + Colors.blue(c) + Colors.blue(d);
        return 0xFF000000 | (r + 2) / 4 << 16 | (g + 2) / 4 << 8 | (bl + 2) / 4;
    }
}
