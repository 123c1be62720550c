package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.Arguments;
import simpview.scene.SceneException;
import simpview.surface.DrawingThreads;
import simpview.testing.CourseFiles;
import simpview.testing.GoldenCase;
import simpview.testing.Goldens;
import simpview.testing.ThreadCounts;

/** Every page against its golden PNG, exactly, drawn by 1, 2 and 7 threads. */
class PageGoldenTest {

    private final PageRenderer renderer = new PageRenderer();

    static Stream<Arguments> seededPages() {
        return ThreadCounts.each(GoldenCase.seededPages());
    }

    @ParameterizedTest(name = "{0} on {1} threads")
    @MethodSource("seededPages")
    void seededPagesMatchTheirGoldens(GoldenCase c, int threads) throws SceneException {
        Goldens.assertMatches(c.name(), render(c, threads));
    }

    static Stream<Arguments> ownScenePages() {
        return ThreadCounts.each(GoldenCase.ownScenePages());
    }

    @ParameterizedTest(name = "{0} on {1} threads")
    @MethodSource("ownScenePages")
    void theProjectsOwnScenesMatchTheirGoldens(GoldenCase c, int threads) throws SceneException {
        Goldens.assertMatches(c.name(), render(c, threads));
    }

    static Stream<Arguments> coursePages() {
        return ThreadCounts.each(List.of(6, 7, 8));
    }

    @ParameterizedTest(name = "page {0} on {1} threads")
    @MethodSource("coursePages")
    void theCourseScenesMatchTheirGoldens(int page, int threads) throws SceneException {
        CourseFiles.requireSimpDir();
        GoldenCase c = GoldenCase.coursePages().get(page - 6);
        Goldens.assertMatches(c.name(), render(c, threads));
    }

    /** The case's page drawn by a renderer with that many threads. */
    private static BufferedImage render(GoldenCase c, int threads) throws SceneException {
        try (DrawingThreads drawing = DrawingThreads.of(threads)) {
            return new PageRenderer(drawing).renderImage(c.page(), c.context());
        }
    }

    @Test
    void theSameSeedGivesTheSamePictureBitForBit() throws SceneException {
        for (int page = 1; page <= 3; page++) {
            PageContext context = PageContext.defaults().withSeed(99);
            BufferedImage first = renderer.renderImage(page, context);
            renderer.renderImage(4 - page, context.withSeed(5)); // something else in between
            BufferedImage second = new PageRenderer().renderImage(page, context);
            assertTrue(sameImage(first, second), "page " + page);
        }
    }

    @Test
    void anotherSeedGivesAnotherPicture() throws SceneException {
        for (int page = 1; page <= 3; page++) {
            assertFalse(sameImage(renderer.renderImage(page, PageContext.defaults().withSeed(1)),
                    renderer.renderImage(page, PageContext.defaults().withSeed(2))), "page " + page);
        }
    }

    static boolean sameImage(BufferedImage a, BufferedImage b) {
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    return false;
                }
            }
        }
        return true;
    }
}
