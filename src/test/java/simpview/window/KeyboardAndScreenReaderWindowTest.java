package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.KeyboardFocusManager;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import javax.swing.MenuElement;
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
 * keyboard.
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
}
