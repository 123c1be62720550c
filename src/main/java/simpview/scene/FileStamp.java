package simpview.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Objects;

/**
 * What the file system says of a file at one moment: its size, its time of
 * last change and its inode (or whatever stands for one), or that it is not
 * there. Two stamps that differ are two versions of the file; two that are
 * equal may still be two quick saves within one tick of the file system's
 * clock, which only the bytes tell ({@link FileChecksum}).
 *
 * @param size the size in bytes, -1 when missing
 * @param modified the time of last change, in the file system's own resolution (its {@code toString}), "" when missing
 * @param key the inode or file key, "" when missing
 */
public record FileStamp(long size, String modified, String key) {

    /** No file there (or none that can be looked at). */
    public static final FileStamp MISSING = new FileStamp(-1, "", "");

    /** The file as it is now. */
    public static FileStamp of(Path file) {
        try {
            return of(Files.readAttributes(file, BasicFileAttributes.class));
        } catch (IOException | SecurityException e) {
            return MISSING;
        }
    }

    /** The stamp of attributes already read. */
    public static FileStamp of(BasicFileAttributes attributes) {
        return new FileStamp(attributes.size(), attributes.lastModifiedTime().toString(),
                Objects.toString(attributes.fileKey()));
    }

    /**
     * Equal in every component, as a record's own equals has it, written out:
     * a scene's every include compares the kept stamp with its file's
     * ({@code KeptFiles.get}), and the record's generated equals, left out of
     * line there, took 0.7 us a call, 68 us a picture of A4 page-f1 (its 91
     * includes of one cube; docs/performance-log.md, session 50).
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof FileStamp other && size == other.size && Objects.equals(modified, other.modified)
                && Objects.equals(key, other.key);
    }

    @Override
    public int hashCode() {
        return (Long.hashCode(size) * 31 + Objects.hashCode(modified)) * 31 + Objects.hashCode(key);
    }
}
