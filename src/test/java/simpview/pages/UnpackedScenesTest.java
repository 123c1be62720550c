package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.testing.Images;

/**
 * simpview.jar's own scenes, unpacked for a Java caller: the same files as
 * simp/, drawing the same pages, and nothing left once the caller closes
 * them.
 */
class UnpackedScenesTest {

    private static Path project() {
        return Path.of(System.getProperty("simpview.projectDir", "."));
    }

    private static Path runnableJar() {
        String jar = System.getProperty("simpview.runnableJar");
        assertNotNull(jar, "simpview.runnableJar is not set: run the tests through Gradle, which builds the jar first");
        return Path.of(jar);
    }

    private static List<String> names(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void theJarsScenesAreSimpsFilesAndDrawTheSamePagesAndCloseLeavesNothing(@TempDir Path temporary)
            throws Exception {
        Path simp = project().resolve("simp");
        Path folder;
        try (UnpackedScenes own = UnpackedScenes.into(runnableJar(), temporary)) {
            folder = own.folder();
            assertEquals(List.of(folder.getFileName().toString()), names(temporary));
            assertEquals(names(simp), names(folder));
            for (String name : names(simp)) {
                assertArrayEquals(Files.readAllBytes(simp.resolve(name)), Files.readAllBytes(folder.resolve(name)), name);
            }
            BufferedImage fromJar = new PageRenderer().renderImage(4, own.context());
            BufferedImage fromSimp = new PageRenderer().renderImage(4, PageContext.of(simp));
            assertEquals(0, Images.differingPixels(fromSimp, fromJar));
            Files.writeString(folder.resolve("notes.txt"), "the caller's own file, in the caller's folder\n");
        }
        assertFalse(Files.exists(folder), folder + " is left");
        assertEquals(List.of(), names(temporary));
    }

    @Test
    void aJarWithoutScenesIsSaidAndLeavesNothing(@TempDir Path temporary) throws Exception {
        Path jar = temporary.resolve("plain.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new JarEntry("simpview/Nothing.class"));
            out.closeEntry();
        }
        IOException e = assertThrows(IOException.class, () -> UnpackedScenes.into(jar, temporary));
        assertEquals(jar + " carries no scenes (no simp/ in it)", e.getMessage());
        assertEquals(List.of("plain.jar"), names(temporary));
    }

    /** A file that is no jar at all (a scene, a missing path) is named, with why, not left to the zip reader's words. */
    @Test
    void aFileThatIsNoJarIsNamedWithWhy(@TempDir Path temporary) throws Exception {
        Path scene = Files.writeString(temporary.resolve("page4.simp"), "polygon (0, 0, -1) (1, 0, -1) (1, 1, -1)\n");
        IOException e = assertThrows(IOException.class, () -> UnpackedScenes.from(scene));
        assertTrue(e.getMessage().startsWith(scene + " cannot be read as a jar: it is no zip archive ("), e.getMessage());
        Path missing = temporary.resolve("simpview.jar");
        IOException none = assertThrows(IOException.class, () -> UnpackedScenes.from(missing));
        assertEquals(missing + " cannot be read: file not found", none.getMessage());
        assertEquals(List.of("page4.simp"), names(temporary));
    }

    @Test
    void simpviewLoadedFromItsClassesFolderIsToldToNameTheFolder() {
        // the tests run simpview from build/classes, not from a jar
        assertTrue(UnpackedScenes.simpviewJar().isEmpty());
        IOException e = assertThrows(IOException.class, UnpackedScenes::fromSimpviewJar);
        assertTrue(e.getMessage().startsWith("simpview was not loaded from simpview.jar but from "), e.getMessage());
        assertTrue(e.getMessage().endsWith("name the folder of its scenes (simp/ in the repository) with "
                + "PageContext.of(folder)"), e.getMessage());
    }
}
