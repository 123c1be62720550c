package simpview.window.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.stream.Stream;
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

    /** The looks at {@code files} now, in their order. */
    private static List<SceneWatcher.Look> looks(Path... files) {
        long now = System.currentTimeMillis();
        return Stream.of(files).map(file -> SceneWatcher.look(file, now)).toList();
    }

    /**
     * An editor that empties the file and then writes it (vim, nano), in
     * two calls, or by a new file renamed over the old: a look in the middle
     * of the save is not told; the save is, once a look finds the file as
     * the look before it did.
     */
    @Test
    void aSaveIsToldOnceTheFileHoldsStillNeverHalfWritten() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), BEFORE);
        Path other = Files.writeString(dir.resolve("b.simp"), "wire\n");
        SceneWatcher.Changes changes = new SceneWatcher.Changes(looks(file, other), looks(file, other));
        assertFalse(changes.told(looks(file, other)), "nothing saved");

        Files.writeString(file, ""); // emptied: the save has begun
        assertFalse(changes.told(looks(file, other)), "emptied, half way through the save");
        Files.writeString(file, AFTER.substring(0, 20));
        assertFalse(changes.told(looks(file, other)), "its first write");
        Files.writeString(file, AFTER);
        assertFalse(changes.told(looks(file, other)), "written whole, but not yet seen to hold still");
        assertTrue(changes.told(looks(file, other)), "held still: told");
        assertFalse(changes.told(looks(file, other)), "told once");

        Path temporary = Files.writeString(dir.resolve("b.simp.tmp"), "filled\nwire\n");
        Files.delete(other); // a rename save that leaves no file for a moment
        assertFalse(changes.told(looks(file, other)), "gone for a moment");
        Files.move(temporary, other);
        assertFalse(changes.told(looks(file, other)), "there again, not yet held still");
        assertTrue(changes.told(looks(file, other)), "the new file told");
    }

    @Test
    void aSaveWhileThePictureWasDrawnIsToldOnceItHoldsStill() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), "wire\n");
        List<FileStamp> asRead = List.of(FileStamp.of(file));
        Files.writeString(file, "filled\nwire\n");
        List<SceneWatcher.Look> now = looks(file);
        SceneWatcher.Changes changes = new SceneWatcher.Changes(SceneWatcher.asDrawn(asRead, now), now);
        assertTrue(changes.told(looks(file)), "the picture is of the file before this save");
        assertFalse(changes.told(looks(file)), "told once");

        List<SceneWatcher.Look> unchanged = looks(file);
        SceneWatcher.Changes asItIs = new SceneWatcher.Changes(
                SceneWatcher.asDrawn(List.of(FileStamp.of(file)), unchanged), unchanged);
        assertFalse(asItIs.told(looks(file)), "drawn as it is: nothing to tell");
    }

    @Test
    void aSaveSinceTheFilesWereReadIsTold() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), "wire\n");
        List<FileStamp> asRead = List.of(FileStamp.of(file));
        List<SceneWatcher.Look> before = List.of(look(file));
        assertEquals(before, SceneWatcher.asDrawn(asRead, before), "as it was read");
        Files.writeString(file, "filled\nwire\n");
        List<SceneWatcher.Look> after = List.of(look(file));
        assertNotEquals(after, SceneWatcher.asDrawn(asRead, after), "saved since");
        assertEquals(after, SceneWatcher.asDrawn(List.of(), after), "not known: not told");
    }
}
