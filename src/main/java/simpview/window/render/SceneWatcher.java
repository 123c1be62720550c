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
 * most {@link #CHECKSUM_LIMIT} long (a few milliseconds of reading at most).
 */
public final class SceneWatcher {

    static final int POLL_MS = 200;
    public static final long FRESH_MILLIS = 3_000;
    static final long CHECKSUM_LIMIT = 8L << 20;
    private static final long NO_CHECKSUM = -1;

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
     * What was seen of a file at one look.
     *
     * @param stamp size, last change and inode, or {@link FileStamp#MISSING}
     * @param checksum the CRC-32C of its bytes when it was fresh and small, else {@link #NO_CHECKSUM}
     */
    record Look(FileStamp stamp, long checksum) {
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
        private List<Look> drawn;
        /** The files at the newest look. */
        private List<Look> last;

        /**
         * @param drawn the files as the picture on screen read them
         * @param now the files as they are now (in the same order)
         */
        Changes(List<Look> drawn, List<Look> now) {
            this.drawn = drawn;
            this.last = now;
        }

        /** Takes the newest look; true when it is a change to tell now. */
        boolean told(List<Look> now) {
            boolean heldStill = !anyChanged(last, now);
            last = now;
            if (heldStill && anyChanged(drawn, now)) {
                drawn = now;
                return true;
            }
            return false;
        }

        private static boolean anyChanged(List<Look> before, List<Look> now) {
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
     * From now on watches {@code toWatch}; {@code asRead} are their stamps as
     * the picture on screen read them (same order; empty when not known). A
     * file saved while the picture was drawn differs from its stamp as read,
     * and is told at the next look that finds it held still: its picture is
     * not what the file now says.
     */
    public synchronized void watch(List<Path> toWatch, List<FileStamp> asRead) {
        List<Path> list = List.copyOf(toWatch);
        List<FileStamp> read = List.copyOf(asRead);
        watched = list;
        if (thread.isShutdown()) {
            return;
        }
        thread.execute(() -> {
            files = list;
            List<Look> now = looksNow();
            changes = new Changes(asDrawn(read, now), now);
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
     * before this call: from then on a save is held against the files as
     * the picture on screen read them. Before, a save that keeps a file's
     * size, time and inode (two within one tick of a coarse clock) may be
     * taken for what was read, its bytes being the first the thread sees.
     * Not on the EDT.
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

    private List<Look> looksNow() {
        long now = System.currentTimeMillis();
        List<Look> seen = new ArrayList<>(files.size());
        for (Path file : files) {
            seen.add(look(file, now));
        }
        return seen;
    }

    /**
     * The files as the picture on screen read them: each file's look now
     * where its stamp is the one it was read at (or the stamps are not
     * known), else its stamp as read, without checksum.
     */
    static List<Look> asDrawn(List<FileStamp> asRead, List<Look> now) {
        if (asRead.size() != now.size()) {
            return now; // not known, or not of these files
        }
        List<Look> drawn = new ArrayList<>(now.size());
        for (int i = 0; i < now.size(); i++) {
            Look look = now.get(i);
            drawn.add(asRead.get(i).equals(look.stamp()) ? look : new Look(asRead.get(i), NO_CHECKSUM));
        }
        return drawn;
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
            return new Look(FileStamp.MISSING, NO_CHECKSUM);
        }
        FileStamp stamp = FileStamp.of(attributes);
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
