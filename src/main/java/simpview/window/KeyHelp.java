package simpview.window;

import java.util.List;

/** Every key and gesture of the window, for the help box (F1); the README lists the same. */
public final class KeyHelp {

    /** One input and what it does. */
    record Row(String input, String does) {
    }

    static final List<Row> ROWS = List.of(
            new Row("click, →, Space, Page Down", "next page (after 8 comes 1)"),
            new Row("←, Page Up / Home, End / 1…8", "previous page / page 1, page 8 / that page"),
            new Row("A", "switch assignment: the first's five pages (A1) / the eight pages (A2)"),
            new Row("R", "new seed for the random pages (A2 1–3, A1 3–5)"),
            new Row("wheel, + / -", "zoom about the pointer (up to 32x) / in, out"),
            new Row("drag", "pan"),
            new Row("F / Z", "fit the window / 1:1"),
            new Row("move the pointer", "inspect a pixel: place, colour, depth, who drew it"),
            new Row("P", "pin the inspected pixel (again: unpin); Ctrl+C copies it"),
            new Row("D", "depth view: the z-buffer as a picture (again: the page)"),
            new Row("C", "own colours: a scene's vertex colours without depth cue"),
            new Row("] / [ · Shift+] / Shift+[ · \\", "step the drawing one / ten primitives (A1: lines or triangles, every panel) · all"),
            new Row("Ctrl+] / Ctrl+[ · Ctrl+Shift+] / Ctrl+Shift+[", "step a hundred / a thousand primitives"),
            new Row("G / J", "go to primitive N / to the one that drew the pixel under the pointer"),
            new Row("I", "inspector panel: the pinned pixel's history, colour explained, vertices"),
            new Row("K", "back faces: pixels of clockwise polygons tinted magenta (again: the page)"),
            new Row("V / Shift+V", "overdraw / depth-test failures per pixel, with the scale (again: the page)"),
            new Row("right-drag, Shift+drag / O", "turn the scene about its centre / back"),
            new Row("Ctrl+wheel, Alt+wheel", "move the scene's view nearer or farther"),
            new Row("F5", "draw again (files are also watched and redrawn on save)"),
            new Row("H", "hide or show a scene error"),
            new Row("Ctrl+O, drop a file", "open a scene"),
            new Row("Ctrl+S", "save what is shown as PNG"),
            new Row("Escape", "stop drawing a long scene"),
            new Row("Ctrl+Q, Ctrl+W", "quit"),
            new Row("F1", "this help (again: hide it)"));

    private KeyHelp() {
    }
}
