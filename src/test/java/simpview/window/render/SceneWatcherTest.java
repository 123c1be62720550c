package simpview.window.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.scene.FileStamp;
import simpview.scene.FileVersion;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.scene.text.LineSource;
import simpview.surface.PageCanvas;

/** What the window's watcher takes for a changed file: a new stamp, or, while the file is fresh, new bytes. */
public class SceneWatcherTest {

    private static final String BEFORE = "polygon (-50, -50, -150) (50, -50, -150) (0, 50, -150)\n";
    private static final String AFTER = "polygon (-50, -50, -120) (50, -50, -120) (0, 50, -120)\n";

    @TempDir
    Path dir;

    private static FileVersion look(Path file) {
        return SceneWatcher.look(file, System.currentTimeMillis());
    }

    @Test
    void aSaveKeepingSizeInodeAndTimeIsSeenWhileTheFileIsFresh() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), BEFORE);
        FileTime saved = Files.getLastModifiedTime(file);
        FileVersion before = look(file);
        Files.writeString(file, AFTER);
        Files.setLastModifiedTime(file, saved); // as a second save within one tick of the file system's clock
        FileVersion after = look(file);
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
        FileVersion fresh = SceneWatcher.look(file, now);
        FileVersion settled = SceneWatcher.look(file, now + 2 * SceneWatcher.FRESH_MILLIS);
        assertNotEquals(-1, fresh.checksum());
        assertEquals(-1, settled.checksum(), "an old file is not read");
        assertFalse(SceneWatcher.changed(fresh, settled));
    }

    @Test
    void aNewTimeOrSizeIsAChangeAndSoIsAFileAppearingOrGoing() throws Exception {
        Path file = dir.resolve("a.simp");
        FileVersion missing = look(file);
        Files.writeString(file, BEFORE);
        FileVersion there = look(file);
        assertTrue(SceneWatcher.changed(missing, there), "appeared");
        Files.setLastModifiedTime(file, FileTime.fromMillis(System.currentTimeMillis() - 60_000));
        FileVersion older = look(file);
        assertTrue(SceneWatcher.changed(there, older), "another time");
        Files.writeString(file, BEFORE + "\n");
        assertTrue(SceneWatcher.changed(older, look(file)), "another size");
        Files.delete(file);
        assertTrue(SceneWatcher.changed(there, look(file)), "gone");
    }

    /** The looks at {@code files} now, in their order. */
    private static List<FileVersion> looks(Path... files) {
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
        List<FileVersion> asRead = List.of(FileVersion.of(FileStamp.of(file)));
        Files.writeString(file, "filled\nwire\n");
        List<FileVersion> now = looks(file);
        SceneWatcher.Changes changes = new SceneWatcher.Changes(SceneWatcher.asDrawn(asRead, now), now);
        assertTrue(changes.told(looks(file)), "the picture is of the file before this save");
        assertFalse(changes.told(looks(file)), "told once");

        List<FileVersion> unchanged = looks(file);
        SceneWatcher.Changes asItIs = new SceneWatcher.Changes(
                SceneWatcher.asDrawn(List.of(FileVersion.of(FileStamp.of(file))), unchanged), unchanged);
        assertFalse(asItIs.told(looks(file)), "drawn as it is: nothing to tell");
    }

    @Test
    void aSaveSinceTheFilesWereReadIsTold() throws Exception {
        Path file = Files.writeString(dir.resolve("a.simp"), "wire\n");
        List<FileVersion> asRead = List.of(FileVersion.of(FileStamp.of(file)));
        List<FileVersion> before = List.of(look(file));
        assertEquals(before, SceneWatcher.asDrawn(asRead, before), "as it was read");
        Files.writeString(file, "filled\nwire\n");
        List<FileVersion> after = List.of(look(file));
        assertNotEquals(after, SceneWatcher.asDrawn(asRead, after), "saved since");
        assertEquals(after, SceneWatcher.asDrawn(List.of(), after), "not known: not told");
    }

    /** A lit scene that includes a part and draws a model, each a file of its own. */
    private static final String TOP = "ambient 0.5 0.5 0.5\n{\n\tcamera -1 -1 1 1 -1 -100\n}\nfile \"part\"\nobj \"tri\"\n";
    private static final String PART = "surface 1 0 0\n";
    /** The same number of bytes as {@link #PART}: only the content tells. */
    private static final String PART_SAVED = "surface 0 1 0\n";
    private static final String MODEL = "v -5 -5 -10\nv 5 -5 -10\nv 0 5 -10\nf 1 2 3\n";
    private static final String MODEL_SAVED = "v -9 -9 -10\nv 9 -9 -10\nv 0 -7 -9\nf 1 2 3\n";

    /** What one picture of a scene read: its files, and each one as it was read (as a window's render job keeps them). */
    private record Picture(List<Path> files, List<FileVersion> asRead) {
    }

    private static Picture draw(Path top, SceneLibrary library) throws SceneException {
        List<FileVersion> asRead = new ArrayList<>();
        SceneMonitor monitor = new SceneMonitor() {
            @Override
            public void versionsAsRead(List<FileVersion> versions) {
                asRead.addAll(versions);
            }
        };
        List<Path> files = ScenePipeline.draw(top, new PageCanvas(), ScenePipeline.Options.byCommands(library), monitor)
                .files();
        return new Picture(files, asRead);
    }

    /** True when the watcher, taking {@code picture}'s files now, tells a change at its next look. */
    private static boolean toldAfterFirstLook(Picture picture) {
        SceneWatcher.Changes changes = SceneWatcher.firstLook(picture.files(), picture.asRead(),
                System.currentTimeMillis());
        return changes.told(looks(picture.files().toArray(Path[]::new)));
    }

    /** Writes {@code text} over the file in place, keeping its size, inode and time: a second save within one tick. */
    private static void saveWithinOneTick(Path file, String text) throws Exception {
        FileTime time = Files.getLastModifiedTime(file);
        Object inode = Files.readAttributes(file, BasicFileAttributes.class).fileKey();
        Files.writeString(file, text);
        Files.setLastModifiedTime(file, time);
        assertEquals(inode, Files.readAttributes(file, BasicFileAttributes.class).fileKey(), "written in place");
    }

    private Path scene() throws Exception {
        Files.writeString(dir.resolve("part.simp"), PART);
        Files.writeString(dir.resolve("tri.obj"), MODEL);
        return Files.writeString(dir.resolve("top.simp"), TOP);
    }

    /**
     * The race a window's watcher had: the picture reads its files, then a
     * save keeps a file's size, time and inode, and only then does the
     * watcher thread first look. The save is held against the bytes the
     * picture read, not taken for them.
     */
    @ParameterizedTest
    @ValueSource(strings = {"tri.obj", "part.simp"})
    void aSaveBeforeTheWatcherFirstLooksIsHeldAgainstTheBytesRead(String saved) throws Exception {
        Path top = scene();
        Picture picture = draw(top, new SceneLibrary());
        assertEquals(List.of(top, dir.resolve("part.simp"), dir.resolve("tri.obj")), picture.files());
        assertFalse(toldAfterFirstLook(picture), "nothing saved yet: the bytes read are the file's");
        Path file = dir.resolve(saved);
        FileStamp asRead = FileStamp.of(file);
        saveWithinOneTick(file, saved.endsWith(".obj") ? MODEL_SAVED : PART_SAVED);
        assertEquals(asRead, FileStamp.of(file), "size, time and inode alike");
        assertTrue(toldAfterFirstLook(picture), saved + " saved after it was read");
    }

    /**
     * A model kept from an earlier picture (not parsed again) is held
     * against the bytes it was parsed from.
     */
    @Test
    void aModelKeptFromAnEarlierPictureIsHeldAgainstTheBytesItWasParsedFrom() throws Exception {
        Path top = scene();
        SceneLibrary library = new SceneLibrary();
        draw(top, library);
        Picture second = draw(top, library);
        assertEquals(1, library.models().parseCount(), "the second picture drew the kept model");
        assertFalse(toldAfterFirstLook(second), "nothing saved yet");
        saveWithinOneTick(dir.resolve("tri.obj"), MODEL_SAVED);
        assertTrue(toldAfterFirstLook(second), "the model saved after it was drawn");
    }

    /** A part too big to be read whole is checksummed as it is streamed. */
    @Test
    void aStreamedPartIsHeldAgainstTheBytesRead() throws Exception {
        Path top = scene();
        String comments = "# a long comment to make the part too big to be read whole\n".repeat(1400);
        Path part = Files.writeString(dir.resolve("part.simp"), comments + PART);
        assertTrue(Files.size(part) > LineSource.CHUNK, "streamed");
        Picture picture = draw(top, new SceneLibrary());
        assertFalse(toldAfterFirstLook(picture), "nothing saved yet: the checksum streamed is the file's");
        saveWithinOneTick(part, comments + PART_SAVED);
        assertTrue(toldAfterFirstLook(picture), "the part saved after it was read");
    }
}
