package simpview.compare;

import java.util.List;

/** Text made a sentence: words listed as a sentence lists them, ended once whatever its last words end in. */
final class Sentence {

    private Sentence() {
    }

    /**
     * The text ended with a full stop, unless it ends a sentence already ("... which bob lacks?" stays as it is,
     * not "lacks?."); blanks at its end are dropped first.
     */
    static String ended(String text) {
        String trimmed = text.stripTrailing();
        if (trimmed.endsWith(".") || trimmed.endsWith("?") || trimmed.endsWith("!")) {
            return trimmed;
        }
        return trimmed + ".";
    }

    /** The words as a sentence lists them: "a", "a and b", "a, b and c" (at least one word). */
    static String listed(List<String> words) {
        int last = words.size() - 1;
        return last == 0 ? words.get(0) : String.join(", ", words.subList(0, last)) + " and " + words.get(last);
    }
}
