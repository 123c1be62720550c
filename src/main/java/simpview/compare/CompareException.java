package simpview.compare;

/**
 * A picture that cannot be compared: missing, unreadable, corrupt, too small,
 * or without a panel in it. The message is for the user and names the file.
 */
public final class CompareException extends Exception {

    private static final long serialVersionUID = 1L;

    /** @param message what is wrong, for the user, naming the file: "page4.png: no such file" */
    public CompareException(String message) {
        super(message);
    }

    /**
     * @param message what is wrong, for the user, naming the file
     * @param cause the failure that said so (a decoder's, the file system's), for the curious
     */
    public CompareException(String message, Throwable cause) {
        super(message, cause);
    }
}
