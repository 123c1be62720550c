package simpview.window;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import simpview.pages.SceneList;

/**
 * The third or the fourth assignment's pages: the course's scenes of that
 * assignment (the .simp files named like a page, "pageA.simp",
 * "page-b2.simp", "tomsPageJ.simp", in their natural order; the scenes they
 * include, "cube.simp", are not pages) in the folder beside the course's
 * pages, course-simp-a3 or course-simp-a4. Where the window is among them.
 */
final class CoursePageSet {

    private final int assignment;
    private final List<Path> pages;
    private int at;

    private CoursePageSet(int assignment, List<Path> pages) {
        this.assignment = assignment;
        this.pages = List.copyOf(pages);
    }

    /** Where the assignment's scenes are looked for: beside the folder of the second's pages. */
    static Path folder(Path simpDir, int assignment) {
        return simpDir.toAbsolutePath().resolveSibling("course-simp-a" + assignment);
    }

    /** The set of assignment 3 or 4 found beside {@code simpDir}, or null when its folder has no page. */
    static CoursePageSet of(Path simpDir, int assignment) {
        Path folder = folder(simpDir, assignment);
        if (!Files.isDirectory(folder)) {
            return null;
        }
        List<Path> pages = SceneList.folder(folder).stream()
                .filter(file -> file.getFileName().toString().toLowerCase(Locale.ROOT).contains("page")).toList();
        return pages.isEmpty() ? null : new CoursePageSet(assignment, pages);
    }

    int assignment() {
        return assignment;
    }

    int size() {
        return pages.size();
    }

    /** The page on show, 1-based. */
    int number() {
        return at + 1;
    }

    Path current() {
        return pages.get(at);
    }

    Path next() {
        at = (at + 1) % pages.size();
        return current();
    }

    Path previous() {
        at = (at + pages.size() - 1) % pages.size();
        return current();
    }

    Path first() {
        at = 0;
        return current();
    }

    Path last() {
        at = pages.size() - 1;
        return current();
    }

    /** Page n (1-based), or null when there is none. */
    Path jump(int n) {
        if (n < 1 || n > pages.size()) {
            return null;
        }
        at = n - 1;
        return current();
    }

    /** "assignment 3, page 2/10: pageB.simp" */
    String describe() {
        return "assignment " + assignment + ", page " + number() + "/" + size() + ": " + current().getFileName();
    }
}
