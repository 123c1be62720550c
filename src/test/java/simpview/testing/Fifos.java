package simpview.testing;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.api.Assumptions;

/**
 * Named pipes (FIFOs) for the tests of files simpview writes: a FIFO is the
 * kind of file that must be written into, never replaced, and the only one a
 * test may make safely (a device such as /dev/null would be replaced by a
 * regular file if the code under test were wrong, and this machine's tests
 * may run as root).
 */
public final class Fifos {

    /** How long a reader waits for the bytes; long enough for a slow machine, short enough to fail, not hang. */
    private static final long SECONDS = 30;

    private Fifos() {
    }

    /**
     * A new FIFO at {@code file}, made by mkfifo. The test is skipped, saying
     * why, where there is none (Windows has no FIFOs in its file system), and
     * fails instead under CI=true.
     */
    public static Path make(Path file) throws IOException, InterruptedException {
        skipUnless(!System.getProperty("os.name").startsWith("Windows"), "Windows has no FIFOs (mkfifo) in its file system");
        Process mkfifo;
        try {
            mkfifo = new ProcessBuilder("mkfifo", file.toString()).redirectErrorStream(true).start();
        } catch (IOException e) {
            skipUnless(false, "no mkfifo here to make a FIFO: " + e.getMessage());
            throw e;
        }
        String said = new String(mkfifo.getInputStream().readAllBytes());
        skipUnless(mkfifo.waitFor() == 0, "mkfifo could not make a FIFO: " + said);
        return file;
    }

    /** Skips the test, saying {@code why}, unless {@code fine}; under CI=true it fails instead: CI makes FIFOs. */
    private static void skipUnless(boolean fine, String why) {
        if (fine) {
            return;
        }
        if ("true".equalsIgnoreCase(System.getenv("CI"))) {
            fail(why + " (CI=true: the FIFO tests must run)");
        }
        Assumptions.abort(why);
    }

    /**
     * Everything written into {@code fifo}, read by a thread of its own from
     * now on until its writer closes it. The thread is a daemon: when the code
     * under test never opens the FIFO (it replaced it), the reader waits for
     * ever for a writer, and must not keep the tests' JVM from ending.
     * Returns once the reader waits in its open for a writer: a run that
     * opens and closes the FIFO at once (one that failed) would otherwise be
     * over before the reader came, and the reader would wait for ever.
     */
    public static CompletableFuture<byte[]> readAll(Path fifo) throws InterruptedException {
        CompletableFuture<byte[]> bytes = new CompletableFuture<>();
        Thread reader = new Thread(() -> {
            try (InputStream in = Files.newInputStream(fifo)) {
                bytes.complete(in.readAllBytes());
            } catch (IOException | RuntimeException e) {
                bytes.completeExceptionally(e);
            }
        }, "reader of " + fifo.getFileName());
        reader.setDaemon(true);
        reader.start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(SECONDS);
        while (!bytes.isDone() && !opening(reader)) {
            if (System.nanoTime() > deadline) {
                fail("the reader of " + fifo + " did not come to open it in " + SECONDS + " s");
            }
            Thread.sleep(1);
        }
        return bytes;
    }

    /** Whether {@code reader} is in the system's open of a file (where a FIFO's reader waits for a writer). */
    private static boolean opening(Thread reader) {
        for (StackTraceElement frame : reader.getStackTrace()) {
            if (frame.getClassName().equals("sun.nio.fs.UnixNativeDispatcher") && frame.getMethodName().startsWith("open")) {
                return true;
            }
        }
        return false;
    }

    /** What the reader of {@link #readAll} got, or a failure that says it got nothing in time. */
    public static byte[] read(CompletableFuture<byte[]> bytes, Path fifo) throws InterruptedException {
        try {
            return bytes.get(SECONDS, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            return fail("nothing was written into the FIFO " + fifo + " in " + SECONDS + " s; is it still one? "
                    + isFifo(fifo));
        } catch (ExecutionException e) {
            return fail("reading the FIFO " + fifo + " failed", e.getCause());
        }
    }

    /** The kind of file a FIFO is, in the bits of a Unix mode that say the kind (S_IFMT). */
    private static final int FIFO_KIND = 0010000;
    private static final int KIND_BITS = 0170000;

    /**
     * True when {@code file} (not followed, if a link) is a FIFO; where the
     * file system tells no Unix mode, when it is neither a regular file, a
     * folder nor a link.
     */
    public static boolean isFifo(Path file) {
        try {
            return ((Integer) Files.getAttribute(file, "unix:mode", LinkOption.NOFOLLOW_LINKS) & KIND_BITS) == FIFO_KIND;
        } catch (UnsupportedOperationException e) {
            try {
                return Files.readAttributes(file, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).isOther();
            } catch (IOException gone) {
                return false;
            }
        } catch (IOException e) {
            return false;
        }
    }
}
