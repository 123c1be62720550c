package simpview.cli;

import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import simpview.pages.A1Layout;

/**
 * The names of a batch's diff images, unique in the run. A picture's is its path with the folders joined
 * by '_' and its ending dropped (alice/page3.png: diffs/alice_page3-diff.png; panel k of a first-assignment
 * page: diffs/alice_a1-page2-panelK-diff.png). Pictures that would share a name (s/t_page1.png and
 * s_t/page1.png, u/page2.png and u/page2.jpg, or names that differ only in case, which are one file on a
 * Mac or Windows) are told apart in the table's order: the first keeps it, the next is named -2, then -3
 * (u_page2-2-diff.png). The names are fixed before any picture is compared, so they do not depend on which
 * comparison finishes first, and a made-up name never takes one another picture has by its own path.
 */
final class DiffNames {

    /** How every diff image's name ends. */
    static final String ENDING = "-diff.png";

    private final Map<String, String> stems;

    private DiffNames(Map<String, String> stems) {
        this.stems = stems;
    }

    /** The names of the diff images of {@code relatives}: the pictures' paths in the folder, in the table's order. */
    static DiffNames of(List<String> relatives) {
        Set<String> ownNames = new HashSet<>();
        relatives.forEach(relative -> ownNames.addAll(keys(plainStem(relative))));
        Set<String> taken = new HashSet<>();
        Map<String, String> stems = new HashMap<>();
        for (String relative : relatives) {
            String plain = plainStem(relative);
            String stem = plain;
            for (int k = 2; !Collections.disjoint(taken, keys(stem))
                    || !stem.equals(plain) && !Collections.disjoint(ownNames, keys(stem)); k++) {
                stem = plain + "-" + k;
            }
            taken.addAll(keys(stem));
            stems.put(relative, stem);
        }
        return new DiffNames(stems);
    }

    /**
     * The diff image of a picture (its path in the folder), relative to the out folder: of its panel (0), or of
     * a first-assignment page's panel.
     */
    String of(String relative, int panel) {
        return CompareBatch.DIFFS + "/" + name(stems.getOrDefault(relative, plainStem(relative)), panel);
    }

    /** "alice_page3" for alice/page3.png. */
    private static String plainStem(String relative) {
        return relative.replaceAll("[/\\\\]", "_").replaceFirst("\\.[^.]*$", "");
    }

    private static String name(String stem, int panel) {
        return stem + (panel == 0 ? "" : "-panel" + panel) + ENDING;
    }

    /** Every name a stem may give diff images (a page's, and a first-assignment page's panels), case folded. */
    private static Set<String> keys(String stem) {
        Set<String> keys = new HashSet<>();
        for (int panel = 0; panel <= A1Layout.PANELS; panel++) {
            keys.add(name(stem, panel).toLowerCase(Locale.ROOT));
        }
        return keys;
    }
}
