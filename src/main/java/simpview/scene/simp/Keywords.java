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

    /** " (did you mean 'polygon'? commands are case-sensitive)" for a near miss of a command word, else "". */
    static String suggestion(String word) {
        java.util.List<String> spellings = new java.util.ArrayList<>();
        for (Kind k : Kind.values()) {
            spellings.add(k.spelling);
        }
        return Nearest.to(word, spellings)
                .map(near -> " (did you mean '" + near + "'?"
                        + (near.equalsIgnoreCase(word) ? " commands are case-sensitive)" : ")"))
                .orElse("");
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
