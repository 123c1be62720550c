package simpview.cli;

/**
 * A usage error found only once a command has begun its work, e.g.
 * depth-cue colours given for a scene that its first lit command shows to be
 * lit. {@link Main} reports it as it reports any usage error (exit 2).
 */
final class UsageProblem extends RuntimeException {

    private static final long serialVersionUID = 1L;

    UsageProblem(String message) {
        super(message, null, false, false);
    }
}
