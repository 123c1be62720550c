package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.InputEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import javax.swing.KeyStroke;
import org.junit.jupiter.api.Test;

/**
 * F1, the menu bar and the README say the same: every entry of the window's
 * one table of actions is a row of the README's tables (its keys, its menu
 * entry, what it does) and of F1, and no key stroke does two things.
 */
class KeyHelpReadmeTest {

    @Test
    void everyActionIsInTheReadmeAndInF1WithItsKeysAndMenuEntry() throws Exception {
        String readme = Files.readString(Path.of("README.md")).replace("`", "");
        // the README writes the menus' keys with Ctrl, and says once that on macOS it is Command
        MenuKey ctrl = new MenuKey(InputEvent.CTRL_DOWN_MASK);
        for (WindowAction action : WindowAction.values()) {
            if (action.help() == null) {
                continue; // pages 2 to 8: the row "1 … 8" of page 1
            }
            String row = "| " + action.keysShown(ctrl) + " | " + action.label()
                    + (action == WindowAction.PAGE_1 ? " … Page 8" : "") + " | " + action.help() + " |";
            assertTrue(readme.contains(row), "the README has the row " + row);
            assertTrue(KeyHelp.rows(ctrl).contains(new KeyHelp.Row(action.keysShown(ctrl), action.help())),
                    "F1 shows " + action);
        }
        for (KeyHelp.Row gesture : KeyHelp.GESTURES) {
            assertTrue(readme.contains("| " + gesture.input() + " |"), "the README names the gesture " + gesture.input());
        }
    }

    @Test
    void noKeyStrokeDoesTwoThings() {
        Map<KeyStroke, WindowAction> seen = new HashMap<>();
        for (WindowAction action : WindowAction.values()) {
            for (KeyStroke stroke : action.strokes()) {
                WindowAction before = seen.put(stroke, action);
                assertEquals(null, before, stroke + " is both " + before + " and " + action);
            }
        }
        Set<String> labels = new HashSet<>();
        for (WindowAction action : WindowAction.values()) {
            assertTrue(labels.add(action.menu() + " " + action.label()), "one entry per label: " + action.label());
        }
    }
}
