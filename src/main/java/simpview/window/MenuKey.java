package simpview.window;

import java.awt.GraphicsEnvironment;
import java.awt.Toolkit;
import java.awt.event.InputEvent;
import java.util.List;

/**
 * The key the menus' accelerators are held with: Ctrl, or Command on a Mac
 * ({@link Toolkit#getMenuShortcutKeyMaskEx}, Ctrl where there is no screen).
 * The menus, F1 and the status line's hints all take it from here, so the
 * words shown name the key the menus use: "Ctrl+Shift+O", or "⇧⌘O" as a
 * Mac's menus write it.
 *
 * @param mask the key's modifier mask, as {@link InputEvent} writes it
 */
record MenuKey(int mask) {

    /** The platform's menu key, as the menus are built with it. */
    static MenuKey ofPlatform() {
        return new MenuKey(GraphicsEnvironment.isHeadless() ? InputEvent.CTRL_DOWN_MASK
                : Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx());
    }

    /** True when the menu key is Command, written in a Mac's own signs (⌘, ⇧, ⌥, ⌃). */
    boolean command() {
        return mask == InputEvent.META_DOWN_MASK;
    }

    /**
     * A key with modifiers, as the window shows it: {@code modifiers} are
     * the words of {@link WindowAction}'s keys ("menu" for this key, "ctrl",
     * "shift", "alt") and {@code key} is the key's name as shown ("O", "]").
     * With Command, a combination with the menu key is written as a Mac's
     * menus write it, its signs in their order (⌃⌥⇧⌘) and no "+": "⇧⌘O";
     * any other as elsewhere, "Ctrl+Shift+]".
     */
    String shown(List<String> modifiers, String key) {
        if (command() && modifiers.contains("menu")) {
            StringBuilder text = new StringBuilder();
            for (String modifier : List.of("ctrl", "alt", "shift", "menu")) {
                if (modifiers.contains(modifier)) {
                    text.append(sign(modifier));
                }
            }
            return text.append(key).toString();
        }
        StringBuilder text = new StringBuilder();
        for (String modifier : modifiers) {
            text.append(switch (modifier) {
                case "menu", "ctrl" -> "Ctrl";
                case "shift" -> "Shift";
                case "alt" -> "Alt";
                default -> throw new IllegalStateException("unknown modifier " + modifier);
            }).append('+');
        }
        return text.append(key).toString();
    }

    private static String sign(String modifier) {
        return switch (modifier) {
            case "ctrl" -> "⌃";
            case "alt" -> "⌥";
            case "shift" -> "⇧";
            case "menu" -> "⌘";
            default -> throw new IllegalStateException("unknown modifier " + modifier);
        };
    }
}
