package simpview.scene;

/**
 * One version of a file, as far as it can be told: its stamp and, when
 * known, the checksum of its bytes ({@link FileChecksum}). What a reader
 * read (the stamp it looked at before reading, the checksum of the very
 * bytes it read), or what a look at the file now finds.
 *
 * @param stamp size, last change and inode, or {@link FileStamp#MISSING}
 * @param checksum the CRC-32C of its bytes, or {@link FileChecksum#NONE} when not known
 */
public record FileVersion(FileStamp stamp, long checksum) {

    /** A version known by its stamp alone. */
    public static FileVersion of(FileStamp stamp) {
        return new FileVersion(stamp, FileChecksum.NONE);
    }

    /** True when the checksum of its bytes is known. */
    public boolean checksummed() {
        return checksum != FileChecksum.NONE;
    }

    /**
     * True when {@code other} is another version of the file: another stamp,
     * or the same stamp (two saves within one tick of the file system's
     * clock) and other bytes, where both checksums are known.
     */
    public boolean differsFrom(FileVersion other) {
        if (!stamp.equals(other.stamp)) {
            return true;
        }
        return checksummed() && other.checksummed() && checksum != other.checksum;
    }
}
