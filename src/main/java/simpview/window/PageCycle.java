package simpview.window;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import simpview.pages.Assignment1;
import simpview.pages.PageStepper;
import simpview.window.render.View;

/**
 * Where the window is among the pages its keys step through: the eight pages
 * (with the scenes named at start), the first assignment's five pages, or the
 * third or fourth assignment's pages, each set kept where it was left. A move
 * hands the view it comes to to {@code goTo}, which leaves the view on screen
 * and draws the new one; a move that has nowhere to go says why on the status
 * line. All methods run on the EDT.
 */
final class PageCycle {

    /** The place among the eight pages and the scenes before them (named at start, or dropped since). */
    private PageStepper stepper;
    /** The first assignment's page on show (1 to 5), or 0 while the window steps through the eight pages and scenes. */
    private int assignment1Page;
    /** The first assignment's page last shown (1 to 5): where Alt+1 and A come back to. */
    private int lastAssignment1Page = 1;
    /** The third or fourth assignment's pages while they are on show, else null; each kept where it was left. */
    private CoursePageSet coursePages;
    private final Map<Integer, CoursePageSet> courseSets = new HashMap<>();
    /** The scenes that are the first pages: those named at start, until several are dropped in their place. */
    private List<Path> sceneList;
    /** The course's pages' folder: the third and fourth assignments' are beside it. */
    private final Path simpDir;
    /** Says where a move has nowhere to go. */
    private final StatusStrip status;
    /** Leaves the view on screen and draws the one a move comes to. */
    private final Consumer<View> goTo;

    /** The cycle through the eight pages and {@code sceneList}, the course's pages being in {@code simpDir}. */
    PageCycle(List<Path> sceneList, Path simpDir, StatusStrip status, Consumer<View> goTo) {
        this.stepper = new PageStepper(sceneList.size());
        this.sceneList = sceneList;
        this.simpDir = simpDir;
        this.status = status;
        this.goTo = goTo;
    }

    /** The view at the place among the eight pages and scenes where the window is (or was last). */
    View current() {
        return viewAt(stepper.current());
    }

    /**
     * The third or fourth assignment's pages (Alt+3, Alt+4), where they were
     * left: the course's scenes beside its pages' folder. The keys that step
     * through pages step through them until another assignment is chosen.
     */
    void showCoursePages(int assignment) {
        CoursePageSet set = courseSets.computeIfAbsent(assignment, n -> CoursePageSet.of(simpDir, n));
        if (set == null) {
            courseSets.remove(assignment);
            status.say("No pages of assignment " + assignment + " in " + CoursePageSet.folder(simpDir, assignment)
                    + ": its scenes are looked for beside the course's pages.");
            return;
        }
        showCoursePage(set, set.current());
    }

    private void showCoursePage(CoursePageSet set, Path page) {
        assignment1Page = 0;
        coursePages = set;
        goTo.accept(new View.OfScene(page));
    }

    /** The next page of the assignment on show (after its last comes its first). */
    void next() {
        if (coursePages != null) {
            showCoursePage(coursePages, coursePages.next());
            return;
        }
        if (assignment1Page > 0) {
            showAssignment1(assignment1Page % Assignment1.COUNT + 1);
        } else {
            stepTo(stepper.next());
        }
    }

    void previous() {
        if (coursePages != null) {
            showCoursePage(coursePages, coursePages.previous());
            return;
        }
        if (assignment1Page > 0) {
            showAssignment1((assignment1Page + Assignment1.COUNT - 2) % Assignment1.COUNT + 1);
        } else {
            stepTo(stepper.previous());
        }
    }

    /** The first or the last place of the assignment on show. */
    void end(boolean first) {
        if (coursePages != null) {
            showCoursePage(coursePages, first ? coursePages.first() : coursePages.last());
            return;
        }
        if (assignment1Page > 0) {
            showAssignment1(first ? 1 : Assignment1.COUNT);
        } else {
            stepTo(first ? stepper.first() : stepper.last());
        }
    }

    /** Page n of the assignment on show. */
    void jump(int n) {
        if (coursePages != null) {
            Path page = coursePages.jump(n);
            if (page == null) {
                status.say("Assignment " + coursePages.assignment() + " has pages 1 to " + coursePages.size()
                        + " (Page Down steps on to the rest); Alt+2 goes back to the eight pages.");
            } else {
                showCoursePage(coursePages, page);
            }
            return;
        }
        if (assignment1Page == 0) {
            stepTo(stepper.jump(n));
        } else if (n <= Assignment1.COUNT) {
            showAssignment1(n);
        } else {
            status.say("The first assignment has pages 1 to " + Assignment1.COUNT + "; A switches to the eight pages.");
        }
    }

    /** A: from the eight pages (and scenes) to the first assignment's five pages and back, each where it was left. */
    void switchAssignment() {
        if (coursePages != null || assignment1Page > 0) {
            stepTo(stepper.current());
        } else {
            showAssignment1(lastAssignment1Page);
        }
    }

    /** Alt+1: the first assignment's pages where they were left, unless they are on show. */
    void firstAssignment() {
        if (assignment1Page == 0) {
            coursePages = null;
            switchAssignment();
        }
    }

    /** Alt+2: the eight pages (and scenes) where they were left, unless they are on show. */
    void secondAssignment() {
        if (assignment1Page > 0 || coursePages != null) {
            stepTo(stepper.current());
        }
    }

    private void showAssignment1(int page) {
        coursePages = null;
        assignment1Page = page;
        lastAssignment1Page = page;
        goTo.accept(new View.OfAssignment1Page(page));
    }

    private void stepTo(int position) {
        assignment1Page = 0;
        coursePages = null;
        goTo.accept(viewAt(position));
    }

    /** A scene opened or dropped: an extra view, from which the keys step through the eight pages again. */
    void openScene(Path file) {
        assignment1Page = 0;
        coursePages = null;
        goTo.accept(new View.OfScene(file));
    }

    /**
     * Several scenes dropped at once: the first pages from now on, in the order given, in place of the scenes
     * named at start (or dropped before), as {@code simpview A.simp B.simp} makes them; the first is shown.
     */
    void openScenes(List<Path> scenes) {
        sceneList = List.copyOf(scenes);
        stepper = new PageStepper(sceneList.size());
        stepTo(stepper.first());
    }

    /** What stands at a place among the pages: one of the scenes named at start, or one of the eight pages. */
    private View viewAt(int position) {
        int scene = stepper.sceneAt(position);
        return scene >= 0 ? new View.OfScene(sceneList.get(scene)) : new View.OfPage(stepper.pageAt(position));
    }

    /**
     * A drawing cancelled: the place among the eight pages and scenes goes
     * back to the view still on screen, when it is one of them.
     */
    void stayAt(View onScreen) {
        if (onScreen instanceof View.OfPage page) {
            stepper.jump(page.number());
        } else if (onScreen instanceof View.OfScene scene && sceneList.contains(scene.file())) {
            stepper.moveTo(sceneList.indexOf(scene.file()) + 1);
        }
    }

    /** How the title and the status line name {@code view} when it is the course pages' page on show, else null. */
    String coursePageOf(View view) {
        return coursePages != null && view.equals(new View.OfScene(coursePages.current())) ? coursePages.describe() : null;
    }
}
