package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class AlternatingLineRendererTest {

    /** Lines 1, 3, 5 by the DDA, 2, 4 by Bresenham: each rising 2:1 line shows which by its tie. */
    @Test
    void theFirstLineIsTheDdasThenTheyTakeTurns() {
        AlternatingLineRenderer alternating = AlternatingLineRenderer.ddaThenBresenham();
        List<String> dda = List.of("0,0", "1,1", "2,1");
        List<String> bresenham = List.of("0,0", "1,0", "2,1");
        for (int i = 0; i < 5; i++) {
            assertEquals(i % 2 == 0 ? dda : bresenham, LineExpectations.drawn(alternating, 0, 0, 2, 1, 10), "line " + (i + 1));
        }
    }
}
