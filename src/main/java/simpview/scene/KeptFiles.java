package simpview.scene;

import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.ToLongFunction;

/**
 * What was made from files (a parsed .obj model, a .simp file's commands),
 * each kept with the stamp its file had, within a budget of bytes: the least
 * recently used go first. The two libraries of scene files keep theirs here
 * and share its rule for when a stamp alone may be trusted.
 *
 * <p>A quick save can keep the size, the inode and the last-modified time,
 * which file systems keep to a tick of a few milliseconds (ext4) up to two
 * seconds (FAT). So a kept value is trusted on its stamp alone only once it
 * is <em>settled</em>: its file was last modified more than
 * {@link #SETTLE_MILLIS} before it was looked at, so any later write stamps a
 * later time. Until then its user also compares the file's content with the
 * content the value was made from, and makes it again when they differ. What
 * is not seen is a change that sets the last-modified time back to exactly
 * the old one, more than that long in the past, keeping size and inode.
 *
 * <p>Thread safe: every method holds this object's lock, and only for the
 * look-up or the store; values are made and used outside it, so a value must
 * not change once kept.
 *
 * @param <V> what is made from a file
 */
public final class KeptFiles<V> {

    /** How long before it is looked at a file must have been last modified for its stamp alone to be trusted. */
    public static final long SETTLE_MILLIS = 3_000;

    /**
     * A value and the file it was made from.
     *
     * @param stamp the file as it was looked at, before it was read
     * @param settled true when the stamp alone tells a change
     * @param value what was made from the file's content
     */
    public record Kept<V>(FileStamp stamp, boolean settled, V value) {
    }

    private final long budget;
    private final ToLongFunction<V> bytesOf;
    /** In access order: the first entry is the least recently used. */
    private final LinkedHashMap<Path, Kept<V>> kept = new LinkedHashMap<>(16, 0.75f, true);
    private long bytesKept;

    /** @param bytesOf roughly the memory a value holds, counted against {@code budget} */
    public KeptFiles(long budget, ToLongFunction<V> bytesOf) {
        this.budget = budget;
        this.bytesOf = bytesOf;
    }

    /**
     * True when a file of these attributes, looked at {@code lookedAt}
     * (milliseconds since the epoch), had been left alone for more than
     * {@code settleMillis}: a later write would stamp a later time.
     */
    public static boolean settled(BasicFileAttributes attributes, long lookedAt, long settleMillis) {
        return attributes.lastModifiedTime().toMillis() < lookedAt - settleMillis;
    }

    /** The value kept for the file {@code real} at this stamp, or null; a value of another stamp is dropped. */
    public synchronized Kept<V> get(Path real, FileStamp stamp) {
        Kept<V> k = kept.get(real);
        if (k == null) {
            return null;
        }
        if (k.stamp().equals(stamp)) {
            return k;
        }
        drop(real);
        return null;
    }

    /** From now on trusts the stamp of {@code k}, whose content was found unchanged once its file had settled. */
    public synchronized void settle(Path real, Kept<V> k) {
        if (kept.get(real) == k) {
            kept.put(real, new Kept<>(k.stamp(), true, k.value()));
        }
    }

    /**
     * Keeps {@code value}, made from {@code real} as stamped, in place of any
     * value before it, dropping the least recently used while the budget
     * would be passed; a value that alone would pass it is not kept.
     */
    public synchronized void keep(Path real, FileStamp stamp, boolean settled, V value) {
        drop(real);
        long bytes = bytesOf.applyAsLong(value);
        if (bytes > budget) {
            return;
        }
        Iterator<Map.Entry<Path, Kept<V>>> eldest = kept.entrySet().iterator();
        while (bytesKept + bytes > budget && eldest.hasNext()) {
            bytesKept -= bytesOf.applyAsLong(eldest.next().getValue().value());
            eldest.remove();
        }
        kept.put(real, new Kept<>(stamp, settled, value));
        bytesKept += bytes;
    }

    private void drop(Path real) {
        Kept<V> old = kept.remove(real);
        if (old != null) {
            bytesKept -= bytesOf.applyAsLong(old.value());
        }
    }

    /** The bytes of the values kept now. */
    public synchronized long bytesKept() {
        return bytesKept;
    }

    /** How many values are kept now. */
    public synchronized int size() {
        return kept.size();
    }

    /** Drops every kept value. */
    public synchronized void clear() {
        kept.clear();
        bytesKept = 0;
    }
}
