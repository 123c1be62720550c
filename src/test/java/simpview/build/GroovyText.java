package simpview.build;

/**
 * Views of a Groovy script that keep every offset and line: comments
 * blanked, then string contents blanked (their quotes stay), so patterns
 * and braces are matched on code only.
 */
final class GroovyText {

    private GroovyText() {
    }

    /** The script with // and /* *&#47; comments turned into spaces (newlines kept). */
    static String withoutComments(String s) {
        return blank(s, true, false);
    }

    /**
     * The script with the characters inside quotes turned into spaces, but
     * for a double-quoted string's interpolations ({@code $name.name},
     * {@code ${...}}), which are code.
     */
    static String withoutStrings(String s) {
        return blank(s, false, true);
    }

    private static String blank(String s, boolean comments, boolean strings) {
        StringBuilder out = new StringBuilder(s);
        int i = 0;
        while (i < s.length()) {
            char c = s.charAt(i);
            if (c == '/' && i + 1 < s.length() && (s.charAt(i + 1) == '/' || s.charAt(i + 1) == '*')) {
                int end = s.charAt(i + 1) == '/' ? lineEnd(s, i) : blockCommentEnd(s, i);
                if (comments) {
                    spaces(out, i, end);
                }
                i = end;
            } else if (c == '\'' || c == '"') {
                int end = stringEnd(s, i);
                int quote = s.startsWith(String.valueOf(c).repeat(3), i) ? 3 : 1;
                if (strings) {
                    int from = i + quote;
                    int to = Math.max(from, end - quote);
                    if (c == '"') {
                        blankKeepingInterpolations(s, out, from, to);
                    } else {
                        spaces(out, from, to);
                    }
                }
                i = end;
            } else {
                i++;
            }
        }
        return out.toString();
    }

    private static int lineEnd(String s, int from) {
        int end = s.indexOf('\n', from);
        return end < 0 ? s.length() : end;
    }

    private static int blockCommentEnd(String s, int from) {
        int end = s.indexOf("*/", from + 2);
        return end < 0 ? s.length() : end + 2;
    }

    /** The offset just past the string that opens at {@code from}. */
    private static int stringEnd(String s, int from) {
        char q = s.charAt(from);
        String triple = String.valueOf(q).repeat(3);
        if (s.startsWith(triple, from)) {
            int end = s.indexOf(triple, from + 3);
            return end < 0 ? s.length() : end + 3;
        }
        for (int i = from + 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\') {
                i++;
            } else if (c == q || c == '\n') {
                return i + 1;
            }
        }
        return s.length();
    }

    /** Blanks s[from, to), a double-quoted string's inside, but for its interpolations. */
    private static void blankKeepingInterpolations(String s, StringBuilder out, int from, int to) {
        int i = from;
        while (i < to) {
            char c = s.charAt(i);
            int kept = i;
            if (c == '\\') {
                i = Math.min(to, i + 2);
            } else if (c == '$' && i + 1 < to && s.charAt(i + 1) == '{') {
                int depth = 0;
                while (i < to) {
                    char d = s.charAt(i++);
                    if (d == '{') {
                        depth++;
                    } else if (d == '}' && --depth == 0) {
                        break;
                    }
                }
                continue;
            } else if (c == '$' && i + 1 < to && Character.isJavaIdentifierStart(s.charAt(i + 1))) {
                i++;
                while (i < to && (Character.isJavaIdentifierPart(s.charAt(i)) || s.charAt(i) == '.')) {
                    i++;
                }
                continue;
            } else {
                i++;
            }
            spaces(out, kept, i);
        }
    }

    private static void spaces(StringBuilder out, int from, int to) {
        for (int i = from; i < to; i++) {
            if (out.charAt(i) != '\n') {
                out.setCharAt(i, ' ');
            }
        }
    }

    /** The offset of the brace that closes the one at {@code open} (the text's length when none does). */
    static int matchingBrace(String bare, int open) {
        int depth = 0;
        for (int i = open; i < bare.length(); i++) {
            char c = bare.charAt(i);
            if (c == '{') {
                depth++;
            } else if (c == '}' && --depth == 0) {
                return i;
            }
        }
        return bare.length();
    }
}
