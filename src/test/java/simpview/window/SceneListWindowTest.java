package simpview.window;

import simpview.scene.simp.SceneDrawer;
import simpview.window.render.View;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import simpview.pages.SceneList;

/** Scenes named at start, or several dropped at once, as the window's first pages, with the eight pages after them. */
public class SceneListWindowTest extends WindowTestCase {

    @Test
    void aFolderOfScenesIsSteppedThroughThenThePages() throws Exception {
        Files.writeString(dir.resolve("scene10.simp"), "ambient 1 1 1\npolygon (-50 -50 -100) (50 -50 -100) (0 50 -100)\n");
        Files.writeString(dir.resolve("scene2.simp"), "polygon (-50 -50 -100) (50 -50 -100) (0 50 -100)\n");
        List<Path> scenes = SceneList.of(List.of(dir));
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty(), scenes),
                SceneDrawer.SIMP);
        driver.awaitShown(new View.OfScene(dir.resolve("scene2.simp")));
        driver.focusByClicking(new View.OfScene(dir.resolve("scene10.simp")));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(1));
        driver.press(KeyEvent.VK_END);
        driver.awaitShown(new View.OfPage(8));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfScene(dir.resolve("scene2.simp")));
        driver.press(KeyEvent.VK_3);
        driver.awaitShown(new View.OfPage(3));
        driver.press(KeyEvent.VK_HOME);
        driver.awaitShown(new View.OfScene(dir.resolve("scene2.simp")));
        assertEquals("simpview — scene: scene2.simp", driver.onEdt(() -> driver.window().frame().getTitle()));
    }

    /** Several .simp files dropped together become the first pages, in the order given, as on the command line. */
    @Test
    void severalScenesDroppedAreSteppedThroughThenThePages() throws Exception {
        Path house = Files.writeString(dir.resolve("house.simp"), "polygon (-50 -50 -100) (50 -50 -100) (0 50 -100)\n");
        Path tree = Files.writeString(dir.resolve("tree.simp"), "line (-50 -50 -100) (50 50 -100)\n");
        Path notes = Files.writeString(dir.resolve("notes.txt"), "not a scene\n");
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));

        assertTrue(DroppedFiles.dropOn(driver, tree, notes, house), "the window took the scenes");
        driver.awaitShown(new View.OfScene(tree));
        driver.awaitEdt(() -> driver.window().status().text().equals("Opened the 2 scenes dropped as the first pages, "
                + "before the eight: tree.simp, house.simp (→ steps through them). Left out notes.txt: a drop with "
                + ".simp files opens those alone (drop a picture or a folder on its own)."), "what the drop did");
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfScene(house));
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(1));
        driver.press(KeyEvent.VK_LEFT);
        driver.awaitShown(new View.OfScene(house));
        driver.press(KeyEvent.VK_HOME);
        driver.awaitShown(new View.OfScene(tree));
    }
}
