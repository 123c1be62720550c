package simpview.cli;

import java.awt.image.BufferedImage;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;
import simpview.compare.Comparison;
import simpview.compare.DepthTestMistake;
import simpview.compare.OtherPage;
import simpview.compare.PanelHint;
import simpview.compare.PanelGridComparison;
import simpview.compare.Picture;
import simpview.compare.RandomValues;
import simpview.compare.RubricRule;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.ZBufferPage;
import simpview.scene.SceneException;

/**
 * simpview's pages of an assignment as the pages a failing picture may be of instead of the one its file is named
 * for ({@link OtherPage}). Each is drawn at most once, and only when some picture fails: those a batch drew for its
 * pictures already are taken as drawn. A page that cannot be drawn (the course's page6.simp absent) is no candidate.
 * Thread-safe: a batch's pictures are compared on several threads, and the eight pages are drawn on one canvas.
 */
final class OtherPages {

    /** The page of the eight that tests the z-buffer: six overlapping triangles. */
    private static final int Z_BUFFER_PAGE = 3;

    /** Who draws the eight pages, asked the first time one is needed; null for the first assignment's alone. */
    private final Supplier<OwnPictures> drawer;
    /** What {@link #drawer} gave, once asked (under the lock of {@link #pages}). */
    private OwnPictures own;
    private final PageContext context;
    /** The eight pages' panels by page, drawn; a page that cannot be drawn maps to null. */
    private final Map<Integer, int[][]> pages = new HashMap<>();
    /** The first assignment's pages, drawn (they read no files). */
    private final Map<Integer, BufferedImage> firstAssignment = new ConcurrentHashMap<>();
    /** The z-buffer page's panel drawn with each wrong depth test, drawn once (it reads no files). */
    private final Map<ZBufferPage.DepthTest, int[]> wrongDepthTests = new HashMap<>();
    /** The one canvas that draws them (under the lock of {@link #wrongDepthTests}); made at the first. */
    private PageRenderer wrongDepthRenderer;

    /** The pages {@code own} draws (its seed, its scene folder, its rule of the first assignment). */
    OtherPages(OwnPictures own) {
        this(() -> own, own.context());
    }

    /**
     * The eight pages as {@code drawer} draws them, made only when one is needed (a picture that passes costs
     * nothing); the first assignment's in {@code context} (its seed, its rule), which should be the drawer's.
     */
    OtherPages(Supplier<OwnPictures> drawer, PageContext context) {
        this.drawer = drawer;
        this.context = context;
    }

    /** The first assignment's pages alone, as {@code compare --assignment 1} of one picture draws them. */
    static OtherPages firstAssignment(PageContext context) {
        return new OtherPages(null, context);
    }

    /**
     * The other of the eight pages a picture whose panel is {@code theirs}, failing page {@code named} by
     * {@code rule}, passes as by that rule; null when none does (or several).
     */
    PanelHint ofEight(int named, int[] theirs, RubricRule rule) {
        OtherPage other = OtherPage.find(named, Assignment2.COUNT, new int[][] {theirs}, Comparison.N,
                new RubricRule[] {rule}, this::eightPage, k -> "page " + CompareTarget.page(k).label(context));
        if (other != null || named != Z_BUFFER_PAGE) {
            return other;
        }
        String page = "page " + CompareTarget.page(named).label(context);
        DepthTestMistake depth = DepthTestMistake.find(page, theirs, Comparison.N, rule,
                zBufferPage(ZBufferPage.DepthTest.NONE), zBufferPage(ZBufferPage.DepthTest.FARTHEST));
        int[][] ours = eightPage(named);
        return depth != null || ours == null ? depth
                : RandomValues.ofZBufferPage(page, named, context.seed(), ours[0], theirs, rule.tolerance());
    }

    /**
     * The z-buffer page, 3, drawn with its triangles in front of each other as {@code test} has them: its panel,
     * drawn once for all the pictures that ask (a batch's failing pictures of page 3 drew it again each).
     */
    private int[] zBufferPage(ZBufferPage.DepthTest test) {
        synchronized (wrongDepthTests) {
            int[] panel = wrongDepthTests.get(test);
            if (panel == null) {
                if (wrongDepthRenderer == null) {
                    wrongDepthRenderer = new PageRenderer();
                }
                try {
                    BufferedImage page = wrongDepthRenderer.renderImage(new ZBufferPage(test), context);
                    panel = Picture.ofPage(page, "page " + Z_BUFFER_PAGE).panel();
                } catch (SceneException e) {
                    throw new IllegalStateException("page 3 reads no file, yet: " + e.getMessage(), e);
                }
                wrongDepthTests.put(test, panel);
            }
            return panel;
        }
    }

    /**
     * The other of the first assignment's pages a picture whose panels are {@code theirs}, failing page
     * {@code named} by its panels' {@code rules}, passes as, every panel by its rule; null when none does (or several).
     */
    OtherPage ofFirstAssignment(int named, int[][] theirs, RubricRule[] rules) {
        PanelGridComparison.Panel[] panels = FirstAssignmentGrading.panels();
        return OtherPage.find(named, Assignment1.COUNT, theirs, panels[0].size(), rules,
                k -> PanelGridComparison.panels(firstAssignmentPage(k), panels),
                k -> "A1 page " + k + (Assignment1.page(k).usesSeed() ? " (seed " + context.seed() + ")" : ""));
    }

    /** The first assignment's page, drawn once. */
    BufferedImage firstAssignmentPage(int page) {
        return firstAssignment.computeIfAbsent(page, p -> Assignment1.render(p, context));
    }

    /** Page k's panel, drawn once (or taken as the batch drew it), as one panel of a page; null when it cannot be. */
    private int[][] eightPage(int k) {
        synchronized (pages) {
            if (!pages.containsKey(k)) {
                int[][] panel;
                if (own == null) {
                    own = drawer.get();
                }
                try {
                    panel = new int[][] {own.of(CompareTarget.page(k)).panel()};
                } catch (SceneException e) {
                    panel = null; // the course's files absent: not a page it can be told to be
                }
                pages.put(k, panel);
            }
            return pages.get(k);
        }
    }
}
