package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.awt.KeyboardFocusManager;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.datatransfer.DataFlavor;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.geom.Rectangle2D;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import simpview.scene.simp.SceneDrawer;
import simpview.surface.PageCanvas;
import simpview.testing.CourseFiles;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * The view on a small screen, the menu bar and getting to a pixel, under
 * Xvfb: on a 768-pixel-high screen the panel is at 1:1 beside the inspector;
 * the inspector follows the pointer, goes to a pixel by its coordinates, and
 * a click on a part of the include chain copies it; menu entries do what
 * their keys do.
 */
public class ViewWindowTest extends WindowTestCase {

    @Test
    void onA768PixelScreenThePanelIsAt1To1BesideTheInspectorWhichFollowsThePointerAndGoesToAPixel() throws Exception {
        Files.writeString(dir.resolve("leaf.simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path scene = dir.resolve("top.simp");
        Files.writeString(scene, "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\nfile \"leaf\"\n");
        SimpviewWindow window = openWindowOn(scene);
        // Xvfb's screen is 1280x1024; the window placed as on a 1366x768 laptop's (its height is what binds).
        driver.onEdt(() -> window.placeWithin(new Rectangle(0, 0, 1280, 768)));
        driver.press(KeyEvent.VK_I);
        driver.awaitEdt(() -> window.inspectorPanel().component().isShowing()
                && window.pageView().getWidth() >= PageCanvas.PANEL, "the panel shown beside the page");
        driver.settle();
        ZoomPan zoomPan = window.pageView().zoomPan();
        assertEquals(1.0, (double) driver.onEdt(zoomPan::zoom), "the panel at 1:1");
        assertTrue(driver.onEdt(zoomPan::cropped), "the white margins cropped");
        int width = driver.onEdt(() -> window.pageView().getWidth());
        int height = driver.onEdt(() -> window.pageView().getHeight());
        assertTrue(height < PageCanvas.SIZE, "the whole page does not fit: " + height);
        double left = driver.onEdt(() -> zoomPan.screenX(PageCanvas.MARGIN));
        double top = driver.onEdt(() -> zoomPan.screenY(PageCanvas.MARGIN));
        assertTrue(left >= 0 && top >= 0 && left + PageCanvas.PANEL <= width && top + PageCanvas.PANEL <= height,
                "the whole panel in view at " + left + "," + top + " in " + width + "x" + height);
        assertEquals(0, driver.screenDiffersFrom(driver.onEdt(() -> window.shown()).image()), "the panel on screen");

        // Nothing pinned: the panel follows the pointer.
        Point centre = driver.onScreen(PageCanvas.SIZE / 2, PageCanvas.SIZE / 2);
        driver.robot().mouseMove(centre.x, centre.y);
        awaitPanel(window, "pixel (325, 324) of the panel");
        assertTrue(driver.onEdt(() -> window.status().inspectorText()).contains("1:1, margins cropped"));
        Point other = driver.onScreen(PageCanvas.MARGIN + 300, PageCanvas.MARGIN + 400);
        driver.robot().mouseMove(other.x, other.y);
        awaitPanel(window, "pixel (300, 249) of the panel");

        // Shift+G: go to panel pixel (325, 330), typed; it is pinned, the panel shows it, the image's row is said.
        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_G);
        driver.awaitEdt(() -> KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner()
                instanceof JTextField, "the go-to-pixel dialog");
        // Typed without waiting for the toolkit to be idle after each key: under a modal dialog that wait
        // (Robot.waitForIdle) can run into its timeout, seconds a key; the X server keeps the keys' order.
        for (int key : new int[] {KeyEvent.VK_3, KeyEvent.VK_2, KeyEvent.VK_5, KeyEvent.VK_COMMA, KeyEvent.VK_3,
                KeyEvent.VK_3, KeyEvent.VK_0, KeyEvent.VK_ENTER}) {
            driver.robot().keyPress(key);
            driver.robot().keyRelease(key);
        }
        try {
            driver.awaitEdt(() -> window.status().messageText().startsWith("Pinned panel pixel (325, 330)"),
                    "the pixel pinned");
        } catch (AssertionError e) {
            throw new AssertionError(e.getMessage() + "; the status line says: "
                    + driver.onEdt(() -> window.status().messageText()), e);
        }
        assertTrue(driver.onEdt(() -> window.status().messageText()).contains("column 375, row 369"));
        driver.robot().mouseMove(1, 1);
        String text = awaitPanel(window, "pixel (325, 330) of the panel");
        assertTrue(text.contains("drawn by primitive 2: top.simp:2 › leaf.simp:1 polygon"), text);

        // A click on "leaf.simp:1" in the panel copies that file's path and line.
        Point link = driver.onEdt(() -> {
            JTextArea area = (JTextArea) ((JScrollPane) window.inspectorPanel().component()).getViewport().getView();
            int at = area.getText().indexOf("leaf.simp:1");
            Rectangle2D box = area.modelToView2D(at + 3);
            area.scrollRectToVisible(box.getBounds());
            Point p = new Point((int) box.getCenterX(), (int) box.getCenterY());
            SwingUtilities.convertPointToScreen(p, area);
            return p;
        });
        driver.robot().mouseMove(link.x, link.y);
        driver.robot().mousePress(InputEvent.BUTTON1_DOWN_MASK);
        driver.robot().mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        String copied = dir.resolve("leaf.simp").toAbsolutePath() + ":1";
        driver.awaitEdt(() -> window.status().messageText().equals("Copied " + copied), "the part copied");
        assertEquals(copied, Toolkit.getDefaultToolkit().getSystemClipboard().getData(DataFlavor.stringFlavor));
    }

    @Test
    void theMenuBarsEntriesShowTheirKeysAndDoWhatTheKeysDo() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);
        SimpviewWindow window = driver.window();
        JMenuBar bar = driver.onEdt(() -> window.frame().getJMenuBar());
        int entries = driver.onEdt(() -> {
            int n = 0;
            for (int m = 0; m < bar.getMenuCount(); m++) {
                if (bar.getMenu(m) == null) {
                    continue; // the glue and the legend at the bar's right end
                }
                for (int k = 0; k < bar.getMenu(m).getItemCount(); k++) {
                    JMenuItem item = bar.getMenu(m).getItem(k);
                    if (item != null) {
                        WindowAction action = WindowAction.valueOf(item.getName());
                        assertEquals(action.accelerator(), item.getAccelerator(), action + "'s accelerator");
                        assertEquals(action.menu().title(), bar.getMenu(m).getText());
                        n++;
                    }
                }
            }
            return n;
        });
        assertEquals(WindowAction.values().length, entries, "every action has its menu entry");

        // View > Crop to the panel, clicked: the panel fills the view, as X does.
        chooseFromMenu(window, "VIEW", WindowAction.CROP);
        driver.awaitEdt(() -> window.pageView().zoomPan().cropped(), "the crop");
        assertTrue(driver.onEdt(() -> window.status().inspectorText()).contains("margins cropped"));
        // View > Depth view, a toggle: on, as D turns it on, and ticked in the menu when it opens again.
        assertEquals(Boolean.FALSE, driver.onEdt(() -> window.isOn(WindowAction.DEPTH_VIEW)));
        chooseFromMenu(window, "VIEW", WindowAction.DEPTH_VIEW);
        driver.awaitEdt(() -> window.isOn(WindowAction.DEPTH_VIEW), "the depth view on");
        JMenuItem depth = chooseFromMenu(window, "VIEW", WindowAction.DEPTH_VIEW);
        driver.awaitEdt(() -> !window.isOn(WindowAction.DEPTH_VIEW), "the depth view off again");
        assertTrue(driver.onEdt(() -> depth instanceof JCheckBoxMenuItem));
        // Page > Page 3, clicked: page 3, as the key 3 does.
        chooseFromMenu(window, "PAGE", WindowAction.PAGE_3);
        driver.awaitShown(new View.OfPage(3));
        assertFalse(driver.onEdt(window::busy));
        // Page > Assignment 3: the course's A3 pages (pageA ... tomsPageJ), stepped by the page keys.
        CourseFiles.require("course-simp-a3");
        Path a3 = CoursePageSet.folder(TestScenes.courseSimpDir(), 3);
        chooseFromMenu(window, "PAGE", WindowAction.ASSIGNMENT_3);
        driver.awaitShown(new View.OfScene(a3.resolve("pageA.simp")));
        assertEquals("simpview — assignment 3, page 1/10: pageA.simp", driver.onEdt(() -> window.frame().getTitle()));
        driver.onEdt(() -> window.perform(WindowAction.NEXT));
        driver.awaitShown(new View.OfScene(a3.resolve("pageB.simp")));
        driver.onEdt(() -> window.perform(WindowAction.ASSIGNMENT_2));
        driver.awaitShown(new View.OfPage(3));
        // On the first assignment's pages the panel follows the pointer too: the pixel's panel drawn again, its writes.
        driver.onEdt(() -> window.perform(WindowAction.ASSIGNMENT_1));
        driver.awaitShown(new View.OfAssignment1Page(1));
        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        Point inPanel = driver.onScreen(200, 200);
        driver.robot().mouseMove(inPanel.x, inPanel.y);
        driver.awaitEdt(() -> window.inspectorPanel().text().contains("of the first assignment's page 1")
                && window.inspectorPanel().text().contains("panel 1 (DDA)")
                && window.inspectorPanel().text().contains("history: "), "the history of a pixel of page 1's panel 1");
        driver.onEdt(() -> window.perform(WindowAction.INSPECTOR));
        driver.robot().mouseMove(1, 1);
        // Help > Keys and gestures shows F1's help over the window; F1 hides it.
        chooseFromMenu(window, "HELP", WindowAction.HELP);
        driver.awaitEdt(() -> window.frame().getGlassPane().isShowing(), "the key help shown");
        driver.press(KeyEvent.VK_F1);
        driver.awaitEdt(() -> !window.frame().getGlassPane().isVisible(), "the key help hidden by F1");
        // Escape hides it too; so does a click on it, and the click does not step the page hidden behind it.
        driver.press(KeyEvent.VK_F1);
        driver.awaitEdt(() -> window.frame().getGlassPane().isShowing(), "the key help shown again");
        driver.press(KeyEvent.VK_ESCAPE);
        driver.awaitEdt(() -> !window.frame().getGlassPane().isVisible(), "the key help hidden by Escape");
        driver.press(KeyEvent.VK_F1);
        driver.awaitEdt(() -> window.frame().getGlassPane().isShowing(), "the key help shown once more");
        driver.click(window.pageView().getRootPane());
        driver.awaitEdt(() -> !window.frame().getGlassPane().isVisible(), "the key help hidden by a click");
        driver.settle();
        assertFalse(driver.onEdt(window::busy), "the click drew no other page");
        assertEquals(new View.OfAssignment1Page(1), driver.onEdt(() -> window.shown().view()), "still page 1");
    }

    @Test
    void openStartsInTheShownScenesFolderAndOnThePagesWhereItWasLeft() throws Exception {
        Path mine = Files.createDirectories(dir.resolve("mine"));
        Path scene = Files.writeString(mine.resolve("own.simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        // a course folder of its own: the pages shown here need none of the course's files, and the test runs without them
        Path course = Files.createDirectories(dir.resolve("course-simp"));
        driver = WindowDriver.open(new WindowOptions(361, course, Optional.empty()), SceneDrawer.SIMP);
        SimpviewWindow window = driver.window();
        driver.onEdt(() -> window.openScene(scene));
        driver.awaitShown(new View.OfScene(scene));
        assertEquals(mine.toRealPath(), openDialogFolder(window));

        driver.onEdt(window::next);
        driver.awaitShown(new View.OfPage(2));
        assertEquals(course.toRealPath(), openDialogFolder(window));

        // page 4 is drawn from simpview's own page4.simp: the dialog starts in that scene's folder
        driver.onEdt(window::next);
        driver.awaitShown(new View.OfPage(3));
        driver.onEdt(window::next);
        RenderedView four = driver.awaitShown(new View.OfPage(4));
        assertEquals(four.facts().files().get(0).toRealPath().getParent(), openDialogFolder(window));
        assertEquals("page4.simp", four.facts().files().get(0).getFileName().toString());
    }

    /** The folder File > Open's dialog starts in, read from the dialog itself, which is then cancelled. */
    private Path openDialogFolder(SimpviewWindow window) throws Exception {
        SwingUtilities.invokeLater(() -> window.perform(WindowAction.OPEN)); // modal: it returns when the dialog closes
        AtomicReference<JFileChooser> found =
                new AtomicReference<>();
        driver.awaitEdt(() -> {
            for (Window w : Window.getWindows()) {
                if (w.isShowing() && w instanceof JDialog dialog) {
                    found.set(chooserIn(dialog.getContentPane()));
                }
            }
            return found.get() != null;
        }, "the Open dialog");
        Path folder = driver.onEdt(() -> found.get().getCurrentDirectory().toPath().toRealPath());
        driver.onEdt(() -> found.get().cancelSelection());
        driver.awaitEdt(() -> !found.get().isShowing(), "the Open dialog closed");
        return folder;
    }

    private static JFileChooser chooserIn(Container container) {
        for (Component c : container.getComponents()) {
            if (c instanceof JFileChooser chooser) {
                return chooser;
            }
            if (c instanceof Container inner && chooserIn(inner) != null) {
                return chooserIn(inner);
            }
        }
        return null;
    }

    /** Clicks a menu on the bar, waits for its popup, and clicks the action's entry in it. */
    private JMenuItem chooseFromMenu(SimpviewWindow window, String menuName, WindowAction action) throws Exception {
        JMenu menu = driver.onEdt(() -> {
            JMenuBar bar = window.frame().getJMenuBar();
            for (int m = 0; m < bar.getMenuCount(); m++) {
                if (bar.getMenu(m) != null && bar.getMenu(m).getName().equals(menuName)) {
                    return bar.getMenu(m);
                }
            }
            throw new AssertionError("no menu " + menuName);
        });
        driver.click(menu);
        JMenuItem item = driver.onEdt(() -> {
            for (int k = 0; k < menu.getItemCount(); k++) {
                if (menu.getItem(k) != null && menu.getItem(k).getName().equals(action.name())) {
                    return menu.getItem(k);
                }
            }
            throw new AssertionError("no entry " + action);
        });
        driver.awaitEdt(item::isShowing, "the " + menuName + " menu open");
        boolean ticked = driver.onEdt(item::isSelected);
        assertEquals(ticked, action.toggle() && driver.onEdt(() -> window.isOn(action)), action + " ticked as it is");
        driver.click(item);
        return item;
    }

    private String awaitPanel(SimpviewWindow window, String start) throws Exception {
        driver.awaitEdt(() -> window.inspectorPanel().answered() && window.inspectorPanel().text().startsWith(start),
                "the panel on " + start);
        return driver.onEdt(() -> window.inspectorPanel().text());
    }
}
