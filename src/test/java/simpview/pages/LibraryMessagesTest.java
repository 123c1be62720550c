package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.inspect.InspectedScene;
import simpview.scene.SceneException;

/**
 * What a Java caller is told to do is said in the library's words, the
 * methods it calls; the command line's options (--simp-dir, --page) are the
 * command line's to add (its own tests pin those).
 */
class LibraryMessagesTest {

    @TempDir
    Path empty;

    @Test
    void aMissingCourseSceneNamesTheMethodThatNamesItsFolder() {
        PageContext context = PageContext.defaults().withSimpDir(empty);
        SceneException e = assertThrows(SceneException.class, () -> new PageRenderer().renderImage(6, context));
        assertEquals("page6.simp was not found in " + empty.toAbsolutePath().normalize()
                + "; name the folder of the course's scene files with PageContext.withSimpDir(folder)", e.problem());
        SceneException inspected = assertThrows(SceneException.class, () -> InspectedScene.page(7, context));
        assertFalse(inspected.getMessage().contains("--"), inspected.getMessage());
    }

    @Test
    void aPageBeyondTheScenesIsNotAnOption() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> InspectedScene.page(9, PageContext.defaults()));
        assertEquals("InspectedScene.page takes pages 4 to 8 (the pages drawn from scene files), not 9", e.getMessage());
    }
}
