package simpview.testing;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The course's scene folders beside the project (../shared/course-simp,
 * course-simp-a3, course-simp-a4), which the project never holds. A test that
 * needs one skips, saying why, when it is absent; under CI=true the absence
 * is a failure instead, so a CI run can never pass by skipping.
 */
public final class CourseFiles {

    private CourseFiles() {
    }

    /** The folder ../shared/NAME beside the project, e.g. "course-simp-a3"; it may be absent. */
    public static Path folder(String name) {
        String depthCued = System.getProperty("simpview.courseSimp");
        Path shared = depthCued != null ? Path.of(depthCued).getParent()
                : Goldens.projectDir().resolve("../shared").normalize();
        return shared == null ? Path.of(name) : shared.resolve(name);
    }

    /** The folder, when it is there; else the test skips (or fails under CI=true). */
    public static Path require(String name) {
        Path dir = folder(name);
        boolean present = Files.isDirectory(dir);
        if (!present && "true".equals(System.getenv("CI"))) {
            fail("the course's files are missing: " + dir.toAbsolutePath().normalize()
                    + " (CI must have ../shared beside the project)");
        }
        assumeTrue(present, "the course's files are not beside the project (" + dir.toAbsolutePath().normalize()
                + "): skipped");
        return dir;
    }
}
