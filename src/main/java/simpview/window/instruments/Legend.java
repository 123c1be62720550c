package simpview.window.instruments;

import java.util.List;
import simpview.compare.HeatMap;

/**
 * What an overlay's colours mean, shown in a box over the page's corner:
 * a title and a swatch with its words for each colour.
 */
public record Legend(String title, List<Entry> entries) {

    /** One colour (0xRRGGBB) and what it stands for. */
    public record Entry(int rgb, String means) {
    }

    public Legend {
        entries = List.copyOf(entries);
    }

    /** The compare mode's heat map (HeatMap's colours, the tolerance in 255ths). */
    public static Legend heatMap(int tolerance) {
        return new Legend("heat map", List.of(
                new Entry(0x404040, "identical (ours, dimmed)"),
                new Entry(HeatMap.WITHIN, "within " + tolerance + "/255"),
                new Entry(HeatMap.SLACK_ONLY, "only 1 px off"),
                new Entry(0xC00000, "more (brighter: more)")));
    }
}
