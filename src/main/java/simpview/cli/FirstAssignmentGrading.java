package simpview.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.IntStream;
import simpview.cli.CompareBatch.Match;
import simpview.cli.CompareOptions.PageRange;
import simpview.compare.AntialiasWeighting;
import simpview.compare.BatchRow;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.FillRule;
import simpview.compare.FlooredEnds;
import simpview.compare.HeatMap;
import simpview.compare.LineEnds;
import simpview.compare.OctantLines;
import simpview.compare.OtherPage;
import simpview.compare.PanelGridComparison;
import simpview.compare.PanelHint;
import simpview.compare.RandomValues;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.SubmissionNames;
import simpview.compare.Wanted;
import simpview.pages.A1Layout;
import simpview.pages.A1Lines;
import simpview.pages.A1Page;
import simpview.pages.A1Polygons;
import simpview.pages.Assignment1;
import simpview.pages.LineTestPage;
import simpview.pages.PageContext;
import simpview.pages.PolygonTestPage;
import simpview.surface.PageCanvas;

/**
 * How a batch grades the first assignment's pages: a picture of one is compared panel by panel with simpview's page,
 * each of its four panels with a rubric key ("a1-page2-panel4"), a label and a rule of its own, and told the hints
 * that say what its drawer did wrong. Which picture is such a page by its name, and the pages the pictures need,
 * drawn once each, are here too; {@code compare PICTURE --assignment 1} judges one picture by the same keys, rules
 * and hints.
 */
final class FirstAssignmentGrading {

    /** How the first assignment's pages are graded, for a picture of one where the eight pages are asked for. */
    static final String HOW_GRADED = "--assignment 1 grades the first assignment's pages";

    private final PageContext context;
    /** The pages a failing picture may be of instead, and the first assignment's pages themselves. */
    private final OtherPages others;
    private final Rubric rubric;
    private final boolean partial;
    /**
     * With --partial, the share an empty panel gets against each first-assignment panel's own
     * ({@link RubricRule#emptyShare}), by its label: measured once, at its first picture that fails.
     */
    private final Map<String, Double> emptyShares = new ConcurrentHashMap<>();

    /** The grading of a batch drawn in {@code context}, judged by {@code rubric}, with partial credit or not. */
    FirstAssignmentGrading(PageContext context, OtherPages others, Rubric rubric, boolean partial) {
        this.context = context;
        this.others = others;
        this.rubric = rubric;
        this.partial = partial;
    }

    /** The panels of the first assignment's pages, in page coordinates. */
    static PanelGridComparison.Panel[] panels() {
        PanelGridComparison.Panel[] panels = new PanelGridComparison.Panel[A1Layout.PANELS];
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            panels[k - 1] = new PanelGridComparison.Panel(A1Layout.left(k), A1Layout.top(k), A1Layout.PANEL);
        }
        return panels;
    }

    /** The rubric key of the first assignment's page's panel: "a1-page2-panel4". */
    static String key(int page, int panel) {
        return "a1-page" + page + "-panel" + panel;
    }

    /** E.g. "A1 page 1", "A1 page 3 (seed 361)": a page of the first assignment as a whole (one that is missing). */
    String label(int page) {
        return "A1 page " + page + (Assignment1.page(page).usesSeed() ? " (seed " + context.seed() + ")" : "");
    }

    /** E.g. "A1 page 1 panel 4 (antialiased)", "A1 page 3 (seed 361) panel 1 (DDA)", "A1 page 4 panel 2". */
    private String label(int page, int panel) {
        return label(page) + " panel " + panel
                + (Assignment1.page(page) instanceof LineTestPage ? " (" + LineTestPage.DRAWERS.get(panel - 1) + ")" : "");
    }

    /**
     * A first-assignment page's rule as a whole (when it is missing, or its picture cannot be compared): its four
     * panels' rules, worth their points.
     */
    RubricRule pageRule(int page) {
        List<RubricRule> panels = new ArrayList<>();
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            panels.add(rule(page, k));
        }
        return RubricRule.whole(panels);
    }

    /**
     * A panel's rule: the rubric's rule for "a1-page2-panel4" (a pattern like "a1-*-panel4" picks out the
     * antialiased panels); when no rule of the rubric names it, the defaults without slack, as
     * {@code compare --assignment 1} judges: which pixels a line drawer lights is the point.
     */
    private RubricRule rule(int page, int panel) {
        return rule(rubric, page, panel);
    }

    /** Of {@code rubric}, the rule of the first assignment's page's panel, as a batch judges it ({@link #rule(int, int)}). */
    static RubricRule rule(Rubric rubric, int page, int panel) {
        RubricRule rule = rubric.ruleFor(key(page, panel), 0);
        if (!"*".equals(rule.match())) {
            return rule;
        }
        return new RubricRule(rule.match(), rule.tolerance(), 0, rule.minShare(), rule.maxFailing(), rule.points(),
                rule.zeroShare(), rule.metric(), rule.alternates(), rule.visibility(), rule.flipThreshold());
    }

    /** The rubric keys of every panel of the first assignment's {@code pages}: "a1-page2-panel4". */
    static Map<String, Integer> subjects(Set<Integer> pages) {
        Map<String, Integer> subjects = new HashMap<>();
        for (int page : pages) {
            for (int k = 1; k <= A1Layout.PANELS; k++) {
                subjects.put(key(page, k), 0);
            }
        }
        return subjects;
    }

    /**
     * Whether a picture is one of the first assignment's pages: its file name says so (a1-page2.png,
     * a1page2.png, assignment1_page2.png) or a folder on its way does (a1/page2.png, the course's own
     * captures' folder).
     */
    static boolean namesFirstAssignment(String relative) {
        for (Path part : Path.of(relative)) {
            if (SubmissionNames.namesFirstAssignment(part.toString())) {
                return true;
            }
        }
        return false;
    }

    /**
     * The first assignment's page a picture's file name names (a1-page3.png, page3.png: page 3), when it is one of
     * {@code pages} (null: any of the five); else why it is skipped, {@code option} naming the pages asked for.
     */
    static Match match(String name, PageRange pages, String option) {
        OptionalInt number = SubmissionNames.pageNumber(name);
        if (number.isEmpty()) {
            return new Match(null, SubmissionNames.noPageNumber(name, "a1-page", Assignment1.COUNT));
        }
        int page = number.getAsInt();
        if (page > Assignment1.COUNT) {
            return new Match(null, "the first assignment has pages 1 to " + Assignment1.COUNT + ", not " + page);
        }
        if (pages != null && !pages.contains(page)) {
            return new Match(null, "A1 page " + page + " is not among " + option);
        }
        return new Match(null, null, page);
    }

    /** Whether a row is of one of the first assignment's pages: one of its panels, or a picture of it that is broken. */
    boolean isOfAPage(BatchRow row) {
        for (int page = 1; page <= Assignment1.COUNT; page++) {
            if (new Wanted(label(page), rubric.defaults()).metBy(row)) {
                return true;
            }
        }
        return false;
    }

    /** The first assignment's pages the pictures need, drawn once each (they read no files). */
    Map<Integer, BufferedImage> draw(List<Match> matches) {
        // concurrent: a picture named like one of the eight pages that holds a first-assignment page adds its page
        Map<Integer, BufferedImage> drawn = new ConcurrentHashMap<>();
        for (Match match : matches) {
            if (match.firstAssignmentPage() > 0) {
                drawn.computeIfAbsent(match.firstAssignmentPage(), others::firstAssignmentPage);
            }
        }
        return drawn;
    }

    /** How a first-assignment picture is cut beside simpview's page (its file read, or a picture already read). */
    interface Cutter {
        PanelGridComparison.Cut cut(BufferedImage ours) throws CompareException;
    }

    /**
     * A picture of one of the first assignment's pages, panel by panel against simpview's page: one row per
     * panel, or one ERROR row when it cannot be read or holds no such page. Thread-safe.
     */
    List<BatchRow> compare(String relative, int page, BufferedImage ours, DiffPlan diffs, Cutter cutter) {
        PanelGridComparison.Cut cut;
        try {
            cut = cutter.cut(ours);
        } catch (CompareException e) {
            // it scores nothing of what its four panels are worth, as a page not handed in
            return List.of(BatchRow.broken(relative, label(page), e.getMessage(), pageRule(page)));
        }
        List<BatchRow> rows = new ArrayList<>();
        // the hints by panel 1's tolerance: a page turned whole is one hint for its four panels
        PanelHint[] hints = PanelHint.ofPage(cut.ours(), cut.theirs(), A1Layout.PANEL, PageCanvas.SIZE,
                rule(page, 1).tolerance(), Assignment1.page(page).panelNames());
        hints(hints, Assignment1.page(page), context, cut.ours(), cut.theirs(), rule(page, 1).tolerance());
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            RubricRule rule = rule(page, k);
            Comparison comparison = rule.compare(cut.ours()[k - 1], cut.theirs()[k - 1], A1Layout.PANEL);
            PanelHint hint = hints[k - 1];
            String note = "page at x " + cut.pageLeft() + ", y " + cut.pageTop() + " of the picture, counted from its "
                    + "top-left; panel " + k + " at x " + A1Layout.left(k) + "-" + (A1Layout.left(k) + A1Layout.PANEL - 1)
                    + ", y " + A1Layout.top(k) + "-" + (A1Layout.top(k) + A1Layout.PANEL - 1) + " of the page"
                    + (cut.runsPast().isEmpty() ? "" : "; " + cut.runsPast());
            boolean passes = rule.passes(comparison);
            String label = label(page, k);
            double empty = partial && !passes ? emptyShare(label, rule, cut.ours()[k - 1]) : Double.NaN;
            double score = rule.score(comparison, partial, empty);
            if (!diffs.writes(passes)) {
                rows.add(BatchRow.panel(relative, label, comparison, rule, score, "", note, hint, empty)
                        .decodedAs(cut.format()));
                continue;
            }
            String diff = diffs.names().of(relative, k);
            try {
                diffs.write(diff, HeatMap.diffPng(comparison, rule.tolerance()));
                rows.add(BatchRow.panel(relative, label, comparison, rule, score, diff, note, hint, empty)
                        .decodedAs(cut.format()));
            } catch (IOException e) {
                rows.add(BatchRow.panel(relative, label, comparison, rule, score, "",
                        DiffPlan.NOT_WRITTEN + e.getMessage(), hint, empty).decodedAs(cut.format()));
            }
        }
        if (rows.stream().anyMatch(r -> r.result() == BatchRow.Result.FAIL)) {
            RubricRule[] rules = IntStream.rangeClosed(1, A1Layout.PANELS).mapToObj(k -> rule(page, k))
                    .toArray(RubricRule[]::new);
            OtherPage other = others.ofFirstAssignment(page, cut.theirs(), rules);
            // a page of the student's own random values, which no panel's own mistake explains (nor a lack of colour)
            RandomValues random = other != null || rows.stream().anyMatch(BatchRow::colourless)
                    || Arrays.stream(hints).anyMatch(h -> h != null) ? null
                    : RandomValues.find(label(page), page, Assignment1.page(page), context.seed(),
                            cut.ours(), cut.theirs(), A1Layout.PANEL, rule(page, 1).tolerance());
            if (other != null) { // the page is another of the five: that says more than each panel's own hint
                rows.replaceAll(row -> row.withHint(other));
            } else if (random != null) {
                rows.replaceAll(row -> row.withHint(random));
            }
        }
        return rows;
    }

    /**
     * The share an empty panel gets against simpview's own panel {@code ours} under {@code rule}, for the panel of
     * {@code label}: measured once. Thread-safe.
     */
    private double emptyShare(String label, RubricRule rule, int[] ours) {
        return emptyShares.computeIfAbsent(label, l -> rule.emptyShare(ours, A1Layout.PANEL));
    }

    /**
     * The first assignment's own hints, for each panel that no other hint explains, passing or not (a line a pixel
     * short passes, and the student would not learn of it). On a page of lines, the DDA, Bresenham and alternating
     * panels: lines drawn with floored ends ({@link FlooredEnds}), differing pixels that are mostly the lines' ends or
     * one past them ({@link LineEnds}), or lines that differ in some octants only ({@link OctantLines}); the
     * antialiased panel: floored ends, or its levels on and beside a line told when they are not simpview's
     * ({@link AntialiasWeighting}). On a page of polygons, each panel: a fill without the top-left rule
     * ({@link FillRule}).
     */
    static void hints(PanelHint[] hints, A1Page shown, PageContext context, int[][] ours, int[][] theirs,
            int tolerance) {
        if (hints.length != A1Layout.PANELS) {
            return;
        }
        int n = A1Layout.PANEL;
        if (shown instanceof PolygonTestPage polygons) {
            A1Polygons scenes = new A1Polygons(context.seed(), context.a1Rule());
            for (int k = 0; k < A1Layout.PANELS; k++) {
                if (hints[k] == null) {
                    hints[k] = FillRule.find(ours[k], theirs[k], n, tolerance, scenes.scene(k + 1), polygons.ghost());
                }
            }
            return;
        }
        if (!(shown instanceof LineTestPage page)) {
            return;
        }
        A1Lines lines = page.lines(context.seed());
        for (int k = 0; k < A1Layout.PANELS; k++) {
            if (hints[k] == null) {
                hints[k] = FlooredEnds.find(ours[k], theirs[k], n, tolerance, k + 1, context.a1Rule(), lines);
            }
        }
        for (int k = 0; k < 3; k++) {
            if (hints[k] == null) {
                hints[k] = LineEnds.find(ours[k], theirs[k], n, tolerance, lines);
            }
            if (hints[k] == null) {
                hints[k] = OctantLines.find(ours[k], theirs[k], n, tolerance, lines);
            }
        }
        if (hints[3] == null) {
            hints[3] = AntialiasWeighting.find(ours[3], theirs[3], n, tolerance, lines);
        }
    }
}
