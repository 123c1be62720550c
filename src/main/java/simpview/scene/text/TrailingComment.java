package simpview.scene.text;

/**
 * A '#' after a line's content. SPEC makes a comment a line of its own, one
 * whose first character that is not blank is '#', in a scene and in a model
 * alike; a '#' after a command is read as part of it, where many other
 * formats would take it as the start of a comment. So an error found at a
 * '#' says this.
 */
public final class TrailingComment {

    /** What an error found at a '#' adds. */
    public static final String HINT = " (a comment is a line of its own, '#' its first character that is not a blank:"
            + " after a command or its numbers, '#' is read as part of them; put the comment on the line above)";

    private TrailingComment() {
    }

    /** {@link #HINT} when the error was found at a '#' (the byte at its place), else "". */
    public static String hint(byte found) {
        return found == '#' ? HINT : "";
    }
}
