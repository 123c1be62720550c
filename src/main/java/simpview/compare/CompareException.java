package simpview.compare;

/**
 * A picture that cannot be compared: missing, unreadable, corrupt, too small,
 * or without a panel in it. The message is for the user and names the file.
 */
public final class CompareException extends Exception {

    private static final long serialVersionUID = 1L;

    public CompareException(String message) {
        super(message);
    }

    public CompareException(String message, Throwable cause) {
        super(message, cause);
    }
}
