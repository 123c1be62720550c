package simpview.simp;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * The lines of one file as byte ranges in a buffer, read in chunks so that a
 * file of any length needs only one buffer of memory. A source can also be a
 * whole small file already in memory.
 *
 * <p>A file-backed source can {@link #suspend()}: it closes its file and
 * drops its buffer, remembering the offset of the next line, and reopens the
 * file there when asked for another line. That keeps a deep include chain
 * from holding a file descriptor per level.
 */
final class LineSource {

    static final int CHUNK = 64 * 1024;
    /** Longer lines are refused: a line must fit in memory, and no real scene comes close. */
    static final int MAX_LINE = 1 << 20;

    private final Path path;
    private FileChannel channel;
    private boolean fileBacked;
    private byte[] buf;
    private int pos;
    private int limit;
    private boolean eof;
    /** File offset of buf[0]. */
    private long bufferOffset;
    /** Where to go on with a suspended source. */
    private long resumeOffset;

    int lineStart;
    int lineEnd;
    int lineNumber;

    private LineSource(Path path) {
        this.path = path;
    }

    static LineSource open(Path path) throws IOException {
        LineSource s = new LineSource(path);
        s.fileBacked = true;
        s.channel = FileChannel.open(path, StandardOpenOption.READ);
        s.buf = new byte[CHUNK];
        return s;
    }

    /** A source over bytes already in memory (a small file read whole, or a test's text). */
    static LineSource of(Path path, byte[] content) {
        LineSource s = new LineSource(path);
        s.buf = content;
        s.limit = content.length;
        s.eof = true;
        return s;
    }

    Path path() {
        return path;
    }

    byte[] buffer() {
        return buf;
    }

    /**
     * Moves to the next line; its bytes are buffer()[lineStart, lineEnd), without
     * the line break and without trailing carriage returns.
     *
     * @return false at the end of the file
     */
    boolean nextLine() throws IOException {
        if (buf == null) {
            resume();
        }
        while (true) {
            byte[] b = buf;
            for (int i = pos; i < limit; i++) {
                if (b[i] == '\n') {
                    setLine(pos, i);
                    pos = i + 1;
                    return true;
                }
            }
            if (eof) {
                if (pos < limit) {
                    setLine(pos, limit);
                    pos = limit;
                    return true;
                }
                return false;
            }
            fill();
        }
    }

    private void setLine(int start, int end) {
        int e = end;
        while (e > start && buf[e - 1] == '\r') {
            e--;
        }
        lineStart = start;
        lineEnd = e;
        lineNumber++;
    }

    /** Keeps the unread bytes and reads more after them; grows the buffer for a long line. */
    private void fill() throws IOException {
        if (pos > 0) {
            System.arraycopy(buf, pos, buf, 0, limit - pos);
            bufferOffset += pos;
            limit -= pos;
            pos = 0;
        }
        if (limit == buf.length) {
            if (buf.length >= MAX_LINE) {
                throw new LineTooLongException();
            }
            byte[] bigger = new byte[Math.min(MAX_LINE, buf.length * 2)];
            System.arraycopy(buf, 0, bigger, 0, limit);
            buf = bigger;
        }
        int n = channel.read(ByteBuffer.wrap(buf, limit, buf.length - limit));
        if (n < 0) {
            eof = true;
        } else {
            limit += n;
        }
    }

    /** Lets go of the file (not of the place in it); the next line reopens it. */
    void suspend() throws IOException {
        if (!fileBacked || buf == null) {
            return;
        }
        resumeOffset = bufferOffset + pos;
        buf = null;
        closeChannel();
    }

    boolean holdsFile() {
        return channel != null;
    }

    boolean suspended() {
        return buf == null;
    }

    private void resume() throws IOException {
        channel = FileChannel.open(path, StandardOpenOption.READ);
        channel.position(resumeOffset);
        buf = new byte[CHUNK];
        bufferOffset = resumeOffset;
        pos = 0;
        limit = 0;
        eof = false;
    }

    void close() throws IOException {
        closeChannel();
    }

    private void closeChannel() throws IOException {
        if (channel != null) {
            FileChannel c = channel;
            channel = null;
            c.close();
        }
    }

    /** A line longer than {@link #MAX_LINE}; the reader turns it into a SceneException. */
    static final class LineTooLongException extends IOException {
        private static final long serialVersionUID = 1L;

        LineTooLongException() {
            super("a line is longer than " + MAX_LINE + " bytes");
        }
    }
}
