package simpview.scene;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.zip.CRC32C;

/**
 * The CRC-32C of a file's bytes: what tells two versions of a file apart when
 * its size, inode and time of last change (kept to a tick of the file
 * system's clock) are the same. Reading is the cost, a fraction of a
 * millisecond per megabyte from the page cache; any change of up to 32
 * adjacent bits is always seen.
 */
public final class FileChecksum {

    private FileChecksum() {
    }

    /** The checksum of the file's bytes as they are now. */
    public static long of(Path file) throws IOException {
        CRC32C crc = new CRC32C();
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
