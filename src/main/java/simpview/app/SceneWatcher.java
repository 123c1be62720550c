package simpview.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import javax.swing.Timer;

/**
 * Watches the files of the picture on screen (the scene and every file it
 * read) and says when one of them changed: its size or its time of last
 * change differs, or it appeared or went away. It looks a few times a
 * second on the EDT, which is cheap for the handful of files a scene reads
 * and sees an editor's save however the editor writes (in place, or a new
 * file renamed over the old).
 */
final class SceneWatcher {

    static final int POLL_MS = 200;

    private final Timer timer;
    private final Runnable changed;
    private List<Path> files = List.of();
    private List<Object> stamps = List.of();

    SceneWatcher(Runnable changed) {
        this.changed = changed;
        this.timer = new Timer(POLL_MS, e -> poll());
        timer.setCoalesce(true);
    }

    /** From now on watches {@code watched}, as they are now. */
    void watch(List<Path> watched) {
        files = List.copyOf(watched);
        stamps = stampsNow();
        if (files.isEmpty()) {
            timer.stop();
        } else if (!timer.isRunning()) {
            timer.start();
        }
    }

    List<Path> watched() {
        return files;
    }

    void stop() {
        timer.stop();
    }

    private void poll() {
        List<Object> now = stampsNow();
        if (!now.equals(stamps)) {
            stamps = now;
            changed.run();
        }
    }

    private List<Object> stampsNow() {
        List<Object> now = new ArrayList<>(files.size());
        for (Path file : files) {
            now.add(stamp(file));
        }
        return now;
    }

    /** Size and last change of a file, or "missing". */
    private static Object stamp(Path file) {
        try {
            BasicFileAttributes attributes = Files.readAttributes(file, BasicFileAttributes.class);
            return List.of(attributes.size(), attributes.lastModifiedTime(), Objects.toString(attributes.fileKey()));
        } catch (IOException e) {
            return "missing";
        }
    }
}
