package simpview.window.render;

import java.nio.file.Path;

/** What the window can show: one of the eight pages, one of the first assignment's five, or a scene the user opened. */
public sealed interface View permits View.OfPage, View.OfAssignment1Page, View.OfScene {

    /** Page n, 1 to 8. */
    record OfPage(int number) implements View {
    }

    /** The first assignment's page n, 1 to 5 (SPEC Part 3). */
    record OfAssignment1Page(int number) implements View {
    }

    /** A scene file shown as a whole page. */
    record OfScene(Path file) implements View {
    }
}
