package simpview.testing;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The course's scene files, which never come with the project: the build
 * passes the depth-cued folder as -Dsimpview.courseSimp (../shared/course-simp
 * beside the project), and the lit ones (course-simp-a3, course-simp-a4) are
 * its siblings. A test that needs them skips, saying so, when they are not
 * there; under CI=true their absence fails the test instead, so that a CI
 * without them cannot turn green by skipping.
 */
public final class CourseFiles {

    private CourseFiles() {
    }

    /** Where the course's depth-cued scenes are looked for (whether or not they are there). */
    public static Path simpDir() {
        return Path.of(System.getProperty("simpview.courseSimp", "../shared/course-simp"));
    }

    public static boolean present() {
        return Files.isRegularFile(simpDir().resolve("page6.simp"));
    }

    /** The course's scene folder; skips the test (fails it under CI=true) when it is absent. */
    public static Path requireSimpDir() {
        if (!present()) {
            absent("the course's scene files are not at " + simpDir().toAbsolutePath().normalize()
                    + " (../shared/course-simp beside the project)");
        }
        return simpDir();
    }

    /** The course folder NAME beside the depth-cued one, e.g. "course-simp-a3"; it may be absent. */
    public static Path folder(String name) {
        Path shared = simpDir().toAbsolutePath().normalize().getParent();
        return shared == null ? Path.of(name) : shared.resolve(name);
    }

    /** {@link #folder} (a folder or a file in one), when it is there; else the test skips (or fails under CI=true). */
    public static Path require(String name) {
        Path dir = folder(name);
        if (!Files.exists(dir)) {
            absent("the course's files are not at " + dir + " (../shared/" + name + " beside the project)");
        }
        return dir;
    }

    private static void absent(String why) {
        if ("true".equalsIgnoreCase(System.getenv("CI"))) {
            fail(why + ", and CI=true: they must be there on CI");
        }
        assumeTrue(false, why + ": this test needs them and is skipped");
    }
}
