package simpview.cli;

import java.nio.file.Path;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.SubmissionNames;
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

    /** The rubric's key of the target: "page6" for page 6, "pageC" for pageC.simp. */
    String key() {
        return isPage() ? "page" + page : SubmissionNames.stem(scene.getFileName().toString());
    }

    /** The target's rule in {@code rubric}: the rule its key names (for a page, of a range that holds its number). */
    RubricRule ruleIn(Rubric rubric) {
        return rubric.ruleFor(key(), isPage() ? page : 0);
    }
}
