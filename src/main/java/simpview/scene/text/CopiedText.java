package simpview.scene.text;

/**
 * Characters that look like ASCII and are not, for an error on the text
 * that holds them: text copied from a PDF or a word processor (the course's
 * handouts) brings a minus sign U+2212 for '-', an en dash, fullwidth
 * brackets and curly quotes for '"', which look right and are read as
 * nothing a scene knows. The message names the first such character by its
 * code point and Unicode name, since it cannot be told apart by eye.
 */
public final class CopiedText {

    /** The curly quotes a word processor makes of '"' and '\''. */
    private static final String CURLY_QUOTES = "\u201C\u201D\u201E\u2018\u2019";

    private CopiedText() {
    }

    /**
     * ", whose '−' is U+2212 MINUS SIGN, not ASCII: {@code rule} (text copied
     * from a PDF ...)" for the first character of {@code text} beyond ASCII;
     * a curly quote is told how a name is quoted instead of {@code rule}.
     * "" when the text is all ASCII.
     *
     * @param rule what is written there instead: "a number is written with the ASCII digits, ..."
     */
    public static String hint(String text, String rule) {
        for (int k = 0; k < text.length(); ) {
            int cp = text.codePointAt(k);
            if (cp > 0x7F) {
                return ", whose '" + new String(Character.toChars(cp)) + "' is " + named(cp) + ", not ASCII: "
                        + (isCurlyQuote(cp) ? "a name is quoted with the ASCII '\"'" : rule)
                        + " (text copied from a PDF or a word processor often looks right and is not)";
            }
            k += Character.charCount(cp);
        }
        return "";
    }

    /** Whether {@code text} holds a curly quote: a name copied from the handouts' obj “filename”. */
    public static boolean hasCurlyQuote(String text) {
        return text.codePoints().anyMatch(CopiedText::isCurlyQuote);
    }

    private static boolean isCurlyQuote(int cp) {
        return CURLY_QUOTES.indexOf(cp) >= 0;
    }

    /** "U+2212 MINUS SIGN": a character's code point and, when Java knows it, its Unicode name. */
    static String named(int cp) {
        String name = Character.getName(cp);
        return "U+" + String.format("%04X", cp) + (name == null ? "" : " " + name);
    }
}
