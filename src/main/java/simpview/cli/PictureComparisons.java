package simpview.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import java.util.stream.Collectors;
import simpview.cli.CompareBatch.Match;
import simpview.compare.BatchRow;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.HeatMap;
import simpview.compare.OtherPage;
import simpview.compare.PanelGridComparison;
import simpview.compare.PanelHint;
import simpview.compare.PanelWords;
import simpview.compare.Percent;
import simpview.compare.Picture;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.pages.Assignment1;

/**
 * A batch's comparisons, on threads of their own ({@code simpview-compare-N}): each picture against the page or scene
 * its name was matched to, and when it does not pass, against the rubric's accepted alternates; a picture of one of
 * the first assignment's pages panel by panel ({@link FirstAssignmentGrading}). Each gets its diff image and, failing,
 * the other page it may be of; its progress is said on stderr as it is done.
 */
final class PictureComparisons {

    private final OwnPictures own;
    /** The pages a failing picture may be of instead, drawn once, if ever. */
    private final OtherPages others;
    private final Rubric rubric;
    private final boolean partial;
    private final FirstAssignmentGrading firstAssignment;
    private final HandedIn handedIn;
    private final PrintWriter err;
    /**
     * Whether a picture named like one of the eight pages that holds a first-assignment page is compared as that
     * ({@code check} without --pages); else the eight pages were asked for, and it is a row of the page it names.
     */
    private final boolean pagesIfHandedIn;
    /**
     * The batch's pictures that are first-assignment pages where the eight pages were asked for (by their paths under
     * the folder), which the comparisons add to.
     */
    private final Set<String> firstAssignmentUnasked;
    /**
     * With --partial, the share an empty panel gets against each page's or scene's own ({@link RubricRule#emptyShare}),
     * by its label: measured once, at its first picture that fails (a first-assignment panel's:
     * {@link FirstAssignmentGrading}'s).
     */
    private final Map<String, Double> emptyShares = new ConcurrentHashMap<>();

    /**
     * The comparisons of a batch that draws with {@code own} and judges by {@code rubric}, with partial credit or not,
     * naming each picture as {@code handedIn} does and saying its progress on {@code err}.
     */
    PictureComparisons(OwnPictures own, OtherPages others, Rubric rubric, boolean partial,
            FirstAssignmentGrading firstAssignment, HandedIn handedIn, PrintWriter err, boolean pagesIfHandedIn,
            Set<String> firstAssignmentUnasked) {
        this.own = own;
        this.others = others;
        this.rubric = rubric;
        this.partial = partial;
        this.firstAssignment = firstAssignment;
        this.handedIn = handedIn;
        this.err = err;
        this.pagesIfHandedIn = pagesIfHandedIn;
        this.firstAssignmentUnasked = firstAssignmentUnasked;
    }

    /**
     * The comparisons of the pictures under {@code dir}, each with what it was matched to, on a thread a core up to
     * four; rows in the pictures' order. {@code drawn}: simpview's pages and scenes; {@code firstAssignmentPages}:
     * the first assignment's pages drawn so far (a picture named like one of the eight pages that holds one adds its
     * page); {@code alternates}: each target's accepted alternates; {@code linkOut}: why a picture is not read, when
     * it is a link out of the folder (its row says so).
     */
    List<BatchRow> rows(Path dir, List<Path> pictures, List<Match> matches,
            Map<CompareTarget, Picture> drawn, Map<Integer, BufferedImage> firstAssignmentPages,
            Map<CompareTarget, List<Alternates.Accepted>> alternates, DiffPlan diffs,
            Function<Path, Optional<String>> linkOut) {
        AtomicInteger named = new AtomicInteger();
        ExecutorService workers = Executors.newFixedThreadPool(
                Math.max(1, Math.min(4, Runtime.getRuntime().availableProcessors())),
                task -> new Thread(task, "simpview-compare-" + named.incrementAndGet()));
        AtomicInteger finished = new AtomicInteger();
        try {
            List<Future<List<BatchRow>>> rows = new ArrayList<>();
            for (int i = 0; i < pictures.size(); i++) {
                Path picture = pictures.get(i);
                Match match = matches.get(i);
                rows.add(workers.submit(() -> {
                    String relative = handedIn.name(dir, picture);
                    List<BatchRow> made;
                    Optional<String> notRead = linkOut.apply(picture);
                    if (notRead.isPresent() && match.firstAssignmentPage() > 0) {
                        int page = match.firstAssignmentPage();
                        made = List.of(BatchRow.broken(relative, firstAssignment.label(page), notRead.get(),
                                firstAssignment.pageRule(page)));
                    } else if (notRead.isPresent() && match.target() != null) {
                        made = List.of(BatchRow.broken(relative, match.target().label(own.context()), notRead.get(),
                                match.target().ruleIn(rubric)));
                    } else if (match.firstAssignmentPage() > 0) {
                        int page = match.firstAssignmentPage();
                        made = firstAssignment.compare(relative, page, firstAssignmentPages.get(page), diffs,
                                ours -> PanelGridComparison.cut(picture, ours, FirstAssignmentGrading.panels()));
                    } else if (match.target() == null) {
                        made = List.of(BatchRow.skipped(relative, match.skipped()));
                    } else {
                        made = compareRead(picture, relative, match.target(), drawn.get(match.target()),
                                alternates.get(match.target()), firstAssignmentPages, diffs);
                    }
                    synchronized (err) {
                        err.printf("[%d/%d] %s: %s%n", finished.incrementAndGet(), pictures.size(), relative, progress(made));
                    }
                    return made;
                }));
            }
            List<BatchRow> done = new ArrayList<>();
            for (Future<List<BatchRow>> row : rows) {
                done.addAll(row.get());
            }
            return done;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while comparing", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a comparison failed", e.getCause());
        } finally {
            workers.shutdownNow();
        }
    }

    /**
     * A picture matched to one of the eight pages by its name. When that page's number is also one of the
     * first assignment's and the picture holds a first-assignment page (four framed 300x300 panels: a capture
     * named page2.png), it is compared as that, panel by panel; else as the page it names.
     */
    private List<BatchRow> compareRead(Path file, String relative, CompareTarget target, Picture ours,
            List<Alternates.Accepted> alternates, Map<Integer, BufferedImage> firstAssignmentPages, DiffPlan diffs) {
        if (!target.isPage() || target.page() > Assignment1.COUNT) {
            return List.of(compare(file, relative, target, ours, alternates, diffs, null));
        }
        Picture theirs;
        try {
            theirs = Picture.read(file);
        } catch (CompareException e) {
            return List.of(compare(file, relative, target, ours, alternates, diffs, null));
        }
        int page = target.page();
        if (PanelGridComparison.holds(theirs, FirstAssignmentGrading.panels())) {
            if (!pagesIfHandedIn) {
                firstAssignmentUnasked.add(relative);
                return List.of(BatchRow.broken(relative, target.label(own.context()), "it holds a page of the first "
                        + "assignment (four framed 300x300 panels), not page " + page + " of the eight pages that "
                        + "--pages names (" + FirstAssignmentGrading.HOW_GRADED + ")", target.ruleIn(rubric)));
            }
            BufferedImage first = firstAssignmentPages.computeIfAbsent(page, others::firstAssignmentPage);
            return firstAssignment.compare(relative, page, first, diffs,
                    mine -> PanelGridComparison.cut(theirs, mine, FirstAssignmentGrading.panels()));
        }
        return List.of(compare(file, relative, target, ours, alternates, diffs, theirs));
    }

    /**
     * One picture against simpview's, and when it does not pass, against each accepted alternate: the first
     * that passes is its result; when none does, the comparison with simpview's own is. Thread-safe.
     */
    private BatchRow compare(Path file, String relative, CompareTarget target, Picture ours,
            List<Alternates.Accepted> alternates, DiffPlan diffs, Picture read) {
        String label = target.label(own.context());
        RubricRule rule = target.ruleIn(rubric);
        Picture theirs = read;
        if (theirs == null) {
            try {
                theirs = Picture.read(file);
            } catch (CompareException e) {
                return BatchRow.broken(relative, label, e.getMessage(), rule);
            }
        }
        String against = target.describe(own.context());
        Alternates.Judged judged = Alternates.judge(ComparisonReport.of(theirs, against,
                rule.compare(ours.panel(), theirs.panel(), Comparison.N), rule), theirs, against, rule, alternates);
        ComparisonReport best = judged.report();
        String bestName = judged.alternate();
        double empty = partial && !best.passes() ? emptyShare(label, rule, ours.panel(), Comparison.N) : Double.NaN;
        double score = rule.score(best.comparison(), partial, empty);
        // a failing picture no mistake explains may be another page, its file named for the wrong one
        PanelHint other = best.passes() || best.systematic() != null || !target.isPage() ? null
                : others.ofEight(target.page(), theirs.panel(), rule);
        if (!diffs.writes(best.passes())) {
            return hinted(BatchRow.compared(relative, label, best, "", rule, score, bestName, empty), other);
        }
        String diff = diffs.names().of(relative, 0);
        try {
            diffs.write(diff, HeatMap.diffPng(best.comparison(), rule.tolerance()));
        } catch (IOException e) {
            return hinted(BatchRow.compared(relative, label, best, "", rule, score, bestName, empty)
                    .withoutDiff(DiffPlan.NOT_WRITTEN + e.getMessage()), other);
        }
        return hinted(BatchRow.compared(relative, label, best, diff, rule, score, bestName, empty), other);
    }

    /** The row with the other page it is of as its hint, when it is one. */
    private static BatchRow hinted(BatchRow row, PanelHint other) {
        return other == null ? row : row.withHint(other);
    }

    /**
     * The share an empty panel gets against simpview's own {@code ours} (of {@code size} pixels a side) under
     * {@code rule}, for the page or scene of {@code label}: measured once. Thread-safe.
     */
    private double emptyShare(String label, RubricRule rule, int[] ours, int size) {
        return emptyShares.computeIfAbsent(label, l -> rule.emptyShare(ours, size));
    }

    /** One picture's progress line: its row's result, or of a page of panels the worst panel's. */
    private static String progress(List<BatchRow> rows) {
        if (rows.size() == 1) {
            return progress(rows.get(0));
        }
        BatchRow worst = rows.stream().filter(BatchRow::compared)
                .min(Comparator.comparingDouble(BatchRow::verdict)).orElse(rows.get(0));
        long passing = rows.stream().filter(r -> r.result() == BatchRow.Result.PASS).count();
        StringBuilder looks = new StringBuilder();
        // the same mistake in several panels said once for them; a page turned whole once for its panels
        PanelHint[] hints = rows.stream().map(BatchRow::panelHint).toArray(PanelHint[]::new);
        for (List<Integer> alike : PanelWords.alike(hints)) {
            PanelHint hint = hints[alike.get(0) - 1];
            looks.append(hint.wholePage() ? "; looks " : "; " + PanelWords.panels(alike)
                    + (alike.size() > 1 ? " look " : " looks ")).append(hint.brief());
        }
        // a note of the picture (its format) is said once, not for each panel
        rows.stream().flatMap(r -> r.briefNotes().stream()).distinct().forEach(note -> looks.append("; ").append(note));
        return (passing == rows.size() ? "PASS: " : "FAIL: ") + passing + " of " + rows.size() + " panels pass; lowest "
                + Percent.of(worst.verdict()) + " (" + worst.target() + ")" + looks;
    }

    private static String progress(BatchRow row) {
        return switch (row.result()) {
            case PASS, FAIL -> row.result() + " " + Percent.of(row.verdict())
                    + (row.panelHint() == null ? "" : "; looks " + row.panelHint().brief())
                    + row.briefNotes().stream().map(note -> "; " + note).collect(Collectors.joining());
            case ERROR, SKIPPED -> row.result() + ": " + row.note().lines().findFirst().orElse("");
        };
    }
}
