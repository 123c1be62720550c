package simpview.window.instruments;

import java.util.List;

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
        return new Legend("heat map: ours against theirs", List.of(
                new Entry(0x404040, "identical (ours, dimmed to a quarter)"),
                new Entry(simpview.compare.HeatMap.WITHIN, "differs by at most " + tolerance + "/255"),
                new Entry(simpview.compare.HeatMap.SLACK_ONLY, "matches only one pixel off (slack)"),
                new Entry(0xC00000, "differs by more, even with slack (brighter: more)")));
    }
}
