package simpview.scene.text;

/**
 * Characters that look like ASCII and are not, for an error on the text
 * that holds them: text copied from a PDF or a word processor (the course's
 * handouts) brings a minus sign U+2212 for '-', an en dash, fullwidth
 * brackets and curly quotes for '"', which look right and are read as
 * nothing a scene knows. Others show nothing at all: a non-breaking space,
 * a byte order mark left inside a file where two files were joined (cat
 * a.simp b.simp), a form feed. The message names the first such character
 * by its code point and Unicode name, since it cannot be told apart by eye.
 */
public final class CopiedText {

    /** The curly quotes a word processor makes of '"' and '\'', and the guillemets of a French keyboard. */
    private static final String CURLY_QUOTES = "\u201C\u201D\u201E\u2018\u2019\u00AB\u00BB\u2039\u203A";

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
            if (invisible(cp) != null) {
                return invisibleAt(text, k, cp);
            }
            if (cp > 0x7F) {
                return ", whose '" + new String(Character.toChars(cp)) + "' is " + named(cp) + ", not ASCII: "
                        + (isCurlyQuote(cp) ? "a name is quoted with the ASCII '\"'" : rule)
                        + " (text copied from a PDF or a word processor often looks right and is not)";
            }
            k += Character.charCount(cp);
        }
        return "";
    }

    /**
     * ", which holds a non-breaking space (U+00A0 NO-BREAK SPACE) after '{': use a plain space" for the first
     * character of {@code text} that shows nothing; "" when there is none. For text that is wrong whatever
     * else it holds (what follows a complete command), where an invisible character is the one thing the
     * student cannot see for themselves.
     */
    public static String invisibleHint(String text) {
        for (int k = 0; k < text.length(); ) {
            int cp = text.codePointAt(k);
            if (invisible(cp) != null) {
                return invisibleAt(text, k, cp);
            }
            k += Character.charCount(cp);
        }
        return "";
    }

    /** {@link #hint}'s words for the invisible character cp at k of {@code text}. */
    private static String invisibleAt(String text, int k, int cp) {
        return ", which holds " + invisible(cp) + " (" + named(cp) + ")" + around(text, k, cp) + ": "
                + (isBlankLike(cp) ? "use a plain space" : "delete it" + (cp == 0xFEFF ? " (a file's byte order"
                + " mark is left there when files are joined, as cat a.simp b.simp joins them)" : ""));
    }

    /** Whether cp is a character that shows nothing ({@link #hint} names it). */
    public static boolean isInvisible(int cp) {
        return invisible(cp) != null;
    }

    /** Whether {@code text} holds a character that shows nothing ({@link #hint} names it). */
    public static boolean hasInvisible(String text) {
        return text.codePoints().anyMatch(cp -> invisible(cp) != null);
    }

    /** What an invisible character is, in words ("a non-breaking space"); null for one that shows. */
    private static String invisible(int cp) {
        return switch (cp) {
            case 0x0C -> "a form feed";
            case 0xA0 -> "a non-breaking space";
            case 0x202F -> "a narrow non-breaking space";
            case 0xFEFF -> "a byte order mark";
            case 0x200B -> "a zero-width space";
            case 0x200C, 0x200D, 0x2060 -> "a zero-width character";
            case 0xAD -> "a soft hyphen";
            default -> cp >= 0x2000 && cp <= 0x200A || cp == 0x205F || cp == 0x3000 ? "a wide or narrow space" : null;
        };
    }

    /** Whether the invisible character cp stands where a blank was meant (else it belongs nowhere). */
    private static boolean isBlankLike(int cp) {
        return cp == 0x0C || cp == 0xA0 || cp == 0x202F || cp >= 0x2000 && cp <= 0x200A || cp == 0x205F
                || cp == 0x3000;
    }

    /** " after 'translate'" (what comes before it at k), " before 'wire'" when it comes first; "" when alone. */
    private static String around(String text, int k, int cp) {
        if (k > 0) {
            return " after '" + text.substring(0, k) + "'";
        }
        String rest = text.substring(Character.charCount(cp));
        int next = 0;
        while (next < rest.length() && invisible(rest.codePointAt(next)) == null) {
            next += Character.charCount(rest.codePointAt(next));
        }
        return next == 0 ? "" : " before '" + rest.substring(0, next) + "'";
    }

    /** Whether {@code text} holds a curly quote: a name copied from the handouts' obj “filename”. */
    public static boolean hasCurlyQuote(String text) {
        return text.codePoints().anyMatch(CopiedText::isCurlyQuote);
    }

    /**
     * The name {@code name} would be, written between straight quotes: its curly quotes and guillemets
     * dropped, and a straight '"' beside them too (file “cube" is the name “cube" to a reader that
     * quotes with '"' only, whose quote was meant to close it).
     */
    public static String withoutQuotes(String name) {
        StringBuilder plain = new StringBuilder(name.length());
        name.codePoints().filter(cp -> cp != '"' && !isCurlyQuote(cp)).forEach(plain::appendCodePoint);
        return plain.toString();
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
