package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.InputEvent;
import org.junit.jupiter.api.Test;

/**
 * The status line's hints and F1 name the menus' keys by the key the menus
 * are built with: Ctrl, or Command on a Mac, whose mask is passed in here as
 * a Mac's toolkit would give it.
 */
class MenuKeyTest {

    private static final MenuKey CTRL = new MenuKey(InputEvent.CTRL_DOWN_MASK);
    private static final MenuKey COMMAND = new MenuKey(InputEvent.META_DOWN_MASK);

    @Test
    void withCommandTheMenusKeysAreWrittenAsAMacsMenusWriteThem() {
        assertEquals("⌘O", WindowAction.OPEN.keysShown(COMMAND));
        assertEquals("⇧⌘O", WindowAction.COMPARE.keysShown(COMMAND));
        assertEquals("⇧⌘C", WindowAction.COPY_CHAIN.keysShown(COMMAND));
        // the stepping keys are Ctrl's on every platform
        assertEquals("Ctrl+]", WindowAction.STEP_ON_100.keysShown(COMMAND));
        assertEquals("Ctrl+Shift+[", WindowAction.STEP_BACK_1000.keysShown(COMMAND));
        assertEquals("Alt+1", WindowAction.ASSIGNMENT_1.keysShown(COMMAND));
        assertEquals("→, Space, Page Down", WindowAction.NEXT.keysShown(COMMAND));
    }

    @Test
    void withCtrlTheyAreWrittenWithCtrl() {
        assertEquals("Ctrl+O", WindowAction.OPEN.keysShown(CTRL));
        assertEquals("Ctrl+Shift+O", WindowAction.COMPARE.keysShown(CTRL));
        assertEquals("Ctrl+Shift+]", WindowAction.STEP_ON_1000.keysShown(CTRL));
    }

    @Test
    void theHintsNameTheMenuKey() {
        String mac = StatusStrip.hints(COMMAND);
        assertTrue(mac.contains(" · ⌘O open · ⌘S save · "), mac);
        assertFalse(mac.contains("Ctrl"), mac);
        String elsewhere = StatusStrip.hints(CTRL);
        assertTrue(elsewhere.contains(" · Ctrl+O open · Ctrl+S save · "), elsewhere);
    }

    @Test
    void f1NamesTheMenuKey() {
        assertTrue(KeyHelp.rows(COMMAND).contains(new KeyHelp.Row("⌘S", WindowAction.SAVE.help())));
        assertTrue(KeyHelp.rows(COMMAND).contains(new KeyHelp.Row("Ctrl+[", WindowAction.STEP_BACK_100.help())));
        assertTrue(KeyHelp.rows(CTRL).contains(new KeyHelp.Row("Ctrl+S", WindowAction.SAVE.help())));
    }

    @Test
    void thePlatformsKeyIsTheOneTheMenusAreBuiltWith() {
        int menu = MenuKey.ofPlatform().mask();
        assertEquals(menu, WindowAction.SAVE.accelerator().getModifiers() & menu);
        assertEquals(WindowAction.SAVE.keysShown(MenuKey.ofPlatform()),
                KeyHelp.ROWS.stream().filter(r -> WindowAction.SAVE.help().equals(r.does())).findFirst().orElseThrow().input());
    }
}
