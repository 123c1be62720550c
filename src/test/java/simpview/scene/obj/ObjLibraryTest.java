package simpview.scene.obj;

import simpview.stage.ObjFace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
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
import simpview.scene.SceneException;

/** The cache of parsed models: kept while the file is unchanged, within its budget, shared safely. */
class ObjLibraryTest {

    @TempDir
    Path dir;

    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    private static final String TRIANGLES = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 3 2 1\n";

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    private static List<CollectedFaces.Face> draw(ObjLibrary library, Path file) throws SceneException {
        CollectedFaces sink = new CollectedFaces();
        library.draw(file, sink);
        return sink.faces;
    }

    private static List<CollectedFaces.Face> streamed(Path file) throws SceneException {
        CollectedFaces sink = new CollectedFaces();
        ObjReader.stream(file, sink);
        return sink.faces;
    }

    @Test
    void aFolderOrAMissingFileIsAnErrorThatSaysSo() throws Exception {
        ObjLibrary library = new ObjLibrary();
        Path folder = Files.createDirectory(dir.resolve("models.obj"));
        SceneException notAFile = assertThrows(SceneException.class, () -> draw(library, folder));
        assertTrue(notAFile.getMessage().contains("cannot read the obj file " + folder + ": not a file but a folder"),
                notAFile.getMessage());
        SceneException missing = assertThrows(SceneException.class, () -> draw(library, dir.resolve("none.obj")));
        assertTrue(missing.getMessage().contains("none.obj"), missing.getMessage());
        assertEquals(0, library.parseCount());
    }

    @Test
    void aSecondDrawOfAnUnchangedFileReplaysWithoutParsing() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        List<CollectedFaces.Face> first = draw(library, file);
        assertEquals(1, library.parseCount());
        List<CollectedFaces.Face> second = draw(library, file);
        assertEquals(1, library.parseCount(), "parsed again");
        assertEquals(streamed(file), first);
        assertEquals(first, second);
        assertEquals(1, library.modelsKept());
        assertEquals(ObjModel.read(file).bytes(), library.bytesKept());
    }

    @Test
    void drawReturnsTheCountsParsedOrReplayed() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        assertEquals(new ObjCounts(3, 1, 2), library.draw(file, face -> { }));
        assertEquals(new ObjCounts(3, 1, 2), library.draw(file, face -> { }));
    }

    @Test
    void aNewModificationTimeParsesAgain() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        draw(library, file);
        Files.setLastModifiedTime(file, FileTime.fromMillis(Files.getLastModifiedTime(file).toMillis() + 10_000));
        draw(library, file);
        assertEquals(2, library.parseCount());
        draw(library, file);
        assertEquals(2, library.parseCount());
        assertEquals(1, library.modelsKept());
    }

    @Test
    void newContentIsParsedAndDrawn() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        FileTime before = Files.getLastModifiedTime(file);
        draw(library, file);
        Files.writeString(file, SQUARE);
        Files.setLastModifiedTime(file, before); // only the size tells
        List<CollectedFaces.Face> faces = draw(library, file);
        assertEquals(2, library.parseCount());
        assertEquals(streamed(file), faces);
        assertEquals(4, faces.get(0).corners().size());
        assertEquals(ObjModel.read(file).bytes(), library.bytesKept(), "the old model is let go");
    }

    @Test
    void sameContentSameSizeNewTimeParsesAgain() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        draw(library, file);
        Files.writeString(file, TRIANGLES.replace("v 1 0 0", "v 7 0 0"));
        Files.setLastModifiedTime(file, FileTime.fromMillis(Files.getLastModifiedTime(file).toMillis() + 5_000));
        assertEquals(7.0, draw(library, file).get(0).corners().get(1).x());
        assertEquals(2, library.parseCount());
    }

    /** A save within one tick of the file system's clock keeps size, inode and time: only the bytes tell. */
    @Test
    void aQuickSaveKeepingSizeInodeAndTimeIsParsedAgain() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        Object inode = Files.readAttributes(file, BasicFileAttributes.class).fileKey();
        FileTime saved = Files.getLastModifiedTime(file);
        ObjLibrary library = new ObjLibrary();
        assertEquals(1.0, draw(library, file).get(0).corners().get(1).x());
        Files.writeString(file, TRIANGLES.replace("v 1 0 0", "v 7 0 0"));
        Files.setLastModifiedTime(file, saved);
        assertEquals(inode, Files.readAttributes(file, BasicFileAttributes.class).fileKey(), "written in place");
        assertEquals(7.0, draw(library, file).get(0).corners().get(1).x(), "the new model, not the kept one");
        assertEquals(2, library.parseCount());
        assertEquals(streamed(file), draw(library, file));
        assertEquals(2, library.parseCount(), "the new model is kept in its turn");
    }

    @Test
    void aFreshFileIsComparedByContentAndReplayedWhileUnchanged() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        draw(library, file);
        draw(library, file);
        draw(library, file);
        assertEquals(1, library.parseCount());
        assertEquals(2, library.contentCheckCount(), "one at each replay: the parse takes its checksum as it reads");
    }

    @Test
    void aFreshModelDrawnTwiceInOnePictureIsReadOnce() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        ObjFilesSeen picture = new ObjFilesSeen();
        library.draw(file, face -> { }, picture);
        library.draw(file, face -> { }, picture);
        assertEquals(1, library.parseCount());
        assertEquals(0, library.contentCheckCount(), "the picture has read its bytes already");
        library.draw(file, face -> { }, new ObjFilesSeen());
        assertEquals(1, library.contentCheckCount(), "the next picture compares them again");
    }

    @Test
    void aPictureLooksAtAModelFileOnce() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        ObjFilesSeen picture = new ObjFilesSeen();
        ObjCounts first = library.draw(file, face -> { }, picture);
        Files.delete(file);
        assertEquals(first, library.draw(file, face -> { }, picture), "the model as the picture first saw it");
        assertEquals(1, library.parseCount());
        SceneException gone = assertThrows(SceneException.class,
                () -> library.draw(file, face -> { }, new ObjFilesSeen()));
        assertTrue(gone.problem().startsWith("cannot open the obj file"), gone.problem());
    }

    @Test
    void aSettledFileIsTrustedOnItsStampAlone() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        Files.setLastModifiedTime(file, FileTime.fromMillis(System.currentTimeMillis() - 60_000));
        ObjLibrary library = new ObjLibrary();
        draw(library, file);
        draw(library, file);
        assertEquals(1, library.parseCount());
        assertEquals(0, library.contentCheckCount(), "no byte read but the parse's");
    }

    @Test
    void aKeptModelSettlesOnceItsFileIsOldEnough() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary(ObjLibrary.DEFAULT_BUDGET, 200);
        draw(library, file);
        draw(library, file);
        assertEquals(1, library.contentCheckCount(), "fresh: its bytes are compared with the parse's");
        Thread.sleep(400);
        draw(library, file);
        assertEquals(2, library.contentCheckCount(), "old enough now: compared once more, then trusted");
        draw(library, file);
        draw(library, file);
        assertEquals(2, library.contentCheckCount());
        assertEquals(1, library.parseCount());
    }

    @Test
    void twoNamesOfOneFileShareOneModel() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        Files.createDirectory(dir.resolve("sub"));
        Path roundabout = dir.resolve("sub").resolve("..").resolve("a.obj");
        Path link = Files.createSymbolicLink(dir.resolve("link.obj"), file);
        ObjLibrary library = new ObjLibrary();
        draw(library, file);
        draw(library, roundabout);
        draw(library, link);
        assertEquals(1, library.parseCount());
        assertEquals(1, library.modelsKept());
    }

    @Test
    void aModelBiggerThanTheBudgetStreamsEveryTime() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary(ObjModel.read(file).bytes() - 1);
        List<CollectedFaces.Face> first = draw(library, file);
        List<CollectedFaces.Face> second = draw(library, file);
        assertEquals(2, library.parseCount());
        assertEquals(0, library.modelsKept());
        assertEquals(0, library.bytesKept());
        assertEquals(streamed(file), first);
        assertEquals(first, second);
    }

    @Test
    void aModelOfExactlyTheBudgetIsKept() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary(ObjModel.read(file).bytes());
        draw(library, file);
        draw(library, file);
        assertEquals(1, library.parseCount());
    }

    @Test
    void theLeastRecentlyDrawnModelIsDroppedFirst() throws Exception {
        Path a = write("a.obj", TRIANGLES);
        Path b = write("b.obj", TRIANGLES + "f 1 3 2\n");
        Path c = write("c.obj", TRIANGLES + "f 2 1 3\n");
        long each = ObjModel.read(b).bytes();
        assertEquals(each, ObjModel.read(c).bytes());
        assertTrue(ObjModel.read(a).bytes() < each);
        ObjLibrary library = new ObjLibrary(2 * each);
        draw(library, a);
        draw(library, b);
        draw(library, a); // now b is the least recently drawn
        assertEquals(2, library.parseCount());
        draw(library, c);
        assertEquals(3, library.parseCount());
        assertEquals(2, library.modelsKept());
        draw(library, a);
        draw(library, c);
        assertEquals(3, library.parseCount(), "a and c kept");
        draw(library, b);
        assertEquals(4, library.parseCount(), "b was dropped");
        assertTrue(library.bytesKept() <= 2 * each);
    }

    @Test
    void aFileWithAnErrorIsNotKept() throws Exception {
        Path file = write("bad.obj", TRIANGLES + "f 1 2 9\n");
        ObjLibrary library = new ObjLibrary();
        CollectedFaces sink = new CollectedFaces();
        SceneException e = assertThrows(SceneException.class, () -> library.draw(file, sink));
        assertEquals(7, e.line());
        assertEquals(2, sink.faces.size(), "the faces before the error were drawn");
        assertThrows(SceneException.class, () -> library.draw(file, face -> { }));
        assertEquals(2, library.parseCount());
        assertEquals(0, library.modelsKept());
    }

    @Test
    void aDrawStoppedByItsSinkIsNotKept() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        assertThrows(IllegalStateException.class, () -> library.draw(file, face -> {
            throw new IllegalStateException("cancelled");
        }));
        assertEquals(0, library.modelsKept());
        assertEquals(streamed(file), draw(library, file));
        assertEquals(2, library.parseCount());
    }

    @Test
    void aMissingFileIsAnError() {
        ObjLibrary library = new ObjLibrary();
        Path missing = dir.resolve("gone.obj");
        SceneException e = assertThrows(SceneException.class, () -> library.draw(missing, face -> { }));
        assertEquals(missing, e.file());
        assertTrue(e.problem().startsWith("cannot open the obj file"), e.problem());
    }

    @Test
    void clearDropsEveryModel() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        ObjLibrary library = new ObjLibrary();
        draw(library, file);
        library.clear();
        assertEquals(0, library.bytesKept());
        draw(library, file);
        assertEquals(2, library.parseCount());
    }

    @Test
    void progressIsReportedOnLongFilesAndReplays() throws Exception {
        StringBuilder text = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        int faces = 3 * ObjReader.PROGRESS_LINES;
        for (int f = 0; f < faces; f++) {
            text.append("f 1 2 3\n");
        }
        Path file = write("long.obj", text.toString());
        List<Integer> parsed = new ArrayList<>();
        List<Integer> replayed = new ArrayList<>();
        ObjLibrary library = new ObjLibrary();
        library.draw(file, progressTo(parsed));
        library.draw(file, progressTo(replayed));
        int p = ObjReader.PROGRESS_LINES;
        assertEquals(List.of(p, 2 * p, 3 * p), parsed);
        assertEquals(List.of(p + 3, 2 * p + 3, 3 * p + 3), replayed, "the lines of every PROGRESS_LINES-th face");
    }

    private static ObjSink progressTo(List<Integer> lines) {
        return new ObjSink() {
            @Override
            public void face(ObjFace face) {
            }

            @Override
            public void progress(int line) {
                lines.add(line);
            }
        };
    }

    @Test
    void oneLibraryServesSeveralThreadsAtOnce() throws Exception {
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            StringBuilder text = new StringBuilder();
            for (int v = 0; v < 300; v++) {
                text.append("v ").append(v).append(' ').append(i).append(" 1 0.5 0.5 0.5\n");
            }
            for (int f = 0; f < 298; f++) {
                text.append("f ").append(f + 1).append(' ').append(f + 2).append(' ').append(f + 3).append('\n');
            }
            files.add(write("m" + i + ".obj", text.toString()));
        }
        List<List<CollectedFaces.Face>> expected = new ArrayList<>();
        for (Path file : files) {
            expected.add(streamed(file));
        }
        // Room for about three of the six models: drawing evicts and parses as it goes.
        ObjLibrary library = new ObjLibrary(3 * ObjModel.read(files.get(0)).bytes());
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<Integer>> results = new ArrayList<>();
            for (int t = 0; t < 4; t++) {
                int seed = t;
                results.add(pool.submit(() -> {
                    int checked = 0;
                    for (int n = 0; n < 60; n++) {
                        int i = (seed * 7 + n * (seed + 1)) % files.size();
                        assertEquals(expected.get(i), draw(library, files.get(i)));
                        checked++;
                    }
                    return checked;
                }));
            }
            for (Future<Integer> r : results) {
                assertEquals(60, r.get());
            }
        } finally {
            pool.shutdownNow();
        }
        assertTrue(library.bytesKept() <= 3 * ObjModel.read(files.get(0)).bytes());
        assertTrue(library.parseCount() >= files.size(), "every file was parsed at least once");
    }

    @Test
    void textInMemoryAndFileAgree() throws Exception {
        Path file = write("a.obj", TRIANGLES);
        CollectedFaces fromText = new CollectedFaces();
        ObjReader.stream(file, TRIANGLES.getBytes(StandardCharsets.UTF_8), fromText);
        assertEquals(streamed(file), fromText.faces);
    }
}
