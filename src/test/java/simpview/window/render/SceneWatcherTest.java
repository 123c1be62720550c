package simpview.window.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.FileStamp;

/** What the window's watcher takes for a changed file: a new stamp, or, while the file is fresh, new bytes. */
public class SceneWatcherTest {

    private static final String BEFORE = "polygon (-50, -50, -150) (50, -50, -150) (0, 50, -150)\n";
    private static final String AFTER = "polygon (-50, -50, -120) (50, -50, -120) (0, 50, -120)\n";

    @TempDir
    Path dir;

    private static SceneWatcher.Look look(Path file) {
        return SceneWatcher.look(file, System.currentTimeMillis());
    }

    @Test
    void aSaveKeepingSizeInodeAndTimeIsSeenWhileTheFileIsFresh() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), BEFORE);
        FileTime saved = Files.getLastModifiedTime(file);
        SceneWatcher.Look before = look(file);
        Files.writeString(file, AFTER);
        Files.setLastModifiedTime(file, saved); // as a second save within one tick of the file system's clock
        SceneWatcher.Look after = look(file);
        assertEquals(before.stamp(), after.stamp(), "size, time and inode alike");
        assertTrue(SceneWatcher.changed(before, after), "the bytes tell");
    }

    @Test
    void anUnchangedFreshFileIsNotTakenForChanged() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), BEFORE);
        assertFalse(SceneWatcher.changed(look(file), look(file)));
    }

    @Test
    void aFileThatSettlesIsNotTakenForChanged() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), BEFORE);
        long now = System.currentTimeMillis();
        SceneWatcher.Look fresh = SceneWatcher.look(file, now);
        SceneWatcher.Look settled = SceneWatcher.look(file, now + 2 * SceneWatcher.FRESH_MILLIS);
        assertNotEquals(-1, fresh.checksum());
        assertEquals(-1, settled.checksum(), "an old file is not read");
        assertFalse(SceneWatcher.changed(fresh, settled));
    }

    @Test
    void aNewTimeOrSizeIsAChangeAndSoIsAFileAppearingOrGoing() throws Exception {
        Path file = dir.resolve("a.simp");
        SceneWatcher.Look missing = look(file);
        Files.writeString(file, BEFORE);
        SceneWatcher.Look there = look(file);
        assertTrue(SceneWatcher.changed(missing, there), "appeared");
        Files.setLastModifiedTime(file, FileTime.fromMillis(System.currentTimeMillis() - 60_000));
        SceneWatcher.Look older = look(file);
        assertTrue(SceneWatcher.changed(there, older), "another time");
        Files.writeString(file, BEFORE + "\n");
        assertTrue(SceneWatcher.changed(older, look(file)), "another size");
        Files.delete(file);
        assertTrue(SceneWatcher.changed(there, look(file)), "gone");
    }

    @Test
    void aSaveSinceTheFilesWereReadIsTold() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), "wire\n");
        List<FileStamp> asRead = List.of(FileStamp.of(file));
        assertFalse(SceneWatcher.savedSinceRead(asRead, List.of(look(file))), "as it was read");
        Files.writeString(file, "filled\nwire\n");
        assertTrue(SceneWatcher.savedSinceRead(asRead, List.of(look(file))), "saved since");
        assertFalse(SceneWatcher.savedSinceRead(List.of(), List.of(look(file))), "not known: not told");
    }
}
