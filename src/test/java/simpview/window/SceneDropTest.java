package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.datatransfer.StringSelection;
import java.awt.datatransfer.Transferable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JPanel;
import javax.swing.TransferHandler.TransferSupport;
import org.junit.jupiter.api.Test;

public class SceneDropTest {

    private final List<Path> opened = new ArrayList<>();
    private final List<String> leftOut = new ArrayList<>();
    private final List<String> told = new ArrayList<>();
    private final SceneDrop drop = new SceneDrop(this::open, told::add);

    private void open(List<Path> scenes, String left) {
        opened.addAll(scenes);
        leftOut.add(left);
    }

    @Test
    void opensEverySimpFileDroppedInTheOrderGivenAndNamesTheRest() {
        assertTrue(drop.importData(files("notes.txt", "tree.simp", "house.simp", "mine.png")));
        assertEquals(List.of(Path.of("tree.simp"), Path.of("house.simp")), opened);
        assertEquals(List.of("Left out notes.txt and mine.png: a drop with .simp files opens those alone (drop a "
                + "picture or a folder on its own)."), leftOut);
        opened.clear();
        leftOut.clear();
        assertTrue(drop.importData(files("house.simp")));
        assertEquals(List.of(Path.of("house.simp")), opened);
        assertEquals(List.of(""), leftOut);
    }

    @Test
    void saysWhatItWantsWhenNoSimpFileIsDropped() {
        assertFalse(drop.importData(files("notes.txt")));
        assertEquals(List.of(), opened);
        assertEquals(List.of("Drop a .simp file to open it."), told);
    }

    @Test
    void aPictureDroppedIsCompared() {
        List<Path> compared = new ArrayList<>();
        SceneDrop comparing = new SceneDrop(this::open, compared::add, told::add);
        assertTrue(comparing.importData(files("notes.txt", "Mine.PNG")));
        assertEquals(List.of(Path.of("Mine.PNG")), compared);
        assertFalse(comparing.importData(files("notes.txt")));
        assertEquals(List.of("Drop a .simp file to open it, or a picture (.png, .jpg) to compare it with the page."), told);
        assertFalse(drop.importData(files("mine.png")), "a window that does not compare refuses pictures");
    }

    @Test
    void aFolderDroppedIsChecked(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        List<Path> checked = new ArrayList<>();
        List<Path> compared = new ArrayList<>();
        SceneDrop checking = new SceneDrop(this::open, compared::add, checked::add, told::add);
        Path folder = Files.createDirectories(dir.resolve("my pages"));
        assertTrue(checking.importData(files("notes.txt", folder.toString())));
        assertEquals(List.of(folder), checked);
        assertFalse(checking.importData(files("notes.txt")));
        assertEquals(List.of("Drop a .simp file to open it, a picture (.png, .jpg) to compare it with the page, "
                + "or a folder of your pages to check them all."), told);
        assertFalse(new SceneDrop(this::open, compared::add, told::add).importData(files(folder.toString())),
                "a window that does not check folders refuses them");
        assertEquals(List.of(), compared);
    }

    @Test
    void refusesWhatIsNotAFileList() {
        assertFalse(drop.canImport(support(new StringSelection("house.simp"))));
        assertFalse(drop.importData(support(new StringSelection("house.simp"))));
        assertEquals(List.of(), opened);
    }

    private static TransferSupport support(Transferable data) {
        return new TransferSupport(new JPanel(), data);
    }

    private static TransferSupport files(String... names) {
        return support(DroppedFiles.named(names));
    }
}
