package simpview.scene.simp;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import simpview.stage.Painter;
import simpview.scene.MemoryAdvice;
import simpview.scene.SceneException;

/**
 * The reading loop: takes commands from the client's file stack, one at a
 * time, and has the client carry them out. It tells the monitor how far it
 * got and stops when the monitor asks it to.
 *
 * <p>A big scene is read on a second thread ({@link ReadAhead}) while this
 * one draws; the monitor sees the same calls, in the same places, either way.
 */
public final class SimpInterpreter {

    /** Commands between two progress reports and cancel polls (a power of two). */
    static final int COMMANDS_PER_POLL = 1024;
    private static final long POLL_MASK = COMMANDS_PER_POLL - 1;
    /**
     * Top files from this size on are read ahead on a second thread. Smaller
     * scenes take a few milliseconds at most, less than starting a thread saves.
     */
    static final long READ_AHEAD_FROM = 1 << 20;

    private final SimpClient client;
    private final SceneMonitor monitor;
    private final long readAheadFrom;

    public SimpInterpreter(SimpClient client, SceneMonitor monitor) {
        this(client, monitor, READ_AHEAD_FROM);
    }

    /**
     * An interpreter that reads and draws on the calling thread only, however
     * big the scene: each primitive is drawn while its command is being
     * carried out (the inspector's replay asks the file stack where it stands).
     */
    public static SimpInterpreter onOneThread(SimpClient client, SceneMonitor monitor) {
        return new SimpInterpreter(client, monitor, Long.MAX_VALUE);
    }

    /** @param readAheadFrom top-file size from which to read on a second thread; Long.MAX_VALUE never */
    SimpInterpreter(SimpClient client, SceneMonitor monitor, long readAheadFrom) {
        this.client = client;
        this.monitor = monitor;
        this.readAheadFrom = readAheadFrom;
    }

    /**
     * Reads {@code file} and everything it includes, to the end. The first
     * commands are read here; once the first primitive is drawn the scene's
     * rules are known (a lit scene's camera comes before it), and a big
     * depth-cued scene goes on reading on a second thread while this one
     * draws.
     */
    public void run(Path file) throws SceneException {
        FileStack files = client.files();
        boolean handedOver = false;
        try {
            files.openTop(file);
            Command c = new Command();
            long commands = 0;
            boolean firstDrawn = false;
            while (next(files, c)) {
                if ((++commands & POLL_MASK) == 0) {
                    report(files.linesRead(), files.topFileShare());
                }
                if (!firstDrawn && client.drew()) {
                    firstDrawn = true;
                    if (readAhead(file)) {
                        handedOver = true;
                        runReadingAhead(file, commands);
                        return;
                    }
                }
            }
            finish(files.linesRead(), client.warnings());
        } finally {
            if (!handedOver) {
                files.close();
            }
        }
    }

    /** Big depth-cued scenes only: a lit scene draws as it reads, with the state at each command. */
    private boolean readAhead(Path file) {
        if (client.isLit()) {
            return false;
        }
        try {
            // The size first: in a container each processor count asked 20 ms after the last reads the
            // cgroup's files again (0.06-0.16 ms a call; DrawingThreads.coreEach), and most scenes are small.
            return Files.size(file) >= readAheadFrom && Runtime.getRuntime().availableProcessors() > 1;
        } catch (IOException | SecurityException e) {
            return false; // reading here reports the problem properly
        }
    }

    /** Reads the next command and carries it out; an error in an included file names the lines that included it. */
    private boolean next(FileStack files, Command c) throws SceneException {
        try {
            if (!files.next(c)) {
                return false;
            }
            client.execute(c);
            return true;
        } catch (SceneException e) {
            throw files.placed(e);
        } catch (OutOfMemoryError e) {
            if (files.depth() == 0) {
                throw e; // between files: the scene's drawing names the top file
            }
            SimpReader at = files.current();
            throw files.placed(new SceneException(at.file(), at.lineNumber(), 0, "",
                    MemoryAdvice.outOfMemory("reading and drawing the scene at this line")));
        }
    }

    /** Draws the batches the reading thread fills; each ends where runHere would report. */
    private void runReadingAhead(Path file, long commandsSoFar) throws SceneException {
        Painter painter = client.painter();
        try (ReadAhead ahead = ReadAhead.start(client, file, commandsSoFar)) {
            while (true) {
                PrimitiveBatch batch = ahead.next();
                batch.drawAll(painter);
                if (batch.failure != null) {
                    ReadAhead.rethrow(batch.failure);
                }
                if (batch.last) {
                    finish(batch.linesRead, batch.warnings);
                    return;
                }
                report(batch.linesRead, batch.topFileShare);
                ahead.recycle(batch);
            }
        }
    }

    private void report(long linesRead, double topFileShare) {
        monitor.linesRead(linesRead);
        monitor.topFileRead(topFileShare);
        if (monitor.cancelled()) {
            throw new SceneCancelledException();
        }
    }

    private void finish(long linesRead, List<String> warnings) {
        monitor.linesRead(linesRead);
        monitor.topFileRead(1);
        for (String w : warnings) {
            monitor.warning(w);
        }
    }
}
