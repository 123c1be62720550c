package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Every diff image of a batch has a name of its own, fixed by the table's order alone. */
class DiffNamesTest {

    @Test
    void picturesThatWouldShareADiffImageAreToldApartInTheTablesOrder() {
        DiffNames names = DiffNames.of(List.of("Page1.png", "page1.png", "s/t_page1.png", "s_t/page1.png",
                "u/page2-2.png", "u/page2.jpg", "u/page2.png"));
        assertEquals("diffs/Page1-diff.png", names.of("Page1.png", 0));
        assertEquals("diffs/page1-2-diff.png", names.of("page1.png", 0), "one file where case is ignored (a Mac)");
        assertEquals("diffs/s_t_page1-diff.png", names.of("s/t_page1.png", 0));
        assertEquals("diffs/s_t_page1-2-diff.png", names.of("s_t/page1.png", 0));
        assertEquals("diffs/s_t_page1-2-panel3-diff.png", names.of("s_t/page1.png", 3));
        assertEquals("diffs/u_page2-2-diff.png", names.of("u/page2-2.png", 0), "a picture keeps its own name");
        assertEquals("diffs/u_page2-diff.png", names.of("u/page2.jpg", 0));
        assertEquals("diffs/u_page2-3-diff.png", names.of("u/page2.png", 0), "-2 is another picture's own");
    }

    @Test
    void aPanelsNameIsNeverAnotherPicturesName() {
        DiffNames names = DiffNames.of(List.of("a1-page1.png", "a1-page1-panel2.png"));
        assertEquals("diffs/a1-page1-panel2-diff.png", names.of("a1-page1.png", 2));
        assertEquals("diffs/a1-page1-panel2-2-diff.png", names.of("a1-page1-panel2.png", 0));
    }
}
