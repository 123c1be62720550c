package simpview.scene.simp;

import simpview.scene.simp.Command.Kind;

/** The command words, matched against bytes without making a String. */
final class Keywords {

    /** Most frequent first: a scene is mostly polygons and lines. */
    private static final Kind[] KINDS = {
        Kind.POLYGON, Kind.LINE, Kind.TRANSLATE, Kind.ROTATE, Kind.SCALE, Kind.FILE, Kind.WIRE, Kind.FILLED};
    private static final byte[][] WORDS = new byte[KINDS.length][];

    static {
        for (int k = 0; k < KINDS.length; k++) {
            WORDS[k] = spelling(KINDS[k]).getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        }
    }

    private Keywords() {
    }

    /** How a file spells the command. */
    static String spelling(Kind kind) {
        return switch (kind) {
            case PUSH -> "{";
            case POP -> "}";
            default -> kind.name().toLowerCase(java.util.Locale.ROOT);
        };
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

    private static boolean matches(byte[] word, byte[] b, int from) {
        for (int i = 1; i < word.length; i++) {
            if (word[i] != b[from + i]) {
                return false;
            }
        }
        return true;
    }
}
