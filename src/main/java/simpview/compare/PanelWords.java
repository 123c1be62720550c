package simpview.compare;

import java.util.ArrayList;
import java.util.List;

/**
 * How the reports name several panels of a page at once ("panels 1-4") and say one hint for all the panels it fits,
 * once: one picture's report ({@code compare --assignment 1}), a batch's progress lines and check's table all say
 * them in these words.
 */
public final class PanelWords {

    private PanelWords() {
    }

    /** "panel 2", "panels 1 and 3", "panels 1-4" (three or more in a row), "panels 1, 2 and 4": k in order. */
    public static String panels(List<Integer> panels) {
        if (panels.size() == 1) {
            return "panel " + panels.get(0);
        }
        boolean inARow = panels.get(panels.size() - 1) - panels.get(0) == panels.size() - 1;
        return "panels " + (inARow && panels.size() > 2 ? panels.get(0) + "-" + panels.get(panels.size() - 1)
                : Sentence.listed(panels.stream().map(String::valueOf).toList()));
    }

    /**
     * The panels (from 1) of a page that share a hint, each group in the order of its first panel: a panel's hint
     * with every later one whose hint is briefly the same ({@link PanelHint#brief}); a hint of the page as a whole
     * ({@link PanelHint#wholePage}) with every panel that has that one. Panels without a hint (null) are in none.
     */
    public static List<List<Integer>> alike(PanelHint[] hints) {
        List<List<Integer>> groups = new ArrayList<>();
        boolean[] grouped = new boolean[hints.length];
        for (int k = 0; k < hints.length; k++) {
            if (hints[k] == null || grouped[k]) {
                continue;
            }
            List<Integer> group = new ArrayList<>(List.of(k + 1));
            for (int j = k + 1; j < hints.length; j++) {
                PanelHint other = hints[j];
                boolean same = other != null && (hints[k].wholePage() ? other == hints[k]
                        : !other.wholePage() && other.brief().equals(hints[k].brief()));
                if (same && !grouped[j]) {
                    group.add(j + 1);
                    grouped[j] = true;
                }
            }
            groups.add(group);
        }
        return groups;
    }

    /**
     * The hint {@code text} of the first of the panels {@code alike} (in order), said once for all of them: when
     * their hints' words differ ({@code sameWords} false: each its own numbers), it says whose numbers these are
     * ("The numbers are panel 1's; panels 2-4 look the same.").
     */
    public static String sharedHint(String text, boolean sameWords, List<Integer> alike) {
        if (sameWords || alike.size() < 2) {
            return text;
        }
        return text + " The numbers are panel " + alike.get(0) + "'s; " + panels(alike.subList(1, alike.size()))
                + (alike.size() == 2 ? " looks" : " look") + " the same.";
    }
}
