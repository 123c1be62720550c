package simpview.window.render;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import javax.swing.Timer;
import simpview.scene.FileChecksum;

/**
 * Watches the files of the picture on screen (the scene and every file it
 * read) and says when one of them changed: its size, its time of last
 * change or its inode differs, or it appeared or went away. It looks a few
 * times a second on the EDT, which is cheap for the handful of files a scene
 * reads and sees an editor's save however the editor writes (in place, or a
 * new file renamed over the old).
 *
 * <p>A file system keeps the time of last change to a tick (a few
 * milliseconds on ext4, two seconds on FAT), so two saves of the same size
 * within one tick look alike. A file changed less than {@link #FRESH_MILLIS}
 * ago is therefore also compared by a CRC-32C of its bytes, while it is at
 * most {@link #CHECKSUM_LIMIT} long (a few milliseconds of reading at most).
 */
public final class SceneWatcher {

    static final int POLL_MS = 200;
    public static final long FRESH_MILLIS = 3_000;
    static final long CHECKSUM_LIMIT = 8L << 20;
    private static final long NO_CHECKSUM = -1;

    private final Timer timer;
    private final Runnable changed;
    private List<Path> files = List.of();
    private List<Look> looks = List.of();

    public SceneWatcher(Runnable changed) {
        this.changed = changed;
        this.timer = new Timer(POLL_MS, e -> poll());
        timer.setCoalesce(true);
    }

    /**
     * What was seen of a file at one look.
     *
     * @param stamp size, last change and inode, or "missing"
     * @param checksum the CRC-32C of its bytes when it was fresh and small, else {@link #NO_CHECKSUM}
     */
    record Look(Object stamp, long checksum) {
    }

    /** From now on watches {@code watched}, as they are now. */
    public void watch(List<Path> watched) {
        files = List.copyOf(watched);
        looks = looksNow();
        if (files.isEmpty()) {
            timer.stop();
        } else if (!timer.isRunning()) {
            timer.start();
        }
    }

    public List<Path> watched() {
        return files;
    }

    public void stop() {
        timer.stop();
    }

    private void poll() {
        List<Look> now = looksNow();
        boolean any = false;
        for (int i = 0; i < now.size(); i++) {
            any |= changed(looks.get(i), now.get(i));
        }
        looks = now;
        if (any) {
            changed.run();
        }
    }

    private List<Look> looksNow() {
        long now = System.currentTimeMillis();
        List<Look> seen = new ArrayList<>(files.size());
        for (Path file : files) {
            seen.add(look(file, now));
        }
        return seen;
    }

    /** True when {@code now} shows another file than {@code before}. */
    static boolean changed(Look before, Look now) {
        if (!before.stamp().equals(now.stamp())) {
            return true;
        }
        return before.checksum() != NO_CHECKSUM && now.checksum() != NO_CHECKSUM && before.checksum() != now.checksum();
    }

    /** Size, last change and inode of a file, and its checksum when it changed within FRESH_MILLIS of {@code now}. */
    static Look look(Path file, long now) {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(file, BasicFileAttributes.class);
        } catch (IOException e) {
            return new Look("missing", NO_CHECKSUM);
        }
        Object stamp = List.of(attributes.size(), attributes.lastModifiedTime(),
                Objects.toString(attributes.fileKey()));
        boolean fresh = attributes.lastModifiedTime().toMillis() > now - FRESH_MILLIS;
        boolean small = attributes.isRegularFile() && attributes.size() <= CHECKSUM_LIMIT;
        return new Look(stamp, fresh && small ? checksum(file) : NO_CHECKSUM);
    }

    /** The CRC-32C of the file's bytes, or NO_CHECKSUM when it cannot be read now. */
    private static long checksum(Path file) {
        try {
            return FileChecksum.of(file);
        } catch (IOException e) {
            return NO_CHECKSUM;
        }
    }
}
