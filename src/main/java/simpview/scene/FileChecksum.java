package simpview.scene;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.zip.CRC32C;
import java.util.zip.Checksum;

/**
 * The CRC-32C of a file's bytes: what tells two versions of a file apart when
 * its size, inode and time of last change (kept to a tick of the file
 * system's clock) are the same. Reading is the cost, a fraction of a
 * millisecond per megabyte from the page cache; any change of up to 32
 * adjacent bits is always seen.
 *
 * <p>The one place that says which checksum and for which files: the readers
 * take it of the bytes they read, as they read them ({@link #running}), and
 * the window's watcher of the files as they are now ({@link #of(Path)}), both
 * for files of at most {@link #LIMIT} bytes ({@link #taken}).
 */
public final class FileChecksum {

    /** Files up to this long are checksummed (a few milliseconds of reading at most); longer ones by their stamp alone. */
    public static final long LIMIT = 8L << 20;
    /** No checksum known (a CRC-32C is never negative). */
    public static final long NONE = -1;

    private FileChecksum() {
    }

    /** True when a file of {@code size} bytes is checksummed: at most {@link #LIMIT} long. */
    public static boolean taken(long size) {
        return size >= 0 && size <= LIMIT;
    }

    /** A checksum to feed the bytes of a file as they are read, in order: {@link #of(Path)}'s value once fed all. */
    public static Checksum running() {
        return new CRC32C();
    }

    /** The checksum of bytes already read whole (a small file's). */
    public static long of(byte[] content) {
        Checksum crc = running();
        crc.update(content, 0, content.length);
        return crc.getValue();
    }

    /** The checksum of the file's bytes as they are now. */
    public static long of(Path file) throws IOException {
        Checksum crc = running();
        ByteBuffer buffer = ByteBuffer.allocate(1 << 16);
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            while (channel.read(buffer) >= 0) {
                buffer.flip();
                crc.update(buffer);
                buffer.clear();
            }
        }
        return crc.getValue();
    }
}
