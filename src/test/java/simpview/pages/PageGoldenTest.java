package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.scene.SceneException;
import simpview.testing.CourseFiles;
import simpview.testing.GoldenCase;
import simpview.testing.Goldens;

/** Every page against its golden PNG, exactly. */
class PageGoldenTest {

    private final PageRenderer renderer = new PageRenderer();

    static Stream<GoldenCase> seededPages() {
        return GoldenCase.seededPages().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("seededPages")
    void seededPagesMatchTheirGoldens(GoldenCase c) throws SceneException {
        Goldens.assertMatches(c.name(), renderer.renderImage(c.page(), c.context()));
    }

    static Stream<GoldenCase> ownScenePages() {
        return GoldenCase.ownScenePages().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("ownScenePages")
    void theProjectsOwnScenesMatchTheirGoldens(GoldenCase c) throws SceneException {
        Goldens.assertMatches(c.name(), renderer.renderImage(c.page(), c.context()));
    }

    @ParameterizedTest(name = "page {0}")
    @ValueSource(ints = {6, 7, 8})
    void theCourseScenesMatchTheirGoldens(int page) throws SceneException {
        CourseFiles.requireSimpDir();
        GoldenCase c = GoldenCase.coursePages().get(page - 6);
        Goldens.assertMatches(c.name(), renderer.renderImage(c.page(), c.context()));
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
