package simpview.scene.text;

import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
import java.util.zip.Checksum;
import simpview.scene.FileChecksum;
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
    private static final long SPACES = 0x2020202020202020L;
    /** How many of a file's first bytes a {@link NotText} message looks at, for what the file is. */
    private static final int HEAD = 4096;
    /** Longer lines are refused: a line must fit in memory, and no real scene comes close. */
    public static final int MAX_LINE = 1 << 20;

    private final Path path;
    /** The checksum of every byte read so far, when asked for ({@link #checksummed}); else null. */
    private Checksum crc;
    /** The file offset the checksum has taken the bytes up to: a suspended source reads some of them again. */
    private long checksummedTo;
    /** True once the checksum has taken every byte of the file. */
    private boolean checksummedWhole;
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
    /** Where in buf the line just scanned holds its first byte that is not UTF-8 text; -1 when it holds none. */
    private int notTextAt;

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
     * From now on (call it before the first line) keeps the checksum of the
     * bytes read ({@link FileChecksum}), so that a reader that reads a file to
     * its end learns its checksum without reading it a second time
     * ({@link #checksum}). Each byte is taken once, also when a suspended
     * source reads again the bytes after its place.
     */
    public LineSource checksummed() {
        crc = FileChecksum.running();
        if (!fileBacked) {
            crc.update(buf, 0, limit);
        }
        checksummedTo = limit;
        checksummedWhole = !fileBacked;
        return this;
    }

    /** The checksum of the bytes read so far: of the whole file once it was read to its end (as FileChecksum gives it). */
    public long checksum() {
        return crc.getValue();
    }

    /**
     * The checksum of the whole file, when this source was {@link #checksummed}
     * and has read it to its end; else {@link FileChecksum#NONE}.
     */
    public long checksumOfWhole() {
        return checksummedWhole ? crc.getValue() : FileChecksum.NONE;
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
     * return. In a line that an LF ends, that is a stray one (pasted from
     * another editor); else the file's lines end in CR alone (old Mac files),
     * so that the whole file reads as one line. Else "".
     */
    public String lineEndHint() {
        for (int i = lineStart; i < lineEnd; i++) {
            if (buf[i] == '\r') {
                return endsInLineFeed() ? " (a carriage return stands alone in this line, where it ends no line (an LF"
                        + " ends this one): remove it)" : " (this file's lines end in a carriage return alone,"
                        + " so it reads as one line: save it with LF or CR LF line ends)";
            }
        }
        return "";
    }

    /** Whether an LF ends the current line, past the CRs before it. */
    private boolean endsInLineFeed() {
        int j = lineEnd;
        while (j < limit && buf[j] == '\r') {
            j++;
        }
        return j < limit && buf[j] == '\n';
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
            int i = scanLine(pos, limit);
            if (i >= 0) {
                setLine(pos, i);
                pos = i + 1;
                return textLine();
            }
            if (eof) {
                if (pos < limit) {
                    setLine(pos, limit);
                    pos = limit;
                    return textLine();
                }
                return false;
            }
            fill();
        }
    }

    /**
     * True, when the line just set holds only UTF-8 text; else the error
     * that the file is not text, naming its first such byte. A byte is
     * looked at once, as the line break is looked for, so this costs a
     * scene of text nothing worth measuring.
     */
    private boolean textLine() throws IOException {
        if (notTextAt < 0) {
            return true;
        }
        int next = notTextAt + 1 < limit ? buf[notTextAt + 1] & 0xFF : -1;
        throw new NotTextException(head(HEAD), bufferOffset + notTextAt, lineNumber,
                1 + characters(buf, lineStart, notTextAt), buf[notTextAt] & 0xFF, next);
    }

    /**
     * How many characters the UTF-8 text b[from, to) holds: its bytes that
     * do not continue a character (0x80 to 0xBF continue one). The text
     * before a line's first byte that no UTF-8 text holds is whole
     * characters, so one plus this is that byte's column.
     */
    private static int characters(byte[] b, int from, int to) {
        int n = 0;
        for (int i = from; i < to; i++) {
            n += (b[i] & 0xC0) == 0x80 ? 0 : 1;
        }
        return n;
    }

    /**
     * The index of the first '\n' in buf[from, to), or -1, noting in
     * {@link #notTextAt} the first byte before it that no UTF-8 text holds:
     * a control character other than tab, carriage return and form feed, or
     * a byte that starts or continues no UTF-8 character. Eight bytes at a
     * time, as {@link #indexOfNewline}: a long is looked at byte by byte only
     * when it holds a byte below 0x20 (the line break among them) or from
     * 0x7F up. Per long: (x - SPACES) &amp; ~x sets the high bit of the first
     * byte below 0x20, (x + ONES) | x that of the first from 0x7F up (later
     * bytes may get false ones, the first is exact).
     */
    private int scanLine(int from, int to) {
        notTextAt = -1;
        byte[] b = buf;
        int i = from;
        while (i < to) {
            if (i + Long.BYTES <= to) {
                long x = (long) LONGS.get(b, i);
                long unusual = ((x - SPACES) & ~x | (x + ONES) | x) & HIGH_BITS;
                if (unusual == 0) {
                    i += Long.BYTES;
                    continue;
                }
                i += Long.numberOfTrailingZeros(unusual) >>> 3;
            }
            int c = b[i] & 0xFF;
            if (c == '\n') {
                return i;
            }
            if (c < 0x80) {
                if ((c < 0x20 && c != '\t' && c != '\r' && c != '\f' || c == 0x7F) && notTextAt < 0) {
                    notTextAt = i;
                }
                i++;
                continue;
            }
            int n = utf8Length(b, i, to);
            if (n < 0 && !eof) {
                return -1; // a character cut by the end of the buffer: looked at again once more is read
            }
            if (n <= 0 && notTextAt < 0) {
                notTextAt = i;
            }
            i += Math.max(n, 1);
        }
        return -1;
    }

    /**
     * The length of the UTF-8 character starting at b[i] (a byte from 0x80
     * up), 2 to 4; 0 when no character of UTF-8 starts so (a continuation
     * byte, an overlong form, a surrogate, beyond U+10FFFF); -1 when its
     * bytes so far are right but b[to] cuts it.
     */
    private static int utf8Length(byte[] b, int i, int to) {
        int c = b[i] & 0xFF;
        int n;
        int low = 0x80;
        int high = 0xBF;
        if (c >= 0xC2 && c <= 0xDF) {
            n = 2;
        } else if (c >= 0xE0 && c <= 0xEF) {
            n = 3;
            low = c == 0xE0 ? 0xA0 : 0x80; // E0 80..9F would be overlong
            high = c == 0xED ? 0x9F : 0xBF; // ED A0..BF would be a surrogate
        } else if (c >= 0xF0 && c <= 0xF4) {
            n = 4;
            low = c == 0xF0 ? 0x90 : 0x80; // overlong
            high = c == 0xF4 ? 0x8F : 0xBF; // beyond U+10FFFF
        } else {
            return 0;
        }
        for (int k = 1; k < n; k++) {
            if (i + k >= to) {
                return -1;
            }
            int next = b[i + k] & 0xFF;
            if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF)) {
                return 0;
            }
        }
        return n;
    }

    /**
     * The index of the first '\n' in b[from, to), or -1. Per long: x has a
     * zero byte where b has '\n'; {@code (x - ONES) & ~x} sets the high bit of the
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
                // the line starts at buf[0] (after a byte order mark on line 1): its first character past the limit
                int bom = lineNumber == 0 && limit >= 3 && buf[0] == (byte) 0xEF && buf[1] == (byte) 0xBB
                        && buf[2] == (byte) 0xBF ? 3 : 0;
                throw new LineTooLongException(1 + characters(buf, bom, MAX_LINE));
            }
            byte[] bigger = new byte[Math.min(MAX_LINE, buf.length * 2)];
            System.arraycopy(buf, 0, bigger, 0, limit);
            buf = bigger;
        }
        int n = channel.read(ByteBuffer.wrap(buf, limit, buf.length - limit));
        if (n < 0) {
            eof = true;
            checksummedWhole = crc != null;
        } else {
            if (crc != null) {
                long from = bufferOffset + limit;
                int skip = (int) Math.max(0, Math.min(n, checksummedTo - from));
                crc.update(buf, limit + skip, n - skip);
                checksummedTo = Math.max(checksummedTo, from + n);
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
            return Arrays.copyOf(buf, Math.min(n, limit));
        }
        try (FileChannel c = FileChannel.open(path, StandardOpenOption.READ)) {
            ByteBuffer head = ByteBuffer.allocate(n);
            while (head.hasRemaining() && c.read(head) >= 0) {
                // reads until n bytes or the end of the file
            }
            return Arrays.copyOf(head.array(), head.position());
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

    /**
     * A byte that no UTF-8 text holds, on the line just read; the reader
     * turns it into a SceneException in {@link NotText}'s words, which
     * shows none of the file's bytes.
     */
    public static final class NotTextException extends IOException {
        private static final long serialVersionUID = 1L;

        /** The file's first bytes, for what the file looks like. */
        private final byte[] head;
        private final long offset;
        private final int line;
        /** The byte's 1-based column: one plus the characters before it on its line. */
        private final int column;
        private final int value;
        /** The byte after it, -1 when there is none: whether the byte is malformed UTF-8 or another encoding's. */
        private final int next;

        NotTextException(byte[] head, long offset, int line, int column, int value, int next) {
            super(String.format("byte 0x%02X at offset %d is not UTF-8 text", value, offset));
            this.head = head;
            this.offset = offset;
            this.line = line;
            this.column = column;
            this.value = value;
            this.next = next;
        }

        /** The problem in words, {@code kind} saying what the file should be ("a SIMP file", "an .obj file"). */
        public NotText notText(String kind) {
            return NotText.of(head, offset, line, column, value, next, kind);
        }
    }

    /** A line longer than {@link #MAX_LINE}; the reader turns it into a SceneException. */
    public static final class LineTooLongException extends IOException {
        private static final long serialVersionUID = 1L;

        /** The column of the line's first character past the limit. */
        private final int column;

        LineTooLongException(int column) {
            super("a line is longer than " + MAX_LINE + " bytes");
            this.column = column;
        }

        /** The 1-based column of the line's first character past {@link #MAX_LINE} bytes: where it is too long. */
        public int column() {
            return column;
        }

        /**
         * The problem in words, the same for every reader: the limit, and what to do. {@code kind} says what the
         * file should be ("a SIMP file", "an .obj file"), {@code eachLine} what one of its lines holds ("one
         * command"). The reader puts the file, line and column in front.
         */
        public String problem(String kind, String eachLine) {
            return "line is too long: over " + MAX_LINE + " bytes (1 MiB), the most a line may hold. Put "
                    + eachLine + " on each line of " + kind + "; a file saved without its line ends is one long "
                    + "line: save it again with them";
        }
    }
}
