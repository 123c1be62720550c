package simpview.window;

import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.KeyStroke;

/**
 * Everything the window does on a key or a menu entry: the one table that
 * the keys, the menu bar and the key help (F1) are all built from. Each
 * entry names its menu, its label there, what it does (for F1 and the
 * README), and its keys: the first is the menu's accelerator, the rest do the
 * same; whether it turns something on and off (a ticked entry) and whether
 * it begins a group of its menu ({@link Entry}). {@code SimpviewWindow.actionOf}
 * says what each does, in a switch expression with no default: a new entry
 * does not build until it has its action; a toggle's state is read in
 * {@code SimpviewWindow.isOn}, which fails for a toggle it does not know as
 * soon as the menu bar is built.
 *
 * <p>Keys are written as {@link KeyStroke#getKeyStroke(String)} reads them;
 * "menu" stands for the platform's menu-shortcut key (Ctrl, or Command on a
 * Mac: {@link MenuKey}).
 */
public enum WindowAction {

    OPEN(Menu.FILE, "Open scene…", "open a scene as an extra view (or drop a .simp file on the window)", "menu O"),
    COMPARE(Menu.FILE, "Open picture to compare…",
            "compare the page with a picture, a PNG of yours (or drop it on the window)", "menu shift O"),
    SAVE(Menu.FILE, "Save as PNG…", "save the page as drawn as PNG, without overlays or the depth view (.png is "
            + "added to a name without one)", "menu S"),
    REDRAW(Menu.FILE, Entry.FIRST_OF_GROUP,
            "Draw again", "draw again, every file read from disk afresh (the files are also watched "
            + "and drawn again when saved)", "F5"),
    CLOSE(Menu.FILE, Entry.FIRST_OF_GROUP, "Close", "close the window", "menu W"),
    QUIT(Menu.FILE, "Quit", "quit", "menu Q"),

    ZOOM_IN(Menu.VIEW, "Zoom in", "zoom in about the middle (the wheel zooms about the pointer, up to 32x)",
            "typed +", "typed ="),
    ZOOM_OUT(Menu.VIEW, "Zoom out", "zoom out about the middle", "typed -"),
    ACTUAL_SIZE(Menu.VIEW, "1:1", "one page pixel to one screen pixel; drag to scroll the page", "Z"),
    FIT(Menu.VIEW, "Fit the window", "the page at the largest zoom that fits; the panel at 1:1 (margins "
            + "cropped) before going below 1:1, where 1-px lines are kept", "F"),
    CROP(Menu.VIEW, "Crop to the panel", "fit the 650 px panel alone, its white margins cropped", "X"),
    DEPTH_VIEW(Menu.VIEW, Entry.TOGGLE_FIRST_OF_GROUP,
            "Depth view", "the z-buffer as a picture (again: the page)", "D"),
    OWN_COLOURS(Menu.VIEW, Entry.TOGGLE,
            "Own colours", "depth-cued scenes in their vertices' own colours (white where none), without "
            + "the cue (the status line then says \"own colours\"); a lit scene, pages 1-3 and the first "
            + "assignment's pages, which have no cue, stay as they are", "C"),
    BACK_FACES(Menu.VIEW, Entry.TOGGLE,
            "Back faces", "pixels of polygons clockwise on the panel (facing away) tinted magenta, "
            + "with how many there are (again: the page)", "K"),
    OVERDRAW(Menu.VIEW, Entry.TOGGLE,
            "Overdraw", "each pixel by how many writes reached its depth test, black (none), then a "
            + "heat ramp from blue (one) through red and yellow to white (the most), the scale above the panel "
            + "(again: the page)", "V"),
    DEPTH_FAILURES(Menu.VIEW, Entry.TOGGLE,
            "Depth-test failures", "each pixel by how many writes lost its depth test, with the "
            + "scale (again: the page)", "shift V"),
    CULLED(Menu.VIEW, Entry.TOGGLE,
            "Culled and clipped-away outlines", "outline the primitives culled (every vertex outside one "
            + "plane of the view) and those clipped away whole, as projected, with a legend (again: off)", "U"),
    WIRE(Menu.VIEW, Entry.TOGGLE,
            "Wire over fill", "every primitive's edges drawn over the page, with a legend (again: off)",
            "W"),
    COMPARE_FLIP(Menu.VIEW, Entry.FIRST_OF_GROUP,
            "Flip ours / theirs", "while comparing: flip between our page and the picture", "B"),
    COMPARE_HEAT(Menu.VIEW, Entry.TOGGLE,
            "Heat map", "while comparing: where they differ, with its legend (again: our page)",
            "H"),
    COMPARE_STOP(Menu.VIEW, "Stop comparing", "stop comparing", "BACK_SPACE"),
    HIDE_ERROR(Menu.VIEW, Entry.TOGGLE_FIRST_OF_GROUP,
            "Hide the error", "hide or show a scene's error over the page", "E"),
    UNTURN(Menu.VIEW, "Unturn", "the scene unturned, and at its own distance, again", "O"),

    NEXT(Menu.PAGE, "Next page", "next page (after the last comes the first)", "RIGHT", "SPACE", "PAGE_DOWN",
            "KP_RIGHT"),
    PREVIOUS(Menu.PAGE, "Previous page", "previous page", "LEFT", "PAGE_UP", "KP_LEFT"),
    FIRST(Menu.PAGE, "First page", "the assignment's first page", "HOME"),
    LAST(Menu.PAGE, "Last page", "the assignment's last page", "END"),
    PAGE_1(Menu.PAGE, Entry.FIRST_OF_GROUP,
            "Page 1", "that page of the assignment shown (A1: 1 to 5; A3, A4: 1 to 8 of theirs)", "1",
            "NUMPAD1"),
    PAGE_2(Menu.PAGE, "Page 2", null, "2", "NUMPAD2"),
    PAGE_3(Menu.PAGE, "Page 3", null, "3", "NUMPAD3"),
    PAGE_4(Menu.PAGE, "Page 4", null, "4", "NUMPAD4"),
    PAGE_5(Menu.PAGE, "Page 5", null, "5", "NUMPAD5"),
    PAGE_6(Menu.PAGE, "Page 6", null, "6", "NUMPAD6"),
    PAGE_7(Menu.PAGE, "Page 7", null, "7", "NUMPAD7"),
    PAGE_8(Menu.PAGE, "Page 8", null, "8", "NUMPAD8"),
    ASSIGNMENT(Menu.PAGE, Entry.FIRST_OF_GROUP,
            "Switch assignment", "switch between the first assignment's five pages (A1) and the "
            + "eight pages (A2); from A3 or A4, back to the eight", "A"),
    ASSIGNMENT_1(Menu.PAGE, "Assignment 1 (five pages)", "the first assignment's pages, where they were left",
            "alt 1"),
    ASSIGNMENT_2(Menu.PAGE, "Assignment 2 (eight pages)", "the eight pages (and the scenes named at start), where "
            + "they were left", "alt 2"),
    ASSIGNMENT_3(Menu.PAGE, "Assignment 3 (the course's scenes)", "the third assignment's pages: the course's "
            + "page scenes in course-simp-a3 beside the pages' folder, where they were left", "alt 3"),
    ASSIGNMENT_4(Menu.PAGE, "Assignment 4 (the course's scenes)", "the fourth assignment's pages, from "
            + "course-simp-a4", "alt 4"),
    A1_RULE(Menu.PAGE, Entry.TOGGLE,
            "The course's pictures' rule (A1)", "the first assignment's Bresenham panels and fills by "
            + "the rule the course's pictures show (Bresenham on the ends' given minor coordinates, rows at integer "
            + "y), not SPEC's (again: SPEC's)", "shift R"),
    SEED(Menu.PAGE, Entry.FIRST_OF_GROUP, "New seed", "a new seed for the random pages (A2 1-3, A1 3-5)", "R"),
    CANCEL(Menu.PAGE, "Stop drawing", "stop drawing a long scene (the page on screen stays); with this help "
            + "shown, hide it first", "ESCAPE"),

    INSPECTOR(Menu.INSTRUMENTS, Entry.TOGGLE,
            "Inspector panel", "the panel beside the page: the pixel's history, its colour "
            + "explained, its primitive's vertices; it follows the pointer, or the pinned pixel", "I"),
    PIN(Menu.INSTRUMENTS, Entry.TOGGLE, "Pin the pixel", "pin the inspected pixel (again: unpin)", "P"),
    GO_TO_PIXEL(Menu.INSTRUMENTS, "Go to pixel…", "go to a pixel by its panel coordinates (x right, y up; on the "
            + "first assignment's pages, the page's) and pin it", "shift G"),
    COPY(Menu.INSTRUMENTS, "Copy", "copy the text selected in the inspector panel, else the status line's "
            + "inspector", "menu C"),
    COPY_CHAIN(Menu.INSTRUMENTS, "Copy the pixel's include chain", "copy where the inspected pixel came from: "
            + "with the inspector panel (I) open, file:line by file:line through the includes (each part is also a "
            + "link in the panel: a click copies it); without it, its primitive's own file:line", "menu shift C"),
    STEP_ON(Menu.INSTRUMENTS, Entry.FIRST_OF_GROUP,
            "Step on", "step the drawing one primitive on (A1: one more line or triangle of "
            + "every panel)", "CLOSE_BRACKET"),
    STEP_BACK(Menu.INSTRUMENTS, "Step back", "one primitive back", "OPEN_BRACKET"),
    STEP_ON_10(Menu.INSTRUMENTS, "Step on 10", "ten primitives on", "shift CLOSE_BRACKET"),
    STEP_BACK_10(Menu.INSTRUMENTS, "Step back 10", "ten primitives back", "shift OPEN_BRACKET"),
    STEP_ON_100(Menu.INSTRUMENTS, "Step on 100", "a hundred primitives on", "ctrl CLOSE_BRACKET"),
    STEP_BACK_100(Menu.INSTRUMENTS, "Step back 100", "a hundred primitives back", "ctrl OPEN_BRACKET"),
    STEP_ON_1000(Menu.INSTRUMENTS, "Step on 1000", "a thousand primitives on", "ctrl shift CLOSE_BRACKET"),
    STEP_BACK_1000(Menu.INSTRUMENTS, "Step back 1000", "a thousand primitives back", "ctrl shift OPEN_BRACKET"),
    STEP_OFF(Menu.INSTRUMENTS, "Whole picture", "the whole picture again (stepping off)", "BACK_SLASH"),
    GO_TO_PRIMITIVE(Menu.INSTRUMENTS, Entry.FIRST_OF_GROUP,
            "Go to primitive…", "step the drawing to primitive N (asks for N)", "G"),
    STEP_TO_OWNER(Menu.INSTRUMENTS, "Step to the pixel's primitive", "step to the primitive that draws the pixel "
            + "under the pointer (or the pinned one) in the whole picture, from any step", "J"),

    HELP(Menu.HELP, Entry.TOGGLE,
            "Keys and gestures", "these keys, menu entries and gestures over the window (again, Escape or a click: "
            + "hide them)",
            "F1");

    /** The menus of the menu bar, in order, with their mnemonics. */
    public enum Menu {
        FILE("File", KeyEvent.VK_F), VIEW("View", KeyEvent.VK_V), PAGE("Page", KeyEvent.VK_P),
        INSTRUMENTS("Instruments", KeyEvent.VK_I), HELP("Help", KeyEvent.VK_H);

        private final String title;
        private final int mnemonic;

        Menu(String title, int mnemonic) {
            this.title = title;
            this.mnemonic = mnemonic;
        }

        public String title() {
            return title;
        }

        public int mnemonic() {
            return mnemonic;
        }
    }

    /** How an entry stands in its menu, when not as a plain entry in the group above it. */
    enum Entry {
        /** A plain entry that begins a group: a line above it. */
        FIRST_OF_GROUP(false, true),
        /** It turns something on and off: ticked in the menu while on ({@code SimpviewWindow.isOn}). */
        TOGGLE(true, false),
        /** Both. */
        TOGGLE_FIRST_OF_GROUP(true, true);

        private final boolean toggle;
        private final boolean firstOfGroup;

        Entry(boolean toggle, boolean firstOfGroup) {
            this.toggle = toggle;
            this.firstOfGroup = firstOfGroup;
        }
    }

    private final Menu menu;
    private final boolean toggle;
    private final boolean firstOfGroup;
    private final String label;
    private final String help;
    private final List<String> keys;

    /** A plain entry in the group above it. */
    WindowAction(Menu menu, String label, String help, String... keys) {
        this(menu, null, label, help, keys);
    }

    WindowAction(Menu menu, Entry entry, String label, String help, String... keys) {
        this.menu = menu;
        this.toggle = entry != null && entry.toggle;
        this.firstOfGroup = entry != null && entry.firstOfGroup;
        this.label = label;
        this.help = help;
        this.keys = List.of(keys);
    }

    public Menu menu() {
        return menu;
    }

    /** True when it turns something on and off: a menu entry that is ticked while it is on. */
    public boolean toggle() {
        return toggle;
    }

    /** True when its menu has a line above it: it begins a group. */
    public boolean firstOfGroup() {
        return firstOfGroup;
    }

    public String label() {
        return label;
    }

    /** What it does, for F1 and the README; null for the pages 2 to 8, which the row of page 1 covers. */
    public String help() {
        return help;
    }

    /** Its key strokes, the accelerator first. */
    public List<KeyStroke> strokes() {
        List<KeyStroke> strokes = new ArrayList<>();
        for (String key : keys) {
            strokes.add(stroke(key));
        }
        return strokes;
    }

    /** The menu entry's accelerator. */
    public KeyStroke accelerator() {
        return stroke(keys.get(0));
    }

    private static KeyStroke stroke(String key) {
        KeyStroke stroke;
        if (key.startsWith("menu ")) {
            KeyStroke rest = KeyStroke.getKeyStroke(key.substring("menu ".length()));
            stroke = KeyStroke.getKeyStroke(rest.getKeyCode(), rest.getModifiers() | MenuKey.ofPlatform().mask());
        } else {
            stroke = KeyStroke.getKeyStroke(key);
        }
        if (stroke == null) {
            throw new IllegalStateException("not a key stroke: " + key);
        }
        return stroke;
    }

    /**
     * Its keys as F1 and the README show them, with {@code menuKey} named as
     * the menus name it: "Ctrl+Shift+O" (on a Mac "⇧⌘O"), "→, Space, Page
     * Down" (the keypad's copies left out); the pages' row "1 … 8".
     */
    String keysShown(MenuKey menuKey) {
        if (this == PAGE_1) {
            return "1 … 8";
        }
        List<String> shown = new ArrayList<>();
        for (String key : keys) {
            if (!key.startsWith("KP_") && !key.startsWith("NUMPAD")) {
                shown.add(describe(key, menuKey));
            }
        }
        return String.join(", ", shown);
    }

    private static String describe(String key, MenuKey menuKey) {
        if (key.startsWith("typed ")) {
            return key.substring("typed ".length());
        }
        List<String> words = List.of(key.split(" "));
        String last = words.get(words.size() - 1);
        String shown = switch (last) {
            case "CLOSE_BRACKET" -> "]";
            case "OPEN_BRACKET" -> "[";
            case "BACK_SLASH" -> "\\";
            case "RIGHT" -> "→";
            case "LEFT" -> "←";
            case "SPACE" -> "Space";
            case "PAGE_DOWN" -> "Page Down";
            case "PAGE_UP" -> "Page Up";
            case "HOME" -> "Home";
            case "END" -> "End";
            case "ESCAPE" -> "Escape";
            case "BACK_SPACE" -> "Backspace";
            default -> last.length() == 1 ? last : last.charAt(0) + last.substring(1).toLowerCase(Locale.ROOT);
        };
        return menuKey.shown(words.subList(0, words.size() - 1), shown);
    }
}
