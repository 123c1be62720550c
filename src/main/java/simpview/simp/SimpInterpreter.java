package simpview.simp;

import java.nio.file.Path;

/**
 * The reading loop: takes commands from the client's file stack, one at a
 * time, and has the client carry them out. It tells the monitor how far it
 * got and stops when the monitor asks it to.
 */
public final class SimpInterpreter {

    /** Commands between two progress reports and cancel polls (a power of two minus one). */
    private static final long POLL_MASK = 1023;

    private final SimpClient client;
    private final SceneMonitor monitor;

    public SimpInterpreter(SimpClient client, SceneMonitor monitor) {
        this.client = client;
        this.monitor = monitor;
    }

    /** Reads {@code file} and everything it includes, to the end. */
    public void run(Path file) throws SceneException {
        FileStack files = client.files();
        try {
            files.openTop(file);
            Command c = new Command();
            long commands = 0;
            while (files.next(c)) {
                client.execute(c);
                if ((++commands & POLL_MASK) == 0) {
                    report(files);
                }
            }
            monitor.linesRead(files.linesRead());
            int open = client.openBraces();
            if (open > 0) {
                monitor.warning(file.getFileName() + ": " + open + " '{' never closed by the end of the file");
            }
        } finally {
            files.close();
        }
    }

    private void report(FileStack files) {
        monitor.linesRead(files.linesRead());
        if (monitor.cancelled()) {
            throw new SceneCancelledException();
        }
    }
}
