package simpview.scene.text;

import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.zip.CRC32C;
import simpview.scene.SceneException;

/**
 * The lines of one file as byte ranges in a buffer, read in chunks so that a
 * file of any length needs only one buffer of memory. A source can also be a
 * whole small file already in memory.
 *
 * <p>A file-backed source can {@link #suspend()}: it closes its file and
 * drops its buffer, remembering the offset of the next line, and reopens the
 * file there when asked for another line. That keeps a deep include chain
 * from holding a file descriptor per level.
 *
 * <p>Public for the other readers of line-oriented text (the .obj reader):
 * they read lines through {@link #nextLine()}, {@link #buffer()},
 * {@link #lineStart()}, {@link #lineEnd()} and {@link #lineNumber()}.
 */
public final class LineSource {

    public static final int CHUNK = 64 * 1024;
    /** Eight bytes of a byte[] read as one long, so the line break is looked for eight bytes at a time. */
    private static final VarHandle LONGS = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);
    private static final long NEWLINES = 0x0A0A0A0A0A0A0A0AL;
    private static final long ONES = 0x0101010101010101L;
    private static final long HIGH_BITS = 0x8080808080808080L;
    /** Longer lines are refused: a line must fit in memory, and no real scene comes close. */
    public static final int MAX_LINE = 1 << 20;

    private final Path path;
    /** The CRC-32C of every byte read so far, when asked for ({@link #checksummed}); else null. */
    private CRC32C crc;
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

    public static LineSource open(Path path) throws IOException {
        LineSource s = new LineSource(path);
        s.fileBacked = true;
        s.channel = FileChannel.open(path, StandardOpenOption.READ);
        s.buf = new byte[CHUNK];
        return s;
    }

    /** A source over bytes already in memory (a small file read whole, or a test's text). */
    public static LineSource of(Path path, byte[] content) {
        LineSource s = new LineSource(path);
        s.buf = content;
        s.limit = content.length;
        s.eof = true;
        return s;
    }

    /**
     * From now on (call it before the first line) keeps the CRC-32C of the
     * bytes read, so that a reader that reads a file to its end learns its
     * checksum without reading it a second time ({@link #checksum}).
     */
    public LineSource checksummed() {
        crc = new CRC32C();
        if (!fileBacked) {
            crc.update(buf, 0, limit);
        }
        return this;
    }

    /** The CRC-32C of the bytes read so far: of the whole file once it was read to its end (as FileChecksum gives it). */
    public long checksum() {
        return crc.getValue();
    }

    public Path path() {
        return path;
    }

    /** The buffer holding the current line; it may change at every {@link #nextLine()}. */
    public byte[] buffer() {
        return buf;
    }

    /** Where the current line starts in {@link #buffer()}. */
    public int lineStart() {
        return lineStart;
    }

    /** Just past the current line's last byte in {@link #buffer()} (line break and trailing CRs excluded). */
    public int lineEnd() {
        return lineEnd;
    }

    /**
     * Puts the reader back on a line it read before (a replayed command of a
     * file kept in memory): its number and where it starts in the buffer.
     */
    public void standOn(int number, int start, int end) {
        lineNumber = number;
        lineStart = start;
        lineEnd = end;
    }

    /** Where the current line starts in the file, in bytes from its first. */
    public long lineOffset() {
        return bufferOffset + lineStart;
    }

    /**
     * For a message about the current line: a hint when it holds a carriage
     * return, which only a file whose lines end in CR alone (old Mac files)
     * leaves inside a line, so that the whole file reads as one line; else "".
     */
    public String lineEndHint() {
        for (int i = lineStart; i < lineEnd; i++) {
            if (buf[i] == '\r') {
                return " (this file's lines end in a carriage return alone, so it reads as one line: "
                        + "save it with LF or CR LF line ends)";
            }
        }
        return "";
    }

    /** The 1-based number of the current line. */
    public int lineNumber() {
        return lineNumber;
    }

    /**
     * Moves to the next line; its bytes are buffer()[lineStart, lineEnd), without
     * the line break and without trailing carriage returns.
     *
     * @return false at the end of the file
     */
    public boolean nextLine() throws IOException {
        if (buf == null) {
            resume();
        }
        while (true) {
            int i = indexOfNewline(buf, pos, limit);
            if (i >= 0) {
                setLine(pos, i);
                pos = i + 1;
                return true;
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

    /**
     * The index of the first '\n' in b[from, to), or -1. Per long: x has a
     * zero byte where b has '\n'; (x - ONES) & ~x sets the high bit of the
     * first zero byte (later bytes may get false ones, the first is exact).
     */
    public static int indexOfNewline(byte[] b, int from, int to) {
        int i = from;
        for (; i + Long.BYTES <= to; i += Long.BYTES) {
            long x = (long) LONGS.get(b, i) ^ NEWLINES;
            long found = (x - ONES) & ~x & HIGH_BITS;
            if (found != 0) {
                return i + (Long.numberOfTrailingZeros(found) >>> 3);
            }
        }
        for (; i < to; i++) {
            if (b[i] == '\n') {
                return i;
            }
        }
        return -1;
    }

    private void setLine(int start, int end) {
        int e = end;
        while (e > start && buf[e - 1] == '\r') {
            e--;
        }
        lineStart = start;
        lineEnd = e;
        lineNumber++;
        // A UTF-8 byte order mark (Windows' Notepad writes one) is not part of the first line's text.
        if (lineNumber == 1 && e - start >= 3 && buf[start] == (byte) 0xEF && buf[start + 1] == (byte) 0xBB
                && buf[start + 2] == (byte) 0xBF) {
            lineStart = start + 3;
        }
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
            if (crc != null) {
                crc.update(buf, limit, n);
            }
            limit += n;
        }
    }

    /**
     * Up to the first {@code n} bytes of the source, read anew from its file
     * (or copied from the bytes in memory): for a message about what a file
     * that gave nothing is ({@link NotText}).
     */
    public byte[] head(int n) throws IOException {
        if (!fileBacked) {
            return java.util.Arrays.copyOf(buf, Math.min(n, limit));
        }
        try (FileChannel c = FileChannel.open(path, StandardOpenOption.READ)) {
            ByteBuffer head = ByteBuffer.allocate(n);
            while (head.hasRemaining() && c.read(head) >= 0) {
                // reads until n bytes or the end of the file
            }
            return java.util.Arrays.copyOf(head.array(), head.position());
        }
    }

    /** Lets go of the file (not of the place in it); the next line reopens it. */
    public void suspend() throws IOException {
        if (!fileBacked || buf == null) {
            return;
        }
        resumeOffset = bufferOffset + pos;
        buf = null;
        closeChannel();
    }

    public boolean holdsFile() {
        return channel != null;
    }

    public boolean suspended() {
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

    public void close() throws IOException {
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
    public static final class LineTooLongException extends IOException {
        private static final long serialVersionUID = 1L;

        LineTooLongException() {
            super("a line is longer than " + MAX_LINE + " bytes");
        }
    }
}
