package simpview.scene.obj;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import simpview.scene.FileChecksum;
import simpview.scene.FileLook;
import simpview.scene.FileProblem;
import simpview.scene.FileStamp;
import simpview.scene.FileVersion;
import simpview.scene.KeptFiles;
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
 * <p>Thread safe: one library may serve several drawing threads. The kept
 * models are guarded by a lock held only to look up and to store; parsing
 * and replaying run outside it (two threads drawing the same new file may
 * both parse it). The file is looked at before it is read, so a change made
 * while it is read is seen at the next picture: a picture looks at each file
 * once ({@link ObjFilesSeen}).
 *
 * <p>A model is trusted on the file's stamp alone once the file has
 * settled ({@link KeptFiles}). Until then each draw also compares a CRC-32C
 * of the file's bytes with the one of the bytes it was parsed from (taken as
 * they were parsed, so a first draw reads the file once; a later one reads it
 * once more, far cheaper than parsing it), and parses again when they differ.
 * A file of at most {@link FileChecksum#LIMIT} bytes is checksummed as it is
 * parsed also when settled: what the picture drew of it
 * ({@link ObjFilesSeen#asRead}) is what a window's watcher holds a save
 * against.
 */
public final class ObjLibrary {

    /** 64 MB of arrays. */
    public static final long DEFAULT_BUDGET = 64L << 20;

    /** How long before it is looked at a file must have been last modified for its stamp alone to be trusted. */
    public static final long SETTLE_MILLIS = KeptFiles.SETTLE_MILLIS;

    private final long settleMillis;
    private final long budget;
    private final KeptFiles<Parsed> models;
    private final AtomicInteger parses = new AtomicInteger();
    private final AtomicInteger contentChecks = new AtomicInteger();

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
        this.models = new KeptFiles<>(budget, parsed -> parsed.model().bytes());
    }

    /**
     * A parsed model.
     *
     * @param checksum the checksum of the bytes it was parsed from ({@link FileChecksum}), taken as they were
     *     parsed when the file was not settled or small enough for a watcher to checksum it; else
     *     {@link FileChecksum#NONE}
     */
    private record Parsed(long checksum, ObjModel model) {
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
        return draw(file, sink, new ObjFilesSeen());
    }

    /**
     * As {@link #draw(Path, ObjSink)}, for one of the pictures a scene draws
     * ({@code seen}, the picture's own, kept by its caller): a file this
     * picture has looked at already is not looked at again, and one whose
     * bytes it has read already is replayed on its stamp alone, so a model
     * drawn twice in one picture is looked up and read once. A save while the
     * picture is drawn is seen by the next one. {@code seen} is told the
     * version of the file drawn ({@link ObjFilesSeen#asRead}).
     */
    public ObjCounts draw(Path file, ObjSink sink, ObjFilesSeen seen) throws SceneException {
        FileLook look = seen.look(file);
        if (look == null) {
            look = lookAt(file);
            seen.looked(file, look);
        }
        Path real = look.real();
        FileStamp stamp = look.stamp();
        boolean settled = look.settled(settleMillis);
        KeptFiles.Kept<Parsed> kept = models.get(real, stamp);
        if (kept != null && (kept.settled() || seen.hasRead(real))) {
            seen.drew(real, new FileVersion(stamp, kept.value().checksum()));
            return replay(kept.value().model(), sink);
        }
        seen.reading(real);
        if (kept != null && kept.value().checksum() == checksum(file, real)) {
            if (settled) {
                models.settle(real, kept);
            }
            seen.drew(real, new FileVersion(stamp, kept.value().checksum()));
            return replay(kept.value().model(), sink);
        }
        parses.incrementAndGet();
        // Checksummed as it is parsed, its bytes read once: a file not settled yet (the next draw compares it), and
        // one small enough for a watcher to hold a save against the bytes drawn.
        ObjParser parser = ObjParser.open(file).record(budget);
        if (!settled || FileChecksum.taken(stamp.size())) {
            parser.checksummed();
        }
        ObjCounts counts = parser.run(sink);
        long checksum = parser.checksum();
        seen.drew(real, new FileVersion(stamp, checksum));
        ObjModel parsed = parser.model();
        if (parsed != null) {
            models.keep(real, stamp, settled, new Parsed(checksum, parsed));
        }
        return counts;
    }

    /** The file's real path and attributes, looked up once: the check that it is a file, and the stamp. */
    private static FileLook lookAt(Path file) throws SceneException {
        FileLook look;
        try {
            look = FileLook.at(file);
        } catch (IOException e) {
            throw cannotOpen(file, e);
        }
        String notAFile = FileProblem.notAFile(look.attributes());
        if (notAFile != null) {
            throw new SceneException(file, 0, 0, "", "cannot read the obj file "
                    + file.toAbsolutePath().normalize() + ": " + notAFile);
        }
        return look;
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

    /** How many times a file was parsed (not replayed): for tests and statistics. */
    public int parseCount() {
        return parses.get();
    }

    /** How many times a file's bytes were read to compare them with a kept model's: for tests. */
    public int contentCheckCount() {
        return contentChecks.get();
    }

    /** The bytes of the models kept now. */
    public long bytesKept() {
        return models.bytesKept();
    }

    /** How many models are kept now. */
    public int modelsKept() {
        return models.size();
    }

    /** Drops every kept model. */
    public void clear() {
        models.clear();
    }
}
