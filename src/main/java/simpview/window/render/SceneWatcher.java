package simpview.window.render;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;
import simpview.scene.FileChecksum;
import simpview.scene.FileStamp;
import simpview.scene.FileVersion;

/**
 * Watches the files of the picture on screen (the scene and every file it
 * read) and says when one of them changed: its size, its time of last
 * change or its inode differs, or it appeared or went away. It looks a few
 * times a second on a thread of its own, "simpview-watch" (started by the
 * first {@link #watch}, ended by {@link #stop}), so that the EDT never waits
 * for a disk; the change is told on the EDT. Looking sees an editor's save
 * however the editor writes (in place, or a new file renamed over the old).
 *
 * <p>An editor's save is not one step: it may empty the file and then write
 * it (vim, nano), write it in several calls, or leave no file for a moment
 * between renames. A look in the middle would draw a half-written file, and
 * what the window keeps from a picture (the step it shows) would follow it.
 * So a change is told only once the files have held still: when a look
 * finds them as the look before it found them ({@link #POLL_MS} earlier),
 * and not as the picture on screen read them ({@link Changes}).
 *
 * <p>A file system keeps the time of last change to a tick (a few
 * milliseconds on ext4, two seconds on FAT), so two saves of the same size
 * within one tick look alike. A file changed less than {@link #FRESH_MILLIS}
 * ago is therefore also compared by a CRC-32C of its bytes, while it is at
 * most {@link FileChecksum#LIMIT} long (a few milliseconds of reading at
 * most). The picture's readers took that checksum of the very bytes they
 * drew ({@link FileVersion}), so a save after the reading is seen however
 * soon or late the watcher thread first looks: its bytes are held against
 * those drawn, not against the first the thread happens to see.
 */
public final class SceneWatcher {

    static final int POLL_MS = 200;
    public static final long FRESH_MILLIS = 3_000;

    /** Runs every look, one at a time: the files and the looks are this thread's only. */
    private final ScheduledExecutorService thread = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread t = new Thread(task, "simpview-watch");
        t.setDaemon(true);
        return t;
    });
    /** Told on the EDT. */
    private final Runnable changed;
    /** The files watched, as the EDT last gave them (read there by {@link #watched}). */
    private volatile List<Path> watched = List.of();
    /** True once the looks are scheduled (by the first {@link #watch}). */
    private boolean polling;
    /** The watcher thread's: the files it looks at, and what it saw of them. */
    private List<Path> files = List.of();
    private Changes changes = new Changes(List.of(), List.of());

    /** @param changed what to do, on the EDT, when a watched file changed */
    public SceneWatcher(Runnable changed) {
        this.changed = changed;
    }

    /**
     * What the looks at the watched files have found, and when a change is
     * to be told: the files differ from what the picture on screen was drawn
     * from, and the newest look found them as the one before it did, so no
     * save is half done (as far as a look can tell). Told once; the picture
     * drawn then is what the next change is held against.
     */
    static final class Changes {
        /** The files as the picture on screen was drawn from them, as far as known. */
        private List<FileVersion> drawn;
        /** The files at the newest look. */
        private List<FileVersion> last;

        /**
         * @param drawn the files as the picture on screen read them
         * @param now the files as they are now (in the same order)
         */
        Changes(List<FileVersion> drawn, List<FileVersion> now) {
            this.drawn = drawn;
            this.last = now;
        }

        /** Takes the newest look; true when it is a change to tell now. */
        boolean told(List<FileVersion> now) {
            boolean heldStill = !anyChanged(last, now);
            last = now;
            if (heldStill && anyChanged(drawn, now)) {
                drawn = now;
                return true;
            }
            return false;
        }

        private static boolean anyChanged(List<FileVersion> before, List<FileVersion> now) {
            for (int i = 0; i < now.size(); i++) {
                if (changed(before.get(i), now.get(i))) {
                    return true;
                }
            }
            return false;
        }
    }

    /** From now on watches {@code toWatch}, as they are when the watcher thread first looks (soon). */
    public void watch(List<Path> toWatch) {
        watch(toWatch, List.of());
    }

    /**
     * From now on watches {@code toWatch}; {@code asRead} are the files as
     * the picture on screen read them (same order; empty when not known):
     * each one's stamp before it was read and the checksum of the bytes read.
     * A file saved after it was read differs from that, also by its bytes
     * alone, and is told at the next look that finds it held still: its
     * picture is not what the file now says.
     */
    public synchronized void watch(List<Path> toWatch, List<FileVersion> asRead) {
        List<Path> list = List.copyOf(toWatch);
        List<FileVersion> read = List.copyOf(asRead);
        watched = list;
        if (thread.isShutdown()) {
            return;
        }
        thread.execute(() -> {
            files = list;
            changes = firstLook(list, read, System.currentTimeMillis());
        });
        if (!polling) {
            thread.scheduleWithFixedDelay(this::poll, POLL_MS, POLL_MS, TimeUnit.MILLISECONDS);
            polling = true;
        }
    }

    public List<Path> watched() {
        return watched;
    }

    /**
     * Returns once the watcher thread has taken every {@link #watch} given
     * before this call (for tests that look at what it watches). A save is
     * held against the files as the picture read them either way, before
     * or after the thread first looks. Not on the EDT.
     *
     * @throws InterruptedException when interrupted while waiting
     */
    public void awaitWatching() throws InterruptedException {
        try {
            thread.submit(() -> { }).get();
        } catch (ExecutionException e) {
            throw new IllegalStateException("the watcher thread failed", e.getCause());
        }
    }

    /** Stops looking for good and ends the watcher thread. */
    public synchronized void stop() {
        thread.shutdownNow();
    }

    /** On the watcher thread: looks again, and tells the EDT when something changed. */
    private void poll() {
        if (changes.told(looksNow())) {
            SwingUtilities.invokeLater(changed);
        }
    }

    private List<FileVersion> looksNow() {
        return looks(files, System.currentTimeMillis());
    }

    private static List<FileVersion> looks(List<Path> files, long now) {
        List<FileVersion> seen = new ArrayList<>(files.size());
        for (Path file : files) {
            seen.add(look(file, now));
        }
        return seen;
    }

    /**
     * What the watcher thread does with a {@link #watch}: looks at
     * {@code files} for the first time, at {@code now}, and holds the looks
     * to come against the files as the picture read them ({@code asRead}).
     */
    static Changes firstLook(List<Path> files, List<FileVersion> asRead, long now) {
        List<FileVersion> looks = looks(files, now);
        return new Changes(asDrawn(asRead, looks), looks);
    }

    /**
     * The files as the picture on screen read them: each file as it was
     * read, where the checksum of the bytes read is known or its stamp
     * differs from the look now; where only its stamp as read is known and
     * is the look's, the look now (the best there is: a save between the
     * reading and this look that keeps size, time and inode is not seen);
     * all the looks now when the files as read are not known.
     */
    static List<FileVersion> asDrawn(List<FileVersion> asRead, List<FileVersion> now) {
        if (asRead.size() != now.size()) {
            return now; // not known, or not of these files
        }
        List<FileVersion> drawn = new ArrayList<>(now.size());
        for (int i = 0; i < now.size(); i++) {
            FileVersion read = asRead.get(i);
            FileVersion look = now.get(i);
            drawn.add(read.checksummed() || !read.stamp().equals(look.stamp()) ? read : look);
        }
        return drawn;
    }

    /** True when {@code now} shows another file than {@code before}. */
    static boolean changed(FileVersion before, FileVersion now) {
        return before.differsFrom(now);
    }

    /** Size, last change and inode of a file, and its checksum when it changed within FRESH_MILLIS of {@code now}. */
    static FileVersion look(Path file, long now) {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(file, BasicFileAttributes.class);
        } catch (IOException e) {
            return FileVersion.of(FileStamp.MISSING);
        }
        FileStamp stamp = FileStamp.of(attributes);
        boolean fresh = attributes.lastModifiedTime().toMillis() > now - FRESH_MILLIS;
        boolean small = attributes.isRegularFile() && FileChecksum.taken(attributes.size());
        return new FileVersion(stamp, fresh && small ? checksum(file) : FileChecksum.NONE);
    }

    /** The CRC-32C of the file's bytes, or none when it cannot be read now. */
    private static long checksum(Path file) {
        try {
            return FileChecksum.of(file);
        } catch (IOException e) {
            return FileChecksum.NONE;
        }
    }
}
