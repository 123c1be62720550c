package simpview.stage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.surface.DiscardingDrawable;

/**
 * The primitive kinds are ints (they travel in number arrays), so the
 * compiler does not see a kind without its case in {@link Painter#draw}:
 * this draws every kind and checks each reaches its own renderer.
 */
class PainterTest {

    @Test
    void everyKindIsDrawnByItsOwnRenderer() {
        List<String> drawn = new ArrayList<>();
        Painter painter = new Painter(new DiscardingDrawable(),
                (a, b, d) -> drawn.add("line"),
                (a, b, c, d) -> drawn.add("filled"),
                (a, b, c, d) -> drawn.add("wire"));
        double[] p = new double[Painter.STRIDE];
        for (int i = 0; i < 3; i++) {
            p[i * Vertex.NUMBERS + Vertex.X] = i;
        }
        painter.draw(Painter.LINE, p, 0);
        painter.draw(Painter.FILLED, p, 0);
        painter.draw(Painter.WIRE, p, 0);
        assertEquals(List.of("line", "filled", "wire"), drawn);
    }

    @Test
    void aKindWithoutItsCaseFails() {
        Painter painter = new Painter(new DiscardingDrawable(), (a, b, d) -> { }, (a, b, c, d) -> { },
                (a, b, c, d) -> { });
        int unknown = Math.max(Painter.LINE, Math.max(Painter.FILLED, Painter.WIRE)) + 1;
        assertThrows(AssertionError.class, () -> painter.draw(unknown, new double[Painter.STRIDE], 0));
    }
}
