package simpview.surface;

/**
 * Told what the threads of a {@link BandQueue} do, as they do it: for a
 * timeline of where a picture's time goes on each thread (the benchmark
 * {@code BandTimeline}), never for drawing. Set on the {@link DrawingThreads}
 * ({@link DrawingThreads#watchedBy}); the queues made after that tell it.
 * Each call comes on the thread it speaks of, so a watch that keeps a
 * timeline takes the time and the thread itself. A watch must be thread safe,
 * and quick: it runs on the drawing threads, some calls with the queue's lock
 * held.
 */
public interface BandWatch {

    /**
     * Batch {@code batch} is handed in, to be drawn in bands; batches are
     * counted from 0 in each queue, and a picture drawn from a record makes
     * its own queue.
     */
    void handedIn(int batch);

    /** This thread starts drawing band {@code band} of batch {@code batch}. */
    void drawing(int batch, int band);

    /** This thread has drawn what {@link #drawing} said. */
    void drawn(int batch, int band);

    /** This thread parks until something changes (it has spun a while first). */
    void parked();

    /** This thread is awake again after {@link #parked}. */
    void woken();
}
