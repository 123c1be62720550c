package simpview.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import simpview.compare.CompareException;
import simpview.compare.Colourless;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.DiffRegion;
import simpview.compare.DiffRegions;
import simpview.compare.HeatMap;
import simpview.compare.OtherPage;
import simpview.compare.PanelGridComparison;
import simpview.compare.PanelHint;
import simpview.compare.PanelWords;
import simpview.compare.Percent;
import simpview.compare.PngFiles;
import simpview.compare.RandomValues;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.WholePage;
import simpview.compare.WorstPixel;
import simpview.pages.A1Layout;
import simpview.pages.A1Page;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.LineTestPage;
import simpview.pages.PageContext;
import simpview.surface.PageCanvas;

/**
 * One picture of a first-assignment page (four 300x300 panels) against simpview's page, panel by panel, as
 * {@code simpview compare PICTURE --assignment 1 --page N} reports it: the table of the panels' shares, the verdict,
 * the failing panels' patches, the notes and hints, the pixel to look at first and the diff image. Each panel is
 * judged by the rule a batch judges it by ({@link FirstAssignmentGrading}).
 */
final class FirstAssignmentComparison {

    /** The picture compared, as named on the command line. */
    private final Path image;
    /** The first assignment's page it is compared with, 1 to 5. */
    private final int page;
    /** The --rubric file as given, named in the report; null without one. */
    private final Path rubric;
    /** Each panel's rule, panel 1's first. */
    private final RubricRule[] rules;
    /** The options that drew the page, as typed (" --seed 7 --a1-rule course"): for the inspect command suggested. */
    private final String inspectOptions;
    private final PrintWriter out;
    private final PrintWriter err;

    /**
     * The comparison of {@code image} with the first assignment's page {@code page}, each panel judged by
     * {@code read}'s rule for it (the command line's alone without --rubric {@code rubric}), said on {@code out} and
     * {@code err}.
     */
    FirstAssignmentComparison(Path image, int page, Path rubric, Rubric read, String inspectOptions, PrintWriter out,
            PrintWriter err) {
        this.image = image;
        this.page = page;
        this.rubric = rubric;
        this.rules = new RubricRule[A1Layout.PANELS];
        for (int k = 0; k < rules.length; k++) {
            rules[k] = FirstAssignmentGrading.rule(read, page, k + 1);
        }
        this.inspectOptions = inspectOptions;
        this.out = out;
        this.err = err;
    }

    /**
     * The first assignment's page beside the picture, panel by panel, each panel by its rule: the rubric's rule for
     * it ({@code a1-page2-panel4}) with --rubric, as a batch judges it, else the command line's, without slack. The
     * verdict passes when every panel does. Each failing panel's largest differing patches are listed; a hint that
     * fits several panels is said once for them; --diff writes the three pages to {@code diff} (null: none), which
     * {@code files} records. The page is drawn in {@code context}; the exit code is returned.
     */
    int compare(PageContext context, Path diff, OutputPaths files) {
        PanelGridComparison.Panel[] panels = FirstAssignmentGrading.panels();
        A1Page shown = Assignment1.page(page);
        BufferedImage ours = Assignment1.render(page, context);
        PanelGridComparison.Cut cut;
        try {
            cut = PanelGridComparison.cut(image, ours, panels);
        } catch (CompareException e) {
            err.println("simpview compare: " + e.getMessage());
            return ExitCode.SCENE_ERROR;
        }
        Comparison[] compared = new Comparison[panels.length];
        for (int k = 0; k < panels.length; k++) {
            compared[k] = rules[k].compare(cut.ours()[k], cut.theirs()[k], panels[k].size());
        }
        if (rubric != null) {
            sayPanelRules(shown);
        }
        out.println(image + " against simpview's assignment 1, page " + page + ": " + shown.title()
                + (shown.usesSeed() ? ", seed " + context.seed() : "")
                + (context.a1Rule() == A1Rule.SPEC ? "" : ", by " + context.a1Rule().label()));
        out.println("page:    " + cut.describe());
        RubricRule first = rules[0];
        // one rule's terms for all four panels (always so without a rubric): said once, in the table's head
        boolean alike = Arrays.stream(rules).allMatch(r -> sameVerdict(r, first));
        if (alike && first.metric() == Comparison.Metric.BLUR) {
            out.println("metric:  both pictures' panels blurred (3x3) before they are compared");
        }
        boolean flip = first.metric() == Comparison.Metric.FLIP;
        if (alike && flip) {
            out.println("metric:  FLIP (LDR, 67 pixels per degree) of each panel: a pixel matches at FLIP "
                    + String.format(Locale.ROOT, "%.3f", first.flipThreshold()) + " or less");
        }
        String within = alike ? within(first) : "by its rule";
        out.printf(Locale.ROOT, "%-38s %9s %12s%s%n", "panel", "identical", within, alike ? "" : "  needed");
        boolean[] passing = new boolean[panels.length];
        for (int k = 0; k < panels.length; k++) {
            Comparison c = compared[k];
            // rounded down, as every share is printed (Percent): a hint's share of the panel reads the same
            out.printf(Locale.ROOT, "%-38s %7s %% %10s %%%s%n", (k + 1) + " " + panelName(shown, k),
                    Percent.number(c.share(0, false)), Percent.number(c.verdictShare(rules[k].tolerance())),
                    alike ? "" : "  " + needed(rules[k]));
            passing[k] = rules[k].passes(c);
        }
        boolean passes = true;
        for (int k = 0; k < panels.length; k++) {
            passes &= passing[k];
            if (!passing[k]) {
                int tolerance = rules[k].tolerance();
                out.print("panel " + (k + 1) + " (" + panelName(shown, k) + "): " + ComparisonReport.regionsText(
                        compared[k], DiffRegions.of(compared[k], tolerance, ComparisonReport.REGIONS_LISTED), tolerance));
            }
        }
        if (alike) {
            out.printf(Locale.ROOT, "%s: every panel %s %.2f %% %s%s%n", passes ? "PASS" : "FAIL",
                    passes ? "reaches" : "must reach", first.minShare(), flip ? within : within + " ("
                    + (first.deviation() == 0 ? "no slack" : "with " + first.deviation() + " px slack") + ")",
                    first.maxFailing() < 0 ? "" : String.format(Locale.ROOT, ", at most %,d pixels failing",
                            first.maxFailing()));
        } else {
            out.println((passes ? "PASS: every panel reaches" : "FAIL: every panel must reach") + " what its rule "
                    + "needs (the table's last column)");
        }
        // A panel passes with up to 1 % of its pixels wrong, 900: a small shape left out still passes. Its patches
        // are not listed, so a solid one is said, as of a page of the eight pages, by the panel it is in.
        for (int k = 0; k < panels.length; k++) {
            DiffRegion patch = passing[k] ? ComparisonReport.solidPatch(DiffRegions.of(compared[k],
                    rules[k].tolerance(), ComparisonReport.REGIONS_LISTED).largest()) : null;
            if (patch != null) {
                out.println("note: panel " + (k + 1) + " (" + panelName(shown, k) + "): "
                        + ComparisonReport.solidPatchNote(patch));
            }
        }
        // A failing panel without colour where simpview's has some, as a batch notes it of each panel: said once.
        List<Integer> colourless = new ArrayList<>();
        for (int k = 0; k < panels.length; k++) {
            if (!passing[k] && Colourless.note(compared[k].ours(), compared[k].theirs(), rules[k].tolerance()) != null) {
                colourless.add(k + 1);
            }
        }
        if (!colourless.isEmpty()) {
            out.println("note: " + PanelWords.panels(colourless) + ": " + Colourless.NOTE);
        }
        CompareCommand.sayFormat(out, image, passes, cut.format());
        int[][] ourPanels = new int[panels.length][];
        int[][] theirPanels = new int[panels.length][];
        for (int k = 0; k < panels.length; k++) {
            ourPanels[k] = compared[k].ours();
            theirPanels[k] = compared[k].theirs();
        }
        // the hints by panel 1's tolerance, as a batch finds them
        PanelHint[] hints = PanelHint.ofPage(ourPanels, theirPanels, A1Layout.PANEL, PageCanvas.SIZE, first.tolerance(),
                shown.panelNames());
        FirstAssignmentGrading.hints(hints, shown, context, ourPanels, theirPanels, first.tolerance());
        // a page that fails as a whole and passes as another of the five: that one hint, of the page
        OtherPage other = passes ? null : OtherPages.firstAssignment(context).ofFirstAssignment(page, theirPanels, rules);
        // a page of the student's own random values, which no panel's own mistake explains
        // (a page without colour is told so above: its colours are not another draw's)
        RandomValues random = passes || other != null || !colourless.isEmpty()
                || Arrays.stream(hints).anyMatch(h -> h != null) ? null
                : RandomValues.find("A1 page " + page, page, shown, context.seed(), ourPanels, theirPanels,
                        A1Layout.PANEL, first.tolerance());
        if (other != null) {
            out.println("hint: " + other.hint(A1Layout.PANEL));
        } else if (random != null) {
            out.println("hint: " + random.hint(A1Layout.PANEL));
        } else if (hints[0] instanceof WholePage whole) {
            out.println("hint: " + whole.hint(A1Layout.PANEL));
        } else {
            // the same mistake in several panels: said once for them, as check says it
            for (List<Integer> alikePanels : PanelWords.alike(hints)) {
                String text = hints[alikePanels.get(0) - 1].hint(A1Layout.PANEL);
                boolean sameWords = alikePanels.stream().allMatch(k -> text.equals(hints[k - 1].hint(A1Layout.PANEL)));
                out.println("hint: " + PanelWords.panels(alikePanels) + ": "
                        + PanelWords.sharedHint(text, sameWords, alikePanels));
            }
        }
        if (!passes) {
            lookAt(shown, compared, passing);
        }
        if (diff != null) {
            try {
                PngFiles.writeEncoded(HeatMap.pageDiffPng(compared, panels, ours.getWidth(), first.tolerance()), diff);
                files.wrote(diff);
            } catch (IOException e) {
                err.println("simpview compare: " + e.getMessage());
                return ExitCode.SCENE_ERROR;
            }
            out.println("diff:    " + diff + " (ours | theirs | heat map, each the whole page, their panels on white: "
                    + "grey identical, blue within " + first.tolerance() + "/255, "
                    + (flip ? "yellow beyond it but forgiven by FLIP, red above FLIP's threshold)" : "red beyond it)"));
        }
        return passes ? ExitCode.OK : ExitCode.SCENE_ERROR;
    }

    /**
     * Which of the rubric's rules judged which panels, a line a rule, in the order of their first panels, as one
     * picture's report begins: {@code rubric:  compare.json, panel 4 (antialiased): its rule "match": "a1-*-panel4"}.
     */
    private void sayPanelRules(A1Page shown) {
        List<String> said = new ArrayList<>();
        for (int k = 0; k < rules.length; k++) {
            String match = rules[k].match();
            if (said.contains(match)) {
                continue;
            }
            said.add(match);
            List<Integer> judged = new ArrayList<>();
            List<String> keys = new ArrayList<>();
            for (int j = k; j < rules.length; j++) {
                if (rules[j].match().equals(match)) {
                    judged.add(j + 1);
                    keys.add(FirstAssignmentGrading.key(page, j + 1));
                }
            }
            String which = PanelWords.panels(judged) + (judged.size() == 1 ? " (" + panelName(shown, k) + ")" : "");
            out.println("rubric:  " + rubric + ", " + which + ": " + ("*".equals(match)
                    ? "its defaults, without slack (no rule names " + UsageWords.joined(keys, "or") + ")"
                    : "its rule \"match\": \"" + match + "\""));
        }
    }

    /** Whether two rules judge a panel alike: the same tolerance, minimum share, slack, pixel limit and metric. */
    private static boolean sameVerdict(RubricRule a, RubricRule b) {
        return a.tolerance() == b.tolerance() && a.minShare() == b.minShare() && a.deviation() == b.deviation()
                && a.maxFailing() == b.maxFailing() && a.metric() == b.metric()
                && (a.metric() != Comparison.Metric.FLIP || a.flipThreshold() == b.flipThreshold());
    }

    /** What a rule's share counts: "within 8/255", or "FLIP {@code <=} 0.130". */
    private static String within(RubricRule rule) {
        return rule.metric() == Comparison.Metric.FLIP ? String.format(Locale.ROOT, "FLIP <= %.3f",
                rule.flipThreshold()) : "within " + rule.tolerance() + "/255";
    }

    /** What a panel's rule needs, for the table's last column: "99.00 % within 8/255, no slack, blurred". */
    private static String needed(RubricRule rule) {
        return String.format(Locale.ROOT, "%.2f %% %s, %s%s%s", rule.minShare(), within(rule),
                rule.deviation() == 0 ? "no slack" : rule.deviation() + " px slack",
                rule.metric() == Comparison.Metric.BLUR ? ", blurred" : "",
                rule.maxFailing() < 0 ? "" : String.format(Locale.ROOT, ", at most %,d pixels failing",
                        rule.maxFailing()));
    }

    /**
     * Of a first-assignment page that fails, the pixel to look at first, in its lowest failing panel: the one that
     * differs most in that panel's largest patch ({@link WorstPixel}), in the panel's and the page's coordinates;
     * and the {@code inspect} command that shows which lines or triangles wrote it there, or went past it.
     */
    private void lookAt(A1Page shown, Comparison[] compared, boolean[] passing) {
        int worst = -1;
        for (int k = 0; k < compared.length; k++) {
            if (!passing[k] && (worst < 0 || compared[k].verdictShare(rules[k].tolerance())
                    < compared[worst].verdictShare(rules[worst].tolerance()))) {
                worst = k;
            }
        }
        if (worst < 0) {
            return;
        }
        int tolerance = rules[worst].tolerance();
        List<DiffRegion> patches = DiffRegions.of(compared[worst], tolerance, ComparisonReport.REGIONS_LISTED)
                .largest();
        WorstPixel look = patches.isEmpty() ? null : WorstPixel.in(compared[worst], patches.get(0), tolerance);
        if (look == null) {
            return;
        }
        int panel = worst + 1;
        int pageX = A1Layout.left(panel) + look.x();
        int pageY = PageCanvas.SIZE - 1 - (A1Layout.top(panel) + A1Layout.PANEL - 1 - look.y());
        out.println("look:    " + look.describe("panel " + panel + " (" + panelName(shown, worst) + ") x " + look.x()
                + ", y " + look.y() + " (page x " + pageX + ", y " + pageY + ")"));
        CompareCommand.nextStep(out, shown instanceof LineTestPage
                ? "the lines that wrote the page's pixel, or wrote beside it"
                : "the triangles that wrote the page's pixel and why its centre is in or out of each",
                "simpview inspect --assignment 1 --page " + page + inspectOptions + " --at " + pageX + "," + pageY);
    }

    /** Panel k's (from 0) drawer ("Bresenham") on a page of lines, its scene ("mesh") on a page of polygons. */
    private static String panelName(A1Page shown, int k) {
        return shown.panelNames().get(k);
    }
}
