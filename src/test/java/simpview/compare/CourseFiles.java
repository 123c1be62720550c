package simpview.compare;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The course's files beside the project (../shared): its scenes and its own
 * pictures. Never copied into the project. A test that needs them skips when
 * they are absent, except under CI=true, where their absence fails.
 */
public final class CourseFiles {

    private CourseFiles() {
    }

    /** A path under ../shared, relative to the project. */
    public static Path shared(String relative) {
        Path project = Path.of(System.getProperty("simpview.projectDir", "."));
        return project.resolve("..").resolve("shared").resolve(relative).normalize();
    }

    /** The file or folder, once it is known to be there. */
    public static Path require(String relative) {
        Path path = shared(relative);
        if (!Files.exists(path)) {
            String why = path + " is not beside the project: the course's files are needed to compare with them";
            if ("true".equalsIgnoreCase(System.getenv("CI"))) {
                fail(why + " (CI=true: they must be there)");
            }
            assumeTrue(false, why);
        }
        return path;
    }
}
