package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SceneListTest {

    @TempDir
    Path dir;

    private List<String> names(List<Path> files) {
        List<String> names = new ArrayList<>();
        files.forEach(f -> names.add(f.getFileName().toString()));
        return names;
    }

    @Test
    void aFolderGivesItsScenesInNaturalOrder() throws IOException {
        for (String n : List.of("page-b1", "pageJ", "page-a2", "page10", "pageB", "page2", "page-a10", "pageA",
                "page-a1")) {
            Files.writeString(dir.resolve(n + ".simp"), "");
        }
        Files.writeString(dir.resolve("notes.txt"), "");
        Files.createDirectory(dir.resolve("sub.simp"));
        assertEquals(List.of("page-a1.simp", "page-a2.simp", "page-a10.simp", "page-b1.simp", "page2.simp",
                "page10.simp", "pageA.simp", "pageB.simp", "pageJ.simp"), names(SceneList.of(List.of(dir))));
    }

    /** Why a folder could not be read, in words: the exception's message was its path again. */
    @Test
    void aFolderThatCannotBeReadSaysWhy() throws IOException {
        Path file = Files.writeString(dir.resolve("scenes"), "");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SceneList.folder(file));
        assertEquals("cannot read the folder " + file + ": not a folder but a file", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> SceneList.folder(dir.resolve("gone")));
        assertEquals("cannot read the folder " + dir.resolve("gone") + ": no such folder", e.getMessage());
    }

    @Test
    void scenesKeepTheOrderGivenAndMayOmitTheExtension() throws IOException {
        Files.writeString(dir.resolve("pageB.simp"), "");
        Files.writeString(dir.resolve("pageA.simp"), "");
        assertEquals(List.of("pageB.simp", "pageA.simp"),
                names(SceneList.of(List.of(dir.resolve("pageB"), dir.resolve("pageA.simp")))));
    }

    @Test
    void whatIsNoSceneIsNamed() throws IOException {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SceneList.of(List.of(dir.resolve("missing"))));
        assertTrue(e.getMessage().startsWith("no scene " + dir.resolve("missing") + " (nor missing.simp)"),
                e.getMessage());
        Files.createDirectory(dir.resolve("empty"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> SceneList.of(List.of(dir.resolve("empty"))))
                .getMessage().contains("holds no .simp files"));
    }

    @Test
    void picturesAreNamedAfterTheirScenes() {
        assertEquals("pageA.png", SceneList.pictureName(Path.of("x/pageA.simp")));
    }
}
