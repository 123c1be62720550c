package simpview.reference;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Where the course's files are: ../shared beside the project (the build
 * passes ../shared/course-simp as simpview.courseSimp). They are never
 * copied into the project; when they are absent a test skips, saying why,
 * except under CI=true, where their absence is a failure.
 */
final class CourseFiles {

    private CourseFiles() {
    }

    static Path shared() {
        String courseSimp = System.getProperty("simpview.courseSimp");
        return courseSimp != null ? Path.of(courseSimp).toAbsolutePath().getParent() : Path.of("../shared");
    }

    /** The folder under ../shared, or a skip (a failure under CI=true) when it is absent. */
    static Path require(String folder) {
        Path dir = shared().resolve(folder);
        if (!Files.isDirectory(dir)) {
            String why = "the course's files are not beside the project: no " + dir;
            if ("true".equals(System.getenv("CI"))) {
                fail(why + " (under CI=true they must be there)");
            }
            assumeTrue(false, why + "; nothing to compare");
        }
        return dir;
    }
}
