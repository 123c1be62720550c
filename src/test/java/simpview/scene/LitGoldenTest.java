package simpview.scene;

import simpview.testing.DrawnScenes;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import simpview.testing.CourseFiles;
import simpview.testing.Goldens;
import simpview.testing.LitGoldens;

/** The project's own lit scenes and every page of the course's third and fourth assignments against its golden PNG, exactly. */
class LitGoldenTest {

    static Stream<LitGoldens.Case> own() {
        return LitGoldens.own().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("own")
    void theProjectsOwnLitScenesMatchTheirGoldens(LitGoldens.Case c) throws Exception {
        assertTrue(DrawnScenes.isLit(c.scene()), c.scene() + " is a lit scene");
        Goldens.assertMatches(c.name(), c.render());
    }

    static Stream<LitGoldens.Case> a3() {
        CourseFiles.require("course-simp-a3");
        return LitGoldens.cases("course-simp-a3", "a3", LitGoldens.A3).stream();
    }

    static Stream<LitGoldens.Case> a4() {
        CourseFiles.require("course-simp-a4");
        return LitGoldens.cases("course-simp-a4", "a4", LitGoldens.A4).stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("a3")
    void theThirdAssignmentsPagesMatchTheirGoldens(LitGoldens.Case c) throws Exception {
        assertTrue(DrawnScenes.isLit(c.scene()), c.scene() + " is a lit scene");
        Goldens.assertMatches(c.name(), c.render());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("a4")
    void theFourthAssignmentsPagesMatchTheirGoldens(LitGoldens.Case c) throws Exception {
        assertTrue(DrawnScenes.isLit(c.scene()), c.scene() + " is a lit scene");
        Goldens.assertMatches(c.name(), c.render());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource({"own", "a3"})
    void aRedrawIsTheSamePictureBitForBit(LitGoldens.Case c) throws Exception {
        BufferedImage first = c.render();
        BufferedImage second = c.render();
        int differing = 0;
        for (int y = 0; y < first.getHeight(); y++) {
            for (int x = 0; x < first.getWidth(); x++) {
                differing += first.getRGB(x, y) == second.getRGB(x, y) ? 0 : 1;
            }
        }
        assertEquals(0, differing, c.name());
    }
}
