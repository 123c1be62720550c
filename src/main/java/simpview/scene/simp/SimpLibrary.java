package simpview.scene.simp;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import simpview.scene.FileChecksum;
import simpview.scene.FileLook;
import simpview.scene.FileStamp;
import simpview.scene.KeptFiles;

/**
 * The small .simp files of the scenes drawn so far: each one's bytes and its
 * commands as they were read, kept while the file is unchanged, so that a
 * redraw, a second include, or another scene that includes the same file
 * replays the commands instead of reading and scanning the file again. Only
 * a file read to its end without an error is kept, within a budget of bytes
 * (the least recently read go first); a file too big to be read whole is
 * streamed every time and never kept.
 *
 * <p>When it is replayed: always when the file's stamp (real path, size,
 * last-modified time, inode) is the one it was read at and the file has
 * settled ({@link KeptFiles}), or the picture being drawn has read its bytes
 * already; otherwise its bytes are read again and compared with those it was
 * read from, whole, and replayed when they are the same. A replay gives the
 * same commands, lines, columns and messages as a reading.
 *
 * <p>Thread safe: one library may serve several drawing threads (a kept
 * reading never changes). Its owner outlives the pictures: a window, a
 * page renderer, a benchmark.
 */
public final class SimpLibrary {

    /** 32 MB of bytes and recordings: a 64 KB file takes about 300 KB of them. */
    public static final long DEFAULT_BUDGET = 32L << 20;

    private final KeptFiles<Read> files;
    private final long settleMillis;
    private final AtomicInteger reads = new AtomicInteger();
    private final AtomicInteger scans = new AtomicInteger();

    /**
     * A file's bytes and its commands, recorded as it was read to its end without an error, and the checksum of
     * those bytes ({@link FileChecksum}), taken as they were read.
     */
    record Read(byte[] content, Recording recording, long checksum) {

        long bytes() {
            return content.length + recording.bytes();
        }
    }

    public SimpLibrary() {
        this(DEFAULT_BUDGET, KeptFiles.SETTLE_MILLIS);
    }

    /** A library of at most {@code budget} bytes, trusting a stamp alone once its file is {@code settleMillis} old. */
    SimpLibrary(long budget, long settleMillis) {
        this.files = new KeptFiles<>(budget, Read::bytes);
        this.settleMillis = settleMillis;
    }

    /** True when the file looked at is settled: its stamp alone tells a change. */
    boolean settled(FileLook look) {
        return look.settled(settleMillis);
    }

    /**
     * A reader of the small file {@code file} (really {@code real}, stamped
     * {@code stamp} before it is read): replaying its kept commands when it
     * is unchanged, else recording them as it reads them (the caller hands
     * the reader to {@link #keep} once it is done). {@code readThisPicture}
     * is the picture's own set of the files it has read; this adds to it.
     */
    SimpReader open(Path file, Path real, FileStamp stamp, boolean settled, Set<Path> readThisPicture)
            throws IOException {
        KeptFiles.Kept<Read> kept = files.get(real, stamp);
        if (kept != null && (kept.settled() || readThisPicture.contains(real))) {
            return replaying(file, kept.value());
        }
        reads.incrementAndGet();
        byte[] content = Files.readAllBytes(real);
        readThisPicture.add(real);
        if (kept != null && Arrays.equals(kept.value().content(), content)) {
            if (settled) {
                files.settle(real, kept);
            }
            return replaying(file, kept.value());
        }
        scans.incrementAndGet();
        return SimpReader.recording(file, content);
    }

    private static SimpReader replaying(Path file, Read read) {
        return SimpReader.replaying(file, read.content(), read.recording(), read.checksum());
    }

    /** Keeps what {@code done}, a reader {@link #open} gave, recorded, if it read its file to the end. */
    void keep(Path real, FileStamp stamp, boolean settled, SimpReader done) {
        Read read = done.newlyRecorded();
        if (read != null) {
            files.keep(real, stamp, settled, read);
        }
    }

    /** How many times a file's bytes were read (not replayed on its stamp): for tests and statistics. */
    public int readCount() {
        return reads.get();
    }

    /** How many times a file's commands were scanned from its bytes (not replayed): for tests. */
    public int scanCount() {
        return scans.get();
    }

    /** How many files are kept now. */
    public int filesKept() {
        return files.size();
    }

    /** The bytes kept now. */
    public long bytesKept() {
        return files.bytesKept();
    }

    /** Drops every kept file. */
    public void clear() {
        files.clear();
    }
}
