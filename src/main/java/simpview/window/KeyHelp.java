package simpview.window;

import java.util.ArrayList;
import java.util.List;

/**
 * Every key, menu entry and gesture of the window, for the help box (F1):
 * the gestures below, then {@link WindowAction}'s table menu by menu. The
 * README lists the same (KeyHelpReadmeTest holds them together).
 */
public final class KeyHelp {

    /** One input and what it does; a row with a null input is a heading. */
    record Row(String input, String does) {
        boolean heading() {
            return input == null;
        }
    }

    /** What the pointer does: no menu entry, no key. */
    static final List<Row> GESTURES = List.of(
            new Row("click", "next page (a click without dragging)"),
            new Row("move the pointer", "inspect a pixel: place, colour, depth, who drew it (the panel follows it)"),
            new Row("wheel", "zoom about the pointer (up to 32x)"),
            new Row("drag", "pan (scroll the page)"),
            new Row("right-drag, Shift+drag", "turn the scene about its centre"),
            new Row("Ctrl+wheel, Alt+wheel", "move the scene's view nearer or farther"),
            new Row("drop a file", "a .simp: open it (several: the first pages); a picture: compare with it; "
                    + "a folder: check its pictures"));

    /** The rows as the window shows them, its menu key named as its menus name it. */
    static final List<Row> ROWS = rows(MenuKey.ofPlatform());

    private KeyHelp() {
    }

    /** The rows with {@code menuKey}'s words for the menus' keys ("Ctrl+O", or "⌘O" on a Mac). */
    static List<Row> rows(MenuKey menuKey) {
        List<Row> rows = new ArrayList<>();
        rows.add(new Row(null, "Pointer"));
        rows.addAll(GESTURES);
        WindowAction.Menu menu = null;
        for (WindowAction action : WindowAction.values()) {
            if (action.menu() != menu) {
                menu = action.menu();
                rows.add(new Row(null, menu.title() + " menu"));
            }
            if (action.help() != null) {
                rows.add(new Row(action.keysShown(menuKey), action.help()));
            }
        }
        return List.copyOf(rows);
    }
}
