package simpview.pages;

import java.util.List;
import simpview.surface.Rgb;

/** The eight pages, in order. Page n is {@code all().get(n - 1)}. */
public final class Assignment2 {

    /** Page 5's near colour: a warm amber, so it reads differently from page 4's green. */
    public static final Rgb PAGE5_NEAR = new Rgb(1, 0.75, 0.3);

    private static final List<Page> ALL = List.of(
            MeshPage.wireframe(),
            MeshPage.filled(),
            new ZBufferPage(),
            ScenePage.own("Boxes (depth cue green)", "page4.simp", Rgb.GREEN),
            ScenePage.own("Shapes (generated)", "page5.simp", PAGE5_NEAR),
            ScenePage.course("page6.simp"),
            ScenePage.course("page7.simp"),
            ScenePage.course("page8.simp"));

    /** How many pages: eight. */
    public static final int COUNT = ALL.size();

    private Assignment2() {
    }

    public static List<Page> all() {
        return ALL;
    }

    /** Page n, 1-based. */
    public static Page page(int number) {
        if (number < 1 || number > COUNT) {
            throw new IllegalArgumentException("there is no page " + number + "; pages are 1 to " + COUNT);
        }
        return ALL.get(number - 1);
    }
}
