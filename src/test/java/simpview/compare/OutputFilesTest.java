package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import simpview.testing.Fifos;

/**
 * Every file simpview writes is written whole or not at all: the file before
 * survives a failed write. A FIFO (or a device) is written into, not replaced.
 */
class OutputFilesTest {

    @TempDir
    Path dir;

    private List<String> names() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aWriteThatFailsHalfWayLeavesTheOldFileAndNoTemporary() throws IOException {
        Path file = Files.writeString(dir.resolve("compare.md"), "the good table\n");
        IOException failed = assertThrows(IOException.class, () -> OutputFiles.write(file, out -> {
            out.write("half of the new ta".getBytes(StandardCharsets.UTF_8));
            throw new IOException("No space left on device");
        }));
        assertEquals("cannot write " + file + ": No space left on device", failed.getMessage());
        assertEquals("the good table\n", Files.readString(file));
        assertEquals(List.of("compare.md"), names());
    }

    @Test
    void aWriterThatBreaksLeavesTheOldPictureAndNoTemporary() throws IOException {
        BufferedImage picture = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        picture.setRGB(1, 1, 0xFF8000);
        Path file = dir.resolve("page3.png");
        PngFiles.write(picture, file);
        byte[] good = Files.readAllBytes(file);
        assertThrows(IllegalStateException.class, () -> OutputFiles.write(file, out -> {
            out.write(good, 0, good.length / 2);
            throw new IllegalStateException("a bug half-way");
        }));
        assertArrayEquals(good, Files.readAllBytes(file));
        assertEquals(0xFF8000, ImageIO.read(file.toFile()).getRGB(1, 1) & 0xFFFFFF);
        assertEquals(List.of("page3.png"), names());
    }

    @Test
    void aFinishedWriteReplacesTheFileWholeAndMakesItsFolders() throws IOException {
        Path old = Files.writeString(dir.resolve("results.json"), "{\"score\": 1, \"and much more\": true}\n");
        OutputFiles.writeString(old, "{}\n");
        assertEquals("{}\n", Files.readString(old));
        Path deep = dir.resolve("report/diffs/page1-diff.png");
        PngFiles.writeEncoded(new byte[] {1, 2, 3}, deep);
        assertArrayEquals(new byte[] {1, 2, 3}, Files.readAllBytes(deep));
        assertEquals(List.of("report", "results.json"), names());
        try (Stream<Path> files = Files.list(deep.getParent())) {
            assertEquals(List.of("page1-diff.png"), files.map(f -> f.getFileName().toString()).toList());
        }
    }

    @Test
    void aFolderWhereTheFileShouldBeIsSaidAndKept() throws IOException {
        Path folder = Files.createDirectories(dir.resolve("page1.png"));
        Files.writeString(folder.resolve("inside"), "kept");
        IOException failed = assertThrows(IOException.class, () -> OutputFiles.writeString(folder, "x"));
        assertEquals("cannot write " + folder + ": it is a folder", failed.getMessage());
        assertEquals("kept", Files.readString(folder.resolve("inside")));
        Path plain = Files.writeString(dir.resolve("plain"), "a file");
        failed = assertThrows(IOException.class, () -> OutputFiles.writeString(plain.resolve("index.html"), "x"));
        assertEquals("cannot write " + plain.resolve("index.html") + ": " + plain
                + " is in the way: it is a file, not a folder", failed.getMessage());
    }

    @Test
    void aLinkIsFollowedAndKept() throws IOException {
        Path real = Files.writeString(dir.resolve("real.csv"), "old\n");
        Path link = dir.resolve("link.csv");
        try {
            Files.createSymbolicLink(link, real.getFileName());
        } catch (UnsupportedOperationException | IOException e) {
            Assumptions.abort("no symbolic links here: " + e.getMessage());
        }
        OutputFiles.writeString(link, "new\n");
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("new\n", Files.readString(real));
    }

    @Test
    void aNewFileMayBeReadByOthersAsOneWrittenDirectly() throws IOException {
        Assumptions.assumeTrue(FileSystems.getDefault().supportedFileAttributeViews().contains("posix"), "not POSIX");
        Path direct = Files.writeString(dir.resolve("direct.txt"), "x");
        Path written = dir.resolve("written.txt");
        OutputFiles.writeString(written, "x");
        assertEquals(Files.getPosixFilePermissions(direct), Files.getPosixFilePermissions(written));
    }

    /** A picture, as PngFiles writes it to a regular file: what a FIFO's reader must get, byte for byte. */
    private static BufferedImage picture() {
        BufferedImage picture = new BufferedImage(40, 30, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 30; y++) {
            for (int x = 0; x < 40; x++) {
                picture.setRGB(x, y, x * 6 << 16 | y * 8 << 8 | (x + y) * 3);
            }
        }
        return picture;
    }

    /** PNG bytes under another picture format's name would be opened as what they are not: refused, nothing written. */
    @Test
    void aPictureIsWrittenOnlyUnderAPngName() throws IOException {
        Path jpeg = dir.resolve("page3.jpg");
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> PngFiles.write(picture(), jpeg));
        assertEquals(jpeg + ": " + PngFiles.PNG_ONLY, refused.getMessage());
        assertEquals(List.of(), names());
        PngFiles.write(picture(), dir.resolve("page3.PNG"));
        PngFiles.write(picture(), dir.resolve("page3"));
        assertEquals(List.of("page3", "page3.PNG"), names());
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aFifoIsWrittenIntoAndKeptNotReplaced() throws Exception {
        Path regular = dir.resolve("regular.png");
        PngFiles.write(picture(), regular);
        Path fifo = Fifos.make(dir.resolve("page3.png"));
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        PngFiles.write(picture(), fifo);
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
        byte[] got = Fifos.read(read, fifo);
        assertFalse(Files.isRegularFile(fifo));
        assertArrayEquals(Files.readAllBytes(regular), got);
        assertEquals(List.of("page3.png", "regular.png"), names(), "no temporary beside the FIFO");
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aLinkToAFifoIsWrittenThroughAndBothAreKept() throws Exception {
        Path fifo = Fifos.make(dir.resolve("pipe"));
        Path link = dir.resolve("link.csv");
        try {
            Files.createSymbolicLink(link, fifo.getFileName());
        } catch (UnsupportedOperationException | IOException e) {
            Assumptions.abort("no symbolic links here: " + e.getMessage());
        }
        CompletableFuture<byte[]> read = Fifos.readAll(fifo);
        OutputFiles.writeString(link, "page,identical\n1,100\n");
        assertTrue(Files.isSymbolicLink(link));
        assertTrue(Fifos.isFifo(fifo), "the FIFO was replaced by a file");
        assertEquals("page,identical\n1,100\n", new String(Fifos.read(read, fifo), StandardCharsets.UTF_8));
        assertEquals(List.of("link.csv", "pipe"), names());
    }

    @Test
    void aFileThatCannotBeOpenedIsSaidAndKept() throws Exception {
        Assumptions.assumeFalse(System.getProperty("os.name").startsWith("Windows"),
                "a Unix socket on Windows is not a file that open() refuses");
        Path socket = dir.resolve("results.json");
        try (ServerSocketChannel server = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            server.bind(UnixDomainSocketAddress.of(socket));
            // a socket cannot be opened as a file: the write fails, and says so, rather than replace it
            IOException failed = assertThrows(IOException.class, () -> OutputFiles.writeString(socket, "{}\n"));
            assertTrue(failed.getMessage().startsWith("cannot write " + socket + ": "), failed.getMessage());
            assertFalse(failed.getMessage().contains("Exception"), failed.getMessage());
            assertFalse(Files.isRegularFile(socket), "the socket was replaced by a file");
            assertTrue(Files.exists(socket));
            assertEquals(List.of("results.json"), names());
        }
    }
}
