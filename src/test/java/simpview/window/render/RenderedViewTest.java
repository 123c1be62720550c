package simpview.window.render;

import simpview.window.ErrorOverlay;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import simpview.pages.A1Rule;

public class RenderedViewTest {

    private static RenderedView of(View view) {
        return new RenderedView(view, 361, A1Rule.SPEC, null, null, List.of());
    }

    @Test
    void seededPagesShowTheirSeedInTheTitle() {
        assertEquals("simpview — page 3/8: Z-buffer — seed 361", of(new View.OfPage(3)).title());
        assertEquals("page3-seed361.png", of(new View.OfPage(3)).suggestedFileName());
    }

    @Test
    void sceneTitlesNameTheFile() {
        RenderedView scene = of(new View.OfScene(Path.of("/some/where/house.simp")));
        assertEquals("simpview — scene: house.simp", scene.title());
        assertEquals("house.png", scene.suggestedFileName());
    }

    @Test
    void otherPagesHaveNoSeed() {
        assertEquals("simpview — page 6/8: page6.simp", of(new View.OfPage(6)).title());
        assertEquals("page6.png", of(new View.OfPage(6)).suggestedFileName());
    }

    @Test
    void overlayWrapsLongLinesAndKeepsShortOnes() {
        List<String> lines = ErrorOverlay.wrap("short\nabcdefghij klmnopqrstuvwxyz0123456789", 20);
        assertEquals(List.of("short", "abcdefghij", "klmnopqrstuvwxyz0123", "456789"), lines);
    }
}
