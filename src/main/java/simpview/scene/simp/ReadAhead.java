package simpview.scene.simp;

import java.nio.file.Path;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import simpview.scene.SceneException;

/**
 * Reads and interprets a scene on a thread of its own, into a ring of
 * {@link #BATCHES} reusable batches, so that the calling thread only draws.
 * Memory stays bounded: when every batch is full the reader waits.
 *
 * <p>Exactness: the reader stops at the first failure and hands it over
 * inside the batch of the primitives before it, so the drawing thread draws
 * exactly those and then throws it. Closing stops the reader (an interrupt;
 * it polls at every batch) and waits for it to end: no thread outlives a
 * scene, whether it ended, failed or was cancelled.
 */
final class ReadAhead implements AutoCloseable {

    /** Enough for one batch being drawn, one being filled, and some slack between them. */
    static final int BATCHES = 4;
    /** How often a drawing thread waiting for a batch checks that the reader is still alive. */
    private static final long ALIVE_CHECK_MS = 20;

    private final BlockingQueue<PrimitiveBatch> free = new ArrayBlockingQueue<>(BATCHES);
    private final BlockingQueue<PrimitiveBatch> full = new ArrayBlockingQueue<>(BATCHES);
    private final SimpClient client;
    private final long commandsSoFar;
    private final Thread reader;

    private ReadAhead(SimpClient client, Path file, long commandsSoFar) {
        this.client = client;
        this.commandsSoFar = commandsSoFar;
        for (int k = 0; k < BATCHES; k++) {
            free.add(new PrimitiveBatch());
        }
        reader = new Thread(this::read, "simpview-reader " + file.getFileName());
        reader.setDaemon(true);
    }

    /**
     * Goes on reading the scene {@code client}'s files are open on, from the
     * command after the last one it carried out; the client and its files
     * belong to the reader thread from now on, which closes them. {@code top}
     * names the thread; batches end where the calling thread would have
     * reported progress, counting the {@code commandsSoFar} it carried out.
     */
    static ReadAhead start(SimpClient client, Path top, long commandsSoFar) {
        ReadAhead ahead = new ReadAhead(client, top, commandsSoFar);
        ahead.reader.start();
        return ahead;
    }

    /** On the reader thread: fills batches until the scene ends, fails, or close() interrupts. */
    private void read() {
        FileStack files = client.files();
        PrimitiveBatch batch = null;
        try {
            batch = fresh();
            Command c = new Command();
            long commands = commandsSoFar;
            while (files.next(c)) {
                client.execute(c);
                if (++commands % PrimitiveBatch.CAPACITY == 0) {
                    batch.linesRead = files.linesRead();
                    batch.topFileShare = files.topFileShare();
                    full.add(batch); // never blocks: the queue has room for every batch
                    batch = null; // handed over: a failure in fresh() must not touch it
                    batch = fresh();
                }
            }
            batch.linesRead = files.linesRead();
            batch.warnings = client.warnings();
            batch.last = true;
        } catch (InterruptedException e) {
            return; // close() asked: nobody waits for more
        } catch (Throwable t) {
            if (batch == null) {
                return; // cannot happen short of an Error between two batches; next() sees the thread end
            }
            batch.failure = t instanceof SceneException e ? files.placed(e) : t;
        } finally {
            files.close();
            client.sendTo(client.painter());
        }
        full.add(batch);
    }

    private PrimitiveBatch fresh() throws InterruptedException {
        PrimitiveBatch batch = free.take();
        batch.clear();
        client.sendTo(batch);
        return batch;
    }

    /**
     * The next batch, in reading order. An interrupt of the drawing thread
     * cancels the scene (the interrupt stays set).
     */
    PrimitiveBatch next() {
        try {
            while (true) {
                PrimitiveBatch batch = full.poll(ALIVE_CHECK_MS, TimeUnit.MILLISECONDS);
                if (batch != null) {
                    return batch;
                }
                if (!reader.isAlive()) {
                    batch = full.poll(); // it may have handed one over just before ending
                    if (batch == null) {
                        throw new IllegalStateException("the scene reader thread ended without a result");
                    }
                    return batch;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SceneCancelledException();
        }
    }

    /** Gives a drawn batch back to the reader. */
    void recycle(PrimitiveBatch batch) {
        free.add(batch);
    }

    /** Stops the reader if it is still going and waits until it has ended (files closed). */
    @Override
    public void close() {
        reader.interrupt();
        boolean interrupted = false;
        while (true) {
            try {
                reader.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /** Throws what the reader failed with, on the drawing thread. */
    static void rethrow(Throwable t) throws SceneException {
        if (t instanceof SceneException e) {
            throw e;
        }
        if (t instanceof RuntimeException e) {
            throw e;
        }
        if (t instanceof Error e) {
            throw e;
        }
        throw new IllegalStateException("the scene reader failed", t);
    }
}
