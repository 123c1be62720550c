package simpview.scene;

/**
 * The words for Java's memory running out while a scene or a model is read
 * or drawn: what ran out, how much Java may use, and how to give it more.
 * One sentence, never a stack trace; the reader or the command that caught
 * the {@link OutOfMemoryError} says where (the file and line).
 */
public final class MemoryAdvice {

    private MemoryAdvice() {
    }

    /**
     * "out of memory reading this model (Java may use at most 64 MB here):
     * give Java more, ..." for {@code doing}, what was going on.
     */
    public static String outOfMemory(String doing) {
        long most = Runtime.getRuntime().maxMemory();
        String limit = most == Long.MAX_VALUE ? "" : " (Java may use at most " + (most >> 20) + " MB here)";
        return "out of memory " + doing + limit + ": give Java more, e.g. JAVA_OPTS=-Xmx2g before the simpview"
                + " start script, or java -Xmx2g -jar simpview.jar";
    }
}
