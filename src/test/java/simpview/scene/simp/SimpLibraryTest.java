package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Vertex;
import simpview.scene.KeptFiles;
import simpview.scene.SceneException;

/**
 * The .simp files kept from picture to picture: replayed while unchanged,
 * read and drawn anew when changed, however the change was made, with the
 * same commands, places and messages as a first reading.
 */
class SimpLibraryTest {

    @TempDir
    Path dir;

    private static final String[] CUBE = {"line 0 0 0 1 1 1", "polygon 0 0 0 1 0 0 0 1 0"};

    /** A top file that includes the cube twice, moved between. */
    private void writeScene() throws IOException {
        SceneFixture files = new SceneFixture(dir);
        files.write("cube", CUBE);
        files.write("top", "file \"cube\"", "translate 2 0 0", "file \"cube\"");
    }

    /** Every file in the folder last modified a minute ago: settled. */
    private void settleAll() throws IOException {
        FileTime old = FileTime.fromMillis(System.currentTimeMillis() - 60_000);
        try (var files = Files.list(dir)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Files.setLastModifiedTime(f, old);
            }
        }
    }

    /** One picture of name.simp with the library: every vertex drawn, in order, as text. */
    private List<String> picture(String name, SimpLibrary library) throws SceneException {
        SceneFixture scene = new SceneFixture(dir).run(name, new FileStack(FileStack.SMALL_FILE, dir, library));
        List<String> drawn = new ArrayList<>();
        for (List<Vertex[]> kind : List.of(scene.lines, scene.filled, scene.wire)) {
            for (Vertex[] primitive : kind) {
                StringBuilder sb = new StringBuilder();
                for (Vertex v : primitive) {
                    sb.append(v.x()).append(' ').append(v.y()).append(' ').append(v.z()).append("; ");
                }
                drawn.add(sb.toString());
            }
        }
        return drawn;
    }

    @Test
    void aRedrawOfASettledSceneReadsNoFile() throws Exception {
        writeScene();
        settleAll();
        SimpLibrary library = new SimpLibrary();
        List<String> first = picture("top", library);
        assertEquals(2, library.readCount(), "top and cube, the cube once though included twice");
        assertEquals(2, library.filesKept());
        List<String> second = picture("top", library);
        assertEquals(first, second);
        assertEquals(2, library.readCount(), "both settled: trusted on their stamps");
        assertEquals(2, library.scanCount());
        assertEquals(first, picture("top", new SimpLibrary()), "the same as from a library of its own");
    }

    @Test
    void aFreshFileIsComparedByContentAndReplayedWhileUnchanged() throws Exception {
        writeScene();
        SimpLibrary library = new SimpLibrary();
        List<String> first = picture("top", library);
        List<String> second = picture("top", library);
        assertEquals(first, second);
        assertEquals(4, library.readCount(), "each picture reads each fresh file once, to compare it");
        assertEquals(2, library.scanCount(), "and scans none of them again");
    }

    /** A save within one tick of the file system's clock keeps size, inode and time: only the bytes tell. */
    @Test
    void aQuickSaveKeepingSizeInodeAndTimeIsDrawnAnew() throws Exception {
        writeScene();
        Path cube = dir.resolve("cube.simp");
        Object inode = Files.readAttributes(cube, BasicFileAttributes.class).fileKey();
        FileTime saved = Files.getLastModifiedTime(cube);
        SimpLibrary library = new SimpLibrary();
        List<String> before = picture("top", library);
        Files.writeString(cube, String.join("\n", CUBE).replace("line 0 0 0 1 1 1", "line 0 0 0 7 1 1") + "\n");
        Files.setLastModifiedTime(cube, saved);
        assertEquals(inode, Files.readAttributes(cube, BasicFileAttributes.class).fileKey(), "written in place");
        List<String> after = picture("top", library);
        assertNotEquals(before, after);
        assertEquals(picture("top", new SimpLibrary()), after, "the new file, not the kept one");
    }

    @Test
    void aSettledFileSavedAgainIsDrawnAnew() throws Exception {
        writeScene();
        settleAll();
        Path cube = dir.resolve("cube.simp");
        SimpLibrary library = new SimpLibrary();
        List<String> before = picture("top", library);
        Files.writeString(cube, String.join("\n", CUBE).replace("line 0 0 0 1 1 1", "line 0 0 0 1 5 1") + "\n");
        List<String> after = picture("top", library);
        assertNotEquals(before, after);
        assertEquals(picture("top", new SimpLibrary()), after);
        assertEquals(3, library.scanCount(), "the cube scanned again, the top file replayed");
    }

    @Test
    void aKeptFileSettlesOnceItIsOldEnough() throws Exception {
        writeScene();
        long settleMillis = 200;
        SimpLibrary library = new SimpLibrary(SimpLibrary.DEFAULT_BUDGET, settleMillis);
        picture("top", library);
        picture("top", library);
        assertEquals(4, library.readCount(), "fresh: compared by content");
        waitUntilOlderThan(settleMillis, dir.resolve("top.simp"), dir.resolve("cube.simp"));
        picture("top", library);
        assertEquals(6, library.readCount(), "old enough now: compared once more, then trusted");
        picture("top", library);
        picture("top", library);
        assertEquals(6, library.readCount());
        assertEquals(2, library.scanCount());
    }

    /** Waits until every file was last modified more than {@code millis} ago. */
    private static void waitUntilOlderThan(long millis, Path... files) throws Exception {
        for (Path f : files) {
            long due = Files.getLastModifiedTime(f).toMillis() + millis;
            while (System.currentTimeMillis() <= due) {
                Thread.sleep(Math.max(1, due + 1 - System.currentTimeMillis()));
            }
        }
    }

    /**
     * An error met while acting on a replayed command names the same line,
     * column and include chain as on a first reading.
     */
    @Test
    void anErrorInAReplayedFileReadsAsOnAFirstReading() throws Exception {
        SceneFixture files = new SceneFixture(dir);
        files.write("leaf", "line 0 0 0 1 1 1");
        files.write("mid", "# the leaf:", "  file \"leaf\"");
        files.write("top", "file \"mid\"");
        settleAll();
        SimpLibrary library = new SimpLibrary();
        picture("top", library);
        Files.delete(dir.resolve("leaf.simp"));
        SceneException replayed = assertThrows(SceneException.class, () -> picture("top", library));
        SceneException read = assertThrows(SceneException.class, () -> picture("top", new SimpLibrary()));
        assertEquals(read.getMessage(), replayed.getMessage());
        assertEquals(2, replayed.line());
        assertTrue(replayed.getMessage().contains("included from top.simp:1"), replayed.getMessage());
        assertEquals(3, library.scanCount(), "leaf, mid and top, once: the message comes from the recordings");
    }

    @Test
    void aLibraryWithoutRoomKeepsNothingAndDrawsTheSame() throws Exception {
        writeScene();
        settleAll();
        SimpLibrary none = new SimpLibrary(0, KeptFiles.SETTLE_MILLIS);
        List<String> drawn = picture("top", none);
        assertEquals(picture("top", new SimpLibrary()), drawn);
        assertEquals(0, none.filesKept());
        assertEquals(0, none.bytesKept());
        assertEquals(3, none.readCount(), "the cube read at each include");
    }

    @Test
    void aFileWithAnErrorIsNotKept() throws Exception {
        SceneFixture files = new SceneFixture(dir);
        files.write("bad", "line 0 0 0 1 1 1", "rotate Q 10");
        files.write("top", "file \"bad\"");
        settleAll();
        SimpLibrary library = new SimpLibrary();
        assertThrows(SceneException.class, () -> picture("top", library));
        assertEquals(0, library.filesKept());
    }

    @Test
    void clearDropsEveryFile() throws Exception {
        writeScene();
        SimpLibrary library = new SimpLibrary();
        picture("top", library);
        assertTrue(library.bytesKept() > 0);
        library.clear();
        assertEquals(0, library.filesKept());
        assertEquals(0, library.bytesKept());
    }

    @Test
    void oneLibraryServesSeveralThreadsAtOnce() throws Exception {
        writeScene();
        settleAll();
        SimpLibrary library = new SimpLibrary();
        List<String> expected = picture("top", new SimpLibrary());
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<List<String>>> pictures = new ArrayList<>();
            for (int k = 0; k < 16; k++) {
                pictures.add(pool.submit(() -> picture("top", library)));
            }
            for (Future<List<String>> p : pictures) {
                assertEquals(expected, p.get());
            }
        } finally {
            pool.shutdown();
        }
        assertEquals(2, library.filesKept());
    }
}
