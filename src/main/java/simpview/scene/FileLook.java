package simpview.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * One look at a file, as the readers of scene files take it before reading:
 * where it really is and its attributes, looked up once (the real path costs
 * a system call per folder), with the stamp made from them and the time of
 * the look, which says whether its stamp alone may be trusted
 * ({@link KeptFiles#settled}).
 *
 * @param real its real path, which names what is kept of it
 * @param attributes its attributes then: whether it is a file, its size
 * @param stamp its stamp then
 * @param lookedAt when, in milliseconds since the epoch
 */
public record FileLook(Path real, BasicFileAttributes attributes, FileStamp stamp, long lookedAt) {

    /** Looks at {@code file} now. */
    public static FileLook at(Path file) throws IOException {
        long lookedAt = System.currentTimeMillis();
        Path real = file.toRealPath();
        BasicFileAttributes attributes = Files.readAttributes(real, BasicFileAttributes.class);
        return new FileLook(real, attributes, FileStamp.of(attributes), lookedAt);
    }

    /** True when the file had been left alone for more than {@code settleMillis} when it was looked at. */
    public boolean settled(long settleMillis) {
        return KeptFiles.settled(attributes, lookedAt, settleMillis);
    }
}
