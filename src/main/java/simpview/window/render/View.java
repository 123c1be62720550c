package simpview.window.render;

import java.nio.file.Path;

/** What the window can show: one of the eight pages, or a scene the user opened. */
public sealed interface View permits View.OfPage, View.OfScene {

    /** Page n, 1 to 8. */
    record OfPage(int number) implements View {
    }

    /** A scene file shown as a whole page. */
    record OfScene(Path file) implements View {
    }
}
