package simpview.scene.simp;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import simpview.scene.Nearest;
import simpview.scene.simp.Command.Kind;

/** The command words of {@link Kind}, matched against bytes without making a String. */
final class Keywords {

    /** Every word-spelled kind, most frequent first: a scene is mostly polygons and lines. */
    private static final Kind[] KINDS;
    private static final byte[][] WORDS;

    static {
        List<Kind> kinds = new ArrayList<>(List.of(Kind.POLYGON, Kind.LINE));
        for (Kind k : Kind.values()) {
            if (!kinds.contains(k) && k != Kind.PUSH && k != Kind.POP) {
                kinds.add(k);
            }
        }
        KINDS = kinds.toArray(new Kind[0]);
        WORDS = new byte[KINDS.length][];
        for (int k = 0; k < KINDS.length; k++) {
            WORDS[k] = KINDS[k].spelling.getBytes(StandardCharsets.US_ASCII);
        }
    }

    private Keywords() {
    }

    /** The command spelled by b[from, to), case-sensitively; null when there is none. */
    static Kind kind(byte[] b, int from, int to) {
        int length = to - from;
        for (int k = 0; k < KINDS.length; k++) {
            byte[] w = WORDS[k];
            if (w.length == length && w[0] == b[from] && matches(w, b, from)) {
                return KINDS[k];
            }
        }
        return null;
    }

    /**
     * " (did you mean 'polygon'? commands are case-sensitive)" for a near
     * miss of a command word, else "". A word is near when it differs only
     * in case, or by at most one edit in three of its letters (and not in
     * all of them): 'scal' is near 'scale', 'v' or 'x' near nothing. The
     * only commands of one character are the brackets, so a one-character
     * word is near '{' or '}' only when it is another bracket. A word of
     * three letters or more that begins a command word is near it as by one
     * edit ('fill' is 'filled' cut short). Between words equally near, one
     * that takes arguments when the line has some, or none when it has
     * none, is meant: 'fill' and 'filed' alone on a line are 'filled' (file
     * takes a name), 'fill "cube"' is 'file'. A word near none, but
     * another language's for a command ('include', 'push'), is told the
     * SIMP word ({@link WordsElsewhere}).
     *
     * @param arguments whether anything follows the word on its line
     */
    static String suggestion(String word, boolean arguments) {
        String near = word.length() == 1 ? bracket(word.charAt(0)) : nearestWord(word, arguments);
        return near == null ? WordsElsewhere.hint(word) : " (did you mean '" + near + "'?"
                + (near.equalsIgnoreCase(word) ? " commands are case-sensitive)" : ")");
    }

    /** '{' for an opening bracket other than it, '}' for a closing one; else null. */
    private static String bracket(char c) {
        return "([<\uFF08\uFF3B".indexOf(c) >= 0 ? "{" : ")]>\uFF09\uFF3D".indexOf(c) >= 0 ? "}" : null;
    }

    /** The command word near {@code word} (two characters or more), or null. */
    private static String nearestWord(String word, boolean arguments) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (Kind k : KINDS) {
            int d = k.spelling.equalsIgnoreCase(word) ? 0 : Nearest.distance(word, k.spelling);
            if (word.length() >= 3 && k.spelling.startsWith(word)) {
                d = Math.min(d, 1);
            }
            // doubled, so that a word fitting the line's arguments wins a tie and never loses to a nearer one
            int fit = 2 * d + ((k.shape != Command.Shape.NONE) == arguments ? 0 : 1);
            if (fit < bestDistance) {
                best = k.spelling;
                bestDistance = fit;
            }
        }
        int allowed = Math.min(Math.max(1, word.length() / 3), word.length() - 1);
        return bestDistance / 2 <= allowed ? best : null;
    }

    /**
     * Whether {@code word} is one an .obj model's lines start with ('v',
     * 'vn', 'vt', 'f'), for the error of a model read as a scene.
     */
    static boolean startsModelLine(String word) {
        return word.equals("v") || word.equals("vn") || word.equals("vt") || word.equals("f");
    }

    /** Every command's spelling, for "expected ..." messages: "{, }, scale, ..., phong". */
    static String all() {
        StringBuilder sb = new StringBuilder();
        Kind[] all = Kind.values();
        for (int k = 0; k < all.length; k++) {
            sb.append(k == 0 ? "" : k == all.length - 1 ? " or " : ", ").append(all[k].spelling);
        }
        return sb.toString();
    }

    private static boolean matches(byte[] word, byte[] b, int from) {
        for (int i = 1; i < word.length; i++) {
            if (word[i] != b[from + i]) {
                return false;
            }
        }
        return true;
    }
}
