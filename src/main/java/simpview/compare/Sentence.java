package simpview.compare;

/** Text made a sentence: ended once, whatever its last words already end in. */
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
}
