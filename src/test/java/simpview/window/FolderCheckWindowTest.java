package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneDrawer;
import simpview.cli.CheckCommand;
import simpview.pages.Assignment1;
import simpview.window.render.View;
import javax.swing.JDialog;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import java.awt.Rectangle;
import java.util.Comparator;

/**
 * A folder dropped on the real window is checked as {@code simpview check FOLDER} checks it (issue 21):
 * its pages, the first assignment's pages panel by panel, its own scenes with their pictures, and its own
 * compare.json as the rubric.
 */
class FolderCheckWindowTest extends WindowTestCase {

    private static final long SEED = 361;

    @Test
    void aDroppedFolderIsCheckedPageByPage() throws Exception {
        Path mine = Files.createDirectories(dir.resolve("mine"));
        PageContext context = PageContext.defaults().withSeed(SEED);
        ImageIO.write(new PageRenderer().renderImage(1, context), "png", mine.resolve("page1.png").toFile());
        BufferedImage two = new PageRenderer().renderImage(2, context);
        for (int y = 200; y < 300; y++) {
            for (int x = 200; x < 300; x++) {
                two.setRGB(x, y, 0x00FFFF);
            }
        }
        ImageIO.write(two, "png", mine.resolve("page2.png").toFile());
        String table = drop(mine);
        assertEquals(CheckCommand.checkFolder(mine, context.withSimpDir(TestScenes.courseSimpDir())), table);
        assertTrue(table.contains("page1.png  page 1 (seed 361)  PASS"), table);
        assertTrue(table.contains("page2.png  page 2 (seed 361)  FAIL"), table);
        assertTrue(table.contains("no picture of page 8 found"), table);
        assertTrue(table.endsWith("1 of 2 pictures pass; 6 pages without a picture\n"), table);
        assertEquals("mine: 1 of 2 pictures pass; 6 pages without a picture",
                driver.onEdt(() -> driver.window().status().text()));
    }

    @Test
    void aDroppedFolderBringsItsScenesItsRubricAndTheFirstAssignmentsPages() throws Exception {
        Path mine = Files.createDirectories(dir.resolve("mine"));
        Files.writeString(mine.resolve("blank.simp"), "# draws nothing: a black panel\n");
        BufferedImage blank = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                boolean panel = x >= 50 && x < 700 && y >= 50 && y < 700;
                blank.setRGB(x, y, panel ? 0x000000 : 0xFFFFFF);
            }
        }
        for (int x = 300; x < 320; x++) {
            blank.setRGB(x, 400, 0xFFFFFF); // 20 stray pixels: 99.99 %, a pass by the defaults
        }
        ImageIO.write(blank, "png", mine.resolve("blank.png").toFile());
        ImageIO.write(Assignment1.render(2, PageContext.defaults().withSeed(SEED)), "png", mine.resolve("a1-page2.png").toFile());
        Files.writeString(mine.resolve("compare.json"), "{\"pages\": [{\"match\": \"blank\", \"max_failing_pixels\": 0}]}");

        String table = drop(mine);
        assertEquals(CheckCommand.checkFolder(mine, PageContext.defaults().withSeed(SEED)
                .withSimpDir(TestScenes.courseSimpDir())), table);
        assertTrue(table.startsWith("rubric: compare.json (the folder's own)\n"), table);
        assertTrue(table.matches("(?s).*\nblank\\.png +blank\\.simp +FAIL +99\\.99 % +x 250-269, y 299-299 .*"),
                "the folder's rubric allows no failing pixel: " + table);
        for (int k = 1; k <= 4; k++) {
            assertTrue(table.matches("(?s).*\na1-page2\\.png +A1 page 2 panel " + k + " .*PASS +100\\.00 % +none\n.*"), table);
        }
        // no picture is of the eight pages: they are not asked for (check FOLDER without --pages)
        assertTrue(table.endsWith("1 of 2 pictures pass; 4 of 4 panels pass (1 page of the first assignment)\n"), table);
    }

    @Test
    void theTableShowsWithoutTakingTheKeysFromThePage() throws Exception {
        Path mine = Files.createDirectories(dir.resolve("mine"));
        ImageIO.write(new PageRenderer().renderImage(1, PageContext.defaults().withSeed(SEED)), "png",
                mine.resolve("page1.png").toFile());
        openWindow();
        driver.focusByClicking(new View.OfPage(2));
        drop(mine);
        JDialog table = driver.onEdt(() -> driver.window().checkTable());
        driver.awaitEdt(table::isShowing, "the table's window");
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(3));
        drop(mine); // the next table comes in the same window, and again leaves the keys with the page
        driver.awaitEdt(() -> table == driver.window().checkTable() && table.isShowing(), "the table again");
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(4));
    }

    @Test
    void escapeClosesTheTable() throws Exception {
        Path mine = Files.createDirectories(dir.resolve("mine"));
        drop(mine);
        JDialog table = driver.onEdt(() -> driver.window().checkTable());
        driver.awaitEdt(table::isShowing, "the table's window");
        driver.click(table.getRootPane());
        driver.awaitEdt(table::isFocused, "the table's window to have the keys");
        driver.pressToClose(KeyEvent.VK_ESCAPE, table);
        driver.awaitEdt(() -> driver.window().frame().isFocused(), "the page to have the keys again");
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(2));
    }

    /**
     * The table's window shows its widest line whole, clear of its edge, within the screen: a table longer than
     * the screen scrolls, and its scroll bar takes none of the last column's width.
     */
    @Test
    void theTableShowsItsWidestLineWholeWithinTheScreen() throws Exception {
        StringBuilder lines = new StringBuilder();
        for (int row = 1; row <= 200; row++) {
            lines.append(String.format("page%03d.png  page 1 (seed 361)  FAIL  99.%02d %%  x 250-269, y 299-299  last", row,
                    row % 100)).append(row == 120 ? "  the widest line of all, ending here" : "").append('\n');
        }
        String table = lines.toString();
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.onEdt(() -> driver.window().checkFoldersWith((folder, context) -> table));
        assertTrue(DroppedFiles.dropOn(driver, Files.createDirectories(dir.resolve("mine"))), "the window took the folder");
        driver.awaitEdt(() -> table.equals(driver.window().lastCheck()), "the folder's table");
        JDialog window = driver.onEdt(() -> driver.window().checkTable());
        JScrollPane scroll = (JScrollPane) window.getContentPane().getComponent(0);
        JTextArea text = (JTextArea) scroll.getViewport().getView();
        driver.awaitEdt(() -> window.isShowing() && scroll.getViewport().getExtentSize().height > 0, "the table's window");
        Rectangle screen = driver.onEdt(() -> WindowPlacement.usableArea(window.getGraphicsConfiguration()));
        Rectangle bounds = driver.onEdt(() -> window.getBounds());
        assertTrue(screen.contains(bounds), "the table's window " + bounds + " within the screen " + screen);
        int widest = driver.onEdt(() -> text.getFontMetrics(text.getFont())
                .stringWidth(table.lines().max(Comparator.comparingInt(String::length)).orElseThrow()));
        assertTrue(driver.onEdt(() -> text.getInsets().right) > 0, "the last column clear of the edge");
        driver.awaitEdt(() -> scroll.getViewport().getExtentSize().width >= text.getPreferredSize().width
                && text.getPreferredSize().width >= widest + text.getInsets().left + text.getInsets().right
                && !scroll.getHorizontalScrollBar().isVisible(), "the widest line (" + widest + " px) shown whole");
    }

    private void openWindow() throws Exception {
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        driver.onEdt(() -> driver.window().checkFoldersWith(CheckCommand::checkFolder));
    }

    /** Drops the folder on the window (opened here, or the one open) and waits for its table. */
    private String drop(Path mine) throws Exception {
        if (driver == null) {
            openWindow();
        }
        String before = driver.onEdt(() -> driver.window().lastCheck());
        assertTrue(DroppedFiles.dropOn(driver, mine), "the window took the folder");
        driver.awaitEdt(() -> driver.window().lastCheck() != before, "the folder's table");
        return driver.onEdt(() -> driver.window().lastCheck());
    }
}
