package simpview.testing;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import simpview.pages.PageContext;
import simpview.scene.simp.SceneMonitor;

/**
 * One golden image: a page rendered with a given seed and scene folder.
 * Pages 6 to 8 are the course's scenes, read from ../shared/course-simp.
 */
public record GoldenCase(String name, int page, long seed, Path simpDir) {

    public static final long[] SEEDS = {361, 2017};

    public PageContext context() {
        return new PageContext(seed, simpDir, ownSimpDir(), SceneMonitor.NONE);
    }

    public static Path ownSimpDir() {
        return Goldens.projectDir().resolve("simp");
    }

    /** The course's scene folder, or null when it is not beside the project. */
    public static Path courseSimpDir() {
        return CourseFiles.present() ? CourseFiles.simpDir() : null;
    }

    /** Pages 1 to 3 at each seed. */
    public static List<GoldenCase> seededPages() {
        List<GoldenCase> cases = new ArrayList<>();
        for (int page = 1; page <= 3; page++) {
            for (long seed : SEEDS) {
                cases.add(new GoldenCase("page" + page + "-seed" + seed, page, seed, ownSimpDir()));
            }
        }
        return cases;
    }

    /** Pages 4 and 5, the project's own scenes. */
    public static List<GoldenCase> ownScenePages() {
        return List.of(new GoldenCase("page4", 4, PageContext.DEFAULT_SEED, ownSimpDir()),
                new GoldenCase("page5", 5, PageContext.DEFAULT_SEED, ownSimpDir()));
    }

    /** Pages 6 to 8 from the course's folder (empty when it is absent). */
    public static List<GoldenCase> coursePages() {
        Path course = courseSimpDir();
        if (course == null) {
            return List.of();
        }
        List<GoldenCase> cases = new ArrayList<>();
        for (int page = 6; page <= 8; page++) {
            cases.add(new GoldenCase("page" + page, page, PageContext.DEFAULT_SEED, course));
        }
        return cases;
    }
}
