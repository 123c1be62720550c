package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every file simpview writes is written whole or not at all: the file before survives a failed write. */
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
}
