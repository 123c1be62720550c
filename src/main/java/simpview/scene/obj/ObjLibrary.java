package simpview.scene.obj;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import simpview.scene.SceneException;

/**
 * The .obj models of the scenes drawn so far, kept while their files are
 * unchanged, so that a page that draws a model twice, or a redraw, does not
 * parse it again.
 *
 * <p>{@link #draw} replays the kept model when the file's real path, size
 * and last-modified time are those it was parsed at; otherwise it parses the
 * file, streaming its faces to the sink as they are read and recording them
 * at the same time. A model is kept only while all kept models' arrays fit
 * in the budget (the least recently drawn go first); a file whose model
 * alone would pass it stops being recorded as soon as it does and is simply
 * streamed, on every draw. A file that fails to parse is never kept.
 *
 * <p>Thread safe: one library may serve several drawing threads. The map is
 * guarded by this object's lock, held only to look up and to store; parsing
 * and replaying run outside it (two threads drawing the same new file may
 * both parse it). The file is looked at before it is read, so a change made
 * while it is read is seen at the next draw; a change that keeps its size,
 * its inode and its last-modified time (to the file system's resolution) is
 * not seen.
 */
public final class ObjLibrary {

    /** 64 MB of arrays. */
    public static final long DEFAULT_BUDGET = 64L << 20;

    private final long budget;
    /** In access order: the first entry is the least recently drawn. */
    private final LinkedHashMap<Path, Kept> models = new LinkedHashMap<>(16, 0.75f, true);
    private long bytesKept;
    private final AtomicInteger parses = new AtomicInteger();

    public ObjLibrary() {
        this(DEFAULT_BUDGET);
    }

    /** A library keeping at most {@code budget} bytes of model arrays. */
    public ObjLibrary(long budget) {
        this.budget = budget;
    }

    /** The file as last seen: a model is valid while these are unchanged. */
    private record Stamp(long size, FileTime modified, Object fileKey) {
    }

    private record Kept(Stamp stamp, ObjModel model) {
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
        Path real;
        Stamp stamp;
        try {
            real = file.toRealPath();
            BasicFileAttributes a = Files.readAttributes(real, BasicFileAttributes.class);
            stamp = new Stamp(a.size(), a.lastModifiedTime(), a.fileKey());
        } catch (IOException e) {
            throw new SceneException(file, 0, 0, "", "cannot open the obj file: " + e.getClass().getSimpleName()
                    + (e.getMessage() == null ? "" : ": " + e.getMessage()));
        }
        ObjModel model = kept(real, stamp);
        if (model != null) {
            model.replay(sink);
            return model.counts();
        }
        parses.incrementAndGet();
        ObjParser parser = ObjParser.open(file).record(budget);
        ObjCounts counts = parser.run(sink);
        ObjModel parsed = parser.model();
        if (parsed != null) {
            keep(real, stamp, parsed);
        }
        return counts;
    }

    /** The model kept for the file at this stamp; a model of an older stamp is dropped. */
    private synchronized ObjModel kept(Path real, Stamp stamp) {
        Kept k = models.get(real);
        if (k == null) {
            return null;
        }
        if (k.stamp().equals(stamp)) {
            return k.model();
        }
        models.remove(real);
        bytesKept -= k.model().bytes();
        return null;
    }

    private synchronized void keep(Path real, Stamp stamp, ObjModel model) {
        long bytes = model.bytes();
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
        models.put(real, new Kept(stamp, model));
        bytesKept += bytes;
    }

    /** How many times a file was parsed (not replayed): for tests and statistics. */
    public int parseCount() {
        return parses.get();
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
