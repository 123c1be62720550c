package simpview.scene.obj;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.util.HashSet;
import java.util.Iterator;
import java.util.Set;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import simpview.scene.FileChecksum;
import simpview.scene.FileProblem;
import simpview.scene.SceneException;

/**
 * The .obj models of the scenes drawn so far, kept while their files are
 * unchanged, so that a page that draws a model twice, or a redraw, does not
 * parse it again.
 *
 * <p>{@link #draw} replays the kept model when the file's real path, size,
 * last-modified time and inode are those it was parsed at, and the model is
 * settled or its content unchanged (below); otherwise it parses the file,
 * streaming its faces to the sink as they are read and recording them at
 * the same time. A model is kept only while all kept models' arrays fit
 * in the budget (the least recently drawn go first); a file whose model
 * alone would pass it stops being recorded as soon as it does and is simply
 * streamed, on every draw. A file that fails to parse is never kept.
 *
 * <p>Thread safe: one library may serve several drawing threads. The map is
 * guarded by this object's lock, held only to look up and to store; parsing
 * and replaying run outside it (two threads drawing the same new file may
 * both parse it). The file is looked at before it is read, so a change made
 * while it is read is seen at the next draw.
 *
 * <p>A quick save can keep the size, the inode and the last-modified time,
 * which file systems keep to a tick of a few milliseconds (ext4) up to two
 * seconds (FAT). So a model is trusted on those alone only once it is
 * <em>settled</em>: its file was last modified more than {@link #SETTLE_MILLIS}
 * before it was looked at, so any later write stamps a later time. Until then
 * each draw also compares a CRC-32C of the file's bytes with the one of the
 * bytes it was parsed from (taken as they were parsed, so a first draw reads
 * the file once; a later one reads it once more, far cheaper than parsing
 * it), and parses again when they differ. What is not seen is a change that sets
 * the last-modified time back to exactly the old one, more than that long in
 * the past, keeping size and inode.
 */
public final class ObjLibrary {

    /** 64 MB of arrays. */
    public static final long DEFAULT_BUDGET = 64L << 20;

    private final long budget;
    private final long settleMillis;
    /** In access order: the first entry is the least recently drawn. */
    private final LinkedHashMap<Path, Kept> models = new LinkedHashMap<>(16, 0.75f, true);
    private long bytesKept;
    private final AtomicInteger parses = new AtomicInteger();
    private final AtomicInteger contentChecks = new AtomicInteger();

    /** How long before it is looked at a file must have been last modified for its stamp alone to be trusted. */
    public static final long SETTLE_MILLIS = 3_000;

    public ObjLibrary() {
        this(DEFAULT_BUDGET);
    }

    /** A library keeping at most {@code budget} bytes of model arrays. */
    public ObjLibrary(long budget) {
        this(budget, SETTLE_MILLIS);
    }

    /** As {@link #ObjLibrary(long)}, trusting a file's stamp alone once it is {@code settleMillis} old (for tests). */
    ObjLibrary(long budget, long settleMillis) {
        this.budget = budget;
        this.settleMillis = settleMillis;
    }

    /** The file as last seen: a model is valid while these are unchanged. */
    private record Stamp(long size, FileTime modified, Object fileKey) {
    }

    /**
     * A parsed model and the file it was parsed from.
     *
     * @param checksum the CRC-32C of the file's bytes before it was parsed (0 when settled then)
     * @param settled true when the stamp alone tells a change
     */
    private record Kept(Stamp stamp, long checksum, boolean settled, ObjModel model) {
    }

    /**
     * Draws the faces of the .obj file to the sink, in file order: from the
     * kept model when the file is unchanged, else by parsing it.
     *
     * @return the counts of the file's vertices, normals and faces
     * @throws SceneException the file cannot be read, or has an error (faces
     *     before it have gone to the sink), or the sink threw
     */
    public ObjCounts draw(Path file, ObjSink sink) throws SceneException {
        return draw(file, sink, new HashSet<>());
    }

    /**
     * As {@link #draw(Path, ObjSink)}, for one of the pictures a scene draws:
     * a file whose bytes this picture has read already ({@code readThisPicture},
     * the picture's own set, kept by its caller) is replayed on its stamp
     * alone, so a model drawn twice in one picture is read once. A save while
     * the picture is drawn is seen by the next one.
     */
    public ObjCounts draw(Path file, ObjSink sink, Set<Path> readThisPicture) throws SceneException {
        long lookedAt = System.currentTimeMillis();
        Path real;
        Stamp stamp;
        try {
            real = file.toRealPath();
            String notAFile = FileProblem.notAFile(real);
            if (notAFile != null) {
                throw new SceneException(file, 0, 0, "", "cannot read the obj file "
                        + file.toAbsolutePath().normalize() + ": " + notAFile);
            }
            BasicFileAttributes a = Files.readAttributes(real, BasicFileAttributes.class);
            stamp = new Stamp(a.size(), a.lastModifiedTime(), a.fileKey());
        } catch (IOException e) {
            throw cannotOpen(file, e);
        }
        boolean settled = stamp.modified().toMillis() < lookedAt - settleMillis;
        Kept kept = kept(real, stamp);
        long checksum = 0;
        if (kept != null && (kept.settled() || readThisPicture.contains(real))) {
            return replay(kept.model(), sink);
        }
        readThisPicture.add(real);
        if (kept != null) {
            checksum = checksum(file, real);
            if (kept.checksum() == checksum) {
                if (settled) {
                    settle(real, kept);
                }
                return replay(kept.model(), sink);
            }
        }
        parses.incrementAndGet();
        // A file not settled yet is checksummed as it is parsed: its bytes are read once.
        ObjParser parser = ObjParser.open(file).record(budget);
        if (!settled) {
            parser.checksummed();
        }
        ObjCounts counts = parser.run(sink);
        ObjModel parsed = parser.model();
        if (parsed != null) {
            keep(real, new Kept(stamp, settled ? 0 : parser.checksum(), settled, parsed));
        }
        return counts;
    }

    private static ObjCounts replay(ObjModel model, ObjSink sink) throws SceneException {
        model.replay(sink);
        return model.counts();
    }

    private static SceneException cannotOpen(Path file, IOException e) {
        return new SceneException(file, 0, 0, "", "cannot open the obj file "
                + file.toAbsolutePath().normalize() + ": " + FileProblem.of(file, e));
    }

    /** The CRC-32C of the file's bytes as they are now. */
    private long checksum(Path file, Path real) throws SceneException {
        contentChecks.incrementAndGet();
        try {
            return FileChecksum.of(real);
        } catch (IOException e) {
            throw cannotOpen(file, e);
        }
    }

    /** The model kept for the file at this stamp; a model of an older stamp is dropped. */
    private synchronized Kept kept(Path real, Stamp stamp) {
        Kept k = models.get(real);
        if (k == null) {
            return null;
        }
        if (k.stamp().equals(stamp)) {
            return k;
        }
        models.remove(real);
        bytesKept -= k.model().bytes();
        return null;
    }

    /** From now on trusts the stamp of a model whose content was found unchanged once it had settled. */
    private synchronized void settle(Path real, Kept k) {
        if (models.get(real) == k) {
            models.put(real, new Kept(k.stamp(), k.checksum(), true, k.model()));
        }
    }

    private synchronized void keep(Path real, Kept kept) {
        long bytes = kept.model().bytes();
        Kept old = models.remove(real);
        if (old != null) {
            bytesKept -= old.model().bytes();
        }
        if (bytes > budget) {
            return;
        }
        Iterator<Map.Entry<Path, Kept>> eldest = models.entrySet().iterator();
        while (bytesKept + bytes > budget && eldest.hasNext()) {
            bytesKept -= eldest.next().getValue().model().bytes();
            eldest.remove();
        }
        models.put(real, kept);
        bytesKept += bytes;
    }

    /** How many times a file was parsed (not replayed): for tests and statistics. */
    public int parseCount() {
        return parses.get();
    }

    /** How many times a file's bytes were read to compare them with a kept model's: for tests. */
    public int contentCheckCount() {
        return contentChecks.get();
    }

    /** The bytes of the models kept now. */
    public synchronized long bytesKept() {
        return bytesKept;
    }

    /** How many models are kept now. */
    public synchronized int modelsKept() {
        return models.size();
    }

    /** Drops every kept model. */
    public synchronized void clear() {
        models.clear();
        bytesKept = 0;
    }
}
