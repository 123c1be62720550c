package simpview.window;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The key help (F1) as drawn: whole in a large window; in a small one cut with "…", and what is left out named. */
class HelpOverlayTest {

    private static List<HelpOverlay.Drawn> drawn(int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            return HelpOverlay.paint(g, width, height);
        } finally {
            g.dispose();
        }
    }

    /** Every input, every "does" and every heading the help has. */
    private static List<String> whole() {
        List<String> texts = new ArrayList<>();
        for (KeyHelp.Row row : KeyHelp.ROWS) {
            texts.add(row.does());
            if (!row.heading()) {
                texts.add(row.input());
            }
        }
        return texts;
    }

    private static String joined(List<HelpOverlay.Drawn> drawn) {
        StringBuilder all = new StringBuilder();
        for (HelpOverlay.Drawn text : drawn) {
            all.append(text.text()).append('\n');
        }
        return all.toString();
    }

    @Test
    void inASmallWindowEveryTextIsInsideItCutWithAnEllipsisAndEverySectionIsShownOrNamed() {
        int[][] sizes = {{410, 340}, {320, 190}, {600, 300}, {760, 420}, {1000, 260}};
        for (int[] size : sizes) {
            int width = size[0];
            int height = size[1];
            List<HelpOverlay.Drawn> drawn = drawn(width, height);
            String where = " in " + width + "x" + height;
            for (HelpOverlay.Drawn text : drawn) {
                assertTrue(text.x() >= 0 && text.x() + text.width() <= width && text.baseline() <= height,
                        "'" + text.text() + "' at " + text.x() + ".." + (text.x() + text.width()) + ", baseline "
                                + text.baseline() + where);
                for (String full : whole()) {
                    assertFalse(!whole().contains(text.text()) && full.startsWith(text.text()) && text.text().length() > 2,
                            "'" + text.text() + "' is cut without \"…\" from '" + full + "'" + where);
                }
            }
            String all = joined(drawn);
            for (KeyHelp.Row row : KeyHelp.ROWS) {
                if (row.heading()) {
                    String named = row.does().endsWith(" menu") ? row.does() : row.does().toLowerCase();
                    assertTrue(all.replace('\n', ' ').contains(named), "the section " + row.does() + " shown or named"
                            + where + ":\n" + all);
                }
            }
            boolean everyRow = KeyHelp.ROWS.stream().filter(r -> !r.heading())
                    .allMatch(r -> drawn.stream().anyMatch(d -> d.text().equals(r.input())
                            || d.text().endsWith("…") && r.input().startsWith(d.text().substring(0, d.text().length() - 1))));
            assertTrue(everyRow || all.contains("Not shown"), "rows left out, and said so" + where + ":\n" + all);
        }
    }

    @Test
    void inALargeWindowEverythingIsShownWhole() {
        List<HelpOverlay.Drawn> drawn = drawn(1280, 960);
        String all = joined(drawn);
        assertFalse(all.contains("Not shown") || all.contains("cut short"), all);
        for (HelpOverlay.Drawn text : drawn) {
            assertTrue(whole().contains(text.text()) || !text.text().endsWith("…"), "nothing cut: " + text.text());
        }
        for (KeyHelp.Row row : KeyHelp.ROWS) {
            String first = row.heading() ? row.does() : row.input();
            assertTrue(drawn.stream().anyMatch(d -> d.text().equals(first)), first);
        }
    }
}
