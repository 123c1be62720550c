package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.awt.KeyboardFocusManager;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import javax.accessibility.AccessibleContext;
import javax.swing.AbstractButton;
import javax.swing.JMenuItem;
import javax.swing.JProgressBar;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.MenuElement;
import javax.swing.JScrollBar;
import javax.swing.MenuSelectionManager;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import simpview.scene.simp.SceneDrawer;
import simpview.window.render.View;

/**
 * The window for someone who works by keyboard, or with a screen reader,
 * under Xvfb (no window manager, so nothing gives the keys back but the
 * window itself): a question's dialog opens with the keys in its field and
 * gives them back to the page on Enter or Escape; the menus open and work by
 * keyboard; every part of the window has words a screen reader can say.
 */
public class KeyboardAndScreenReaderWindowTest extends WindowTestCase {

    @Test
    void goToPixelsDialogGivesTheKeysBackToThePageOnEscapeAndOnEnter() throws Exception {
        Path scene = dir.resolve("tri.simp");
        Files.writeString(scene, "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        SimpviewWindow window = openWindowOn(scene);

        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_G);
        JTextField field = awaitAnswerField();
        assertTrue(driver.onEdt(() -> field.getAccessibleContext().getAccessibleName()).startsWith("Go to the panel's pixel"),
                "the field is named by its question");
        driver.pressToClose(KeyEvent.VK_ESCAPE, driver.onEdt(() -> SwingUtilities.getWindowAncestor(field)));
        driver.awaitEdt(() -> window.frame().isFocused(), "the page to have the keys again after Escape");
        driver.press(KeyEvent.VK_D);
        driver.awaitEdt(() -> window.isOn(WindowAction.DEPTH_VIEW), "D to show the depth view");

        driver.pressWith(KeyEvent.VK_SHIFT, KeyEvent.VK_G);
        JTextField again = awaitAnswerField();
        for (int key : new int[] {KeyEvent.VK_3, KeyEvent.VK_2, KeyEvent.VK_5, KeyEvent.VK_COMMA, KeyEvent.VK_3,
                KeyEvent.VK_3, KeyEvent.VK_0}) {
            driver.robot().keyPress(key);
            driver.robot().keyRelease(key);
        }
        driver.awaitEdt(() -> again.getText().equals("325,330"), "the pixel typed");
        driver.pressToClose(KeyEvent.VK_ENTER, driver.onEdt(() -> SwingUtilities.getWindowAncestor(again)));
        driver.awaitEdt(() -> window.status().messageText().startsWith("Pinned panel pixel (325, 330)"), "the pixel pinned");
        driver.awaitEdt(() -> window.frame().isFocused(), "the page to have the keys again after Enter");
        driver.press(KeyEvent.VK_D);
        driver.awaitEdt(() -> !window.isOn(WindowAction.DEPTH_VIEW), "D to show the page again");
    }

    @Test
    void aMenuOpensByItsMnemonicAndItsEntriesWorkByArrowsAndEnter() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), SceneDrawer.SIMP);
        driver.focusByClicking(new View.OfPage(2));
        driver.pressWith(KeyEvent.VK_ALT, KeyEvent.VK_P);
        driver.awaitEdt(() -> selected() != null, "Alt+P to open the Page menu");
        // down the Page menu to "Next page", its first entry
        for (int k = 0; k < 3 && !"NEXT".equals(driver.onEdt(this::selected)); k++) {
            driver.press(KeyEvent.VK_DOWN);
        }
        assertEquals("NEXT", driver.onEdt(this::selected), "the arrows reach Next page");
        driver.press(KeyEvent.VK_ENTER);
        driver.awaitShown(new View.OfPage(3));
        driver.awaitEdt(() -> MenuSelectionManager.defaultManager().getSelectedPath().length == 0, "the menu closed");

        // the keys are the page's again
        driver.press(KeyEvent.VK_RIGHT);
        driver.awaitShown(new View.OfPage(4));
    }

    /** The name of the menu entry armed in the open menu, or the menu's own when none is; null when none is open. */
    private String selected() {
        MenuElement[] path = MenuSelectionManager.defaultManager().getSelectedPath();
        for (int k = path.length - 1; k >= 0; k--) {
            if (path[k] instanceof JMenuItem item) {
                return item.getName();
            }
        }
        return null;
    }

    private JTextField awaitAnswerField() throws Exception {
        driver.awaitEdt(() -> KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner() instanceof JTextField,
                "the dialog with the keys in its field");
        return driver.onEdt(() -> (JTextField) KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner());
    }

    @Test
    void everyPartAScreenReaderMeetsHasWordsToSay() throws Exception {
        Path scene = dir.resolve("tri.simp");
        Files.writeString(scene, "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        SimpviewWindow window = openWindowOn(scene);
        driver.press(KeyEvent.VK_I); // the inspector panel shown
        driver.press(KeyEvent.VK_W); // wire over fill: its legend in the menu bar
        driver.awaitEdt(() -> window.inspectorPanel().component().isShowing() && window.legendStrip().isShowing(),
                "the inspector panel and the wire's legend");
        List<String> unnamed = driver.onEdt(() -> {
            List<String> missing = new ArrayList<>();
            unnamed(window.frame().getRootPane(), missing);
            return missing;
        });
        assertEquals(List.of(), unnamed, "parts a screen reader finds nothing to say of");

        AccessibleContext page = driver.onEdt(() -> window.pageView().getAccessibleContext());
        assertEquals("scene: tri.simp", driver.onEdt(page::getAccessibleName));
        assertTrue(driver.onEdt(page::getAccessibleDescription).startsWith("750 by 750 page, its 650 by 650 panel, at "),
                driver.onEdt(page::getAccessibleDescription));
        AccessibleContext legend = driver.onEdt(() -> window.legendStrip().getAccessibleContext());
        assertTrue(driver.onEdt(legend::getAccessibleDescription).startsWith("wire over fill: "),
                driver.onEdt(legend::getAccessibleDescription));
        driver.press(KeyEvent.VK_RIGHT); // from the scene, on from page 2, where the pages were left
        driver.awaitShown(new View.OfPage(3));
        driver.awaitEdt(() -> page.getAccessibleName().startsWith("page 3/8: "), "the page's name to follow the page");
    }

    /**
     * Collects the parts of the window below {@code part} that a screen reader would name nothing: a part with
     * no accessible context, and a control, text, progress bar or drawn component with no name.
     */
    private static void unnamed(Component part, List<String> missing) {
        AccessibleContext context = part.getAccessibleContext();
        // a scroll bar's arrow buttons are the scroll bar's, which says what it is
        boolean control = part instanceof AbstractButton || part instanceof JProgressBar || part instanceof JTextArea
                || part.getClass().getPackageName().equals("simpview.window");
        if (context == null) {
            missing.add(part.getClass().getSimpleName() + " " + part.getName() + " (no accessible context)");
        } else if (control && part.isShowing()
                && (context.getAccessibleName() == null || context.getAccessibleName().isBlank())) {
            missing.add(part.getClass().getSimpleName() + " " + part.getName());
        }
        if (part instanceof Container container && !(part instanceof JScrollBar)) {
            for (Component child : container.getComponents()) {
                unnamed(child, missing);
            }
        }
    }
}
