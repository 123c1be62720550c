package simpview.cli;

import java.nio.file.Path;
import simpview.pages.PageContext;
import simpview.pages.Assignment2;

/** What simpview draws for a comparison: one of its pages, or a scene as a page. Exactly one is set. */
public record CompareTarget(int page, Path scene) {

    static CompareTarget page(int number) {
        return new CompareTarget(number, null);
    }

    static CompareTarget scene(Path file) {
        return new CompareTarget(0, file);
    }

    boolean isPage() {
        return scene == null;
    }

    /** E.g. "page 6: page6.simp", "page 2: Filled mesh (blerp), seed 361" or "scene pageC.simp". */
    String describe(PageContext context) {
        if (!isPage()) {
            return "scene " + scene.getFileName();
        }
        String title = "page " + page + ": " + Assignment2.page(page).title();
        return Assignment2.page(page).usesSeed() ? title + ", seed " + context.seed() : title;
    }

    /** For the batch table: "6", "2 (seed 361)" or "pageC.simp". */
    String label(PageContext context) {
        if (!isPage()) {
            return scene.getFileName().toString();
        }
        return Assignment2.page(page).usesSeed() ? page + " (seed " + context.seed() + ")" : String.valueOf(page);
    }
}
