package simpview.scene;

import simpview.testing.DrawnScenes;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import simpview.testing.CourseFiles;
import simpview.testing.Goldens;
import simpview.testing.LitGoldens;
import simpview.testing.ThreadCounts;

/**
 * The project's own lit scenes and every page of the course's third and
 * fourth assignments against its golden PNG, exactly, drawn by 1, 2 and 7 threads.
 */
class LitGoldenTest {

    static Stream<LitGoldens.Case> own() {
        return LitGoldens.own().stream();
    }

    static Stream<Arguments> ownOnEachThreadCount() {
        return ThreadCounts.each(LitGoldens.own());
    }

    @ParameterizedTest(name = "{0} on {1} threads")
    @MethodSource("ownOnEachThreadCount")
    void theProjectsOwnLitScenesMatchTheirGoldens(LitGoldens.Case c, int threads) throws Exception {
        assertTrue(threads > 1 || DrawnScenes.isLit(c.scene()), c.scene() + " is a lit scene");
        Goldens.assertMatches(c.name(), c.render(threads));
    }

    static Stream<LitGoldens.Case> a3() {
        CourseFiles.require("course-simp-a3");
        return LitGoldens.cases("course-simp-a3", "a3", LitGoldens.A3).stream();
    }

    static Stream<LitGoldens.Case> a4() {
        CourseFiles.require("course-simp-a4");
        return LitGoldens.cases("course-simp-a4", "a4", LitGoldens.A4).stream();
    }

    static Stream<Arguments> a3OnEachThreadCount() {
        CourseFiles.require("course-simp-a3");
        return ThreadCounts.each(LitGoldens.cases("course-simp-a3", "a3", LitGoldens.A3));
    }

    static Stream<Arguments> a4OnEachThreadCount() {
        CourseFiles.require("course-simp-a4");
        return ThreadCounts.each(LitGoldens.cases("course-simp-a4", "a4", LitGoldens.A4));
    }

    @ParameterizedTest(name = "{0} on {1} threads")
    @MethodSource("a3OnEachThreadCount")
    void theThirdAssignmentsPagesMatchTheirGoldens(LitGoldens.Case c, int threads) throws Exception {
        assertTrue(threads > 1 || DrawnScenes.isLit(c.scene()), c.scene() + " is a lit scene");
        Goldens.assertMatches(c.name(), c.render(threads));
    }

    @ParameterizedTest(name = "{0} on {1} threads")
    @MethodSource("a4OnEachThreadCount")
    void theFourthAssignmentsPagesMatchTheirGoldens(LitGoldens.Case c, int threads) throws Exception {
        assertTrue(threads > 1 || DrawnScenes.isLit(c.scene()), c.scene() + " is a lit scene");
        Goldens.assertMatches(c.name(), c.render(threads));
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
