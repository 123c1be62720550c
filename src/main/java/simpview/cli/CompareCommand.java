package simpview.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import simpview.cli.CompareOptions.PageRange;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.Count;
import simpview.compare.ComparisonReport;
import simpview.compare.HeatMap;
import simpview.compare.HtmlReport;
import simpview.compare.PanelGridComparison;
import simpview.compare.OtherPage;
import simpview.compare.PanelHint;
import simpview.compare.Percent;
import simpview.compare.Picture;
import simpview.compare.PictureFormat;
import simpview.compare.PngFiles;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.SystematicError;
import simpview.compare.WorstPixel;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.PageContext;
import simpview.pages.ScenePage;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.DrawingThreads;

/** {@code simpview compare ...}: how close a picture is to simpview's own, one picture or a folder of them. */
@Command(name = "compare",
        mixinStandardHelpOptions = true,
        version = ExitCode.VERSION,
        description = "Compares a picture (a 750x750 page or a window capture: its 650x650 panel is found) with the "
                + "page or scene as simpview draws it, and reports the share of panel pixels that match, the margins "
                + "and where they differ. With --dir, compares a whole folder and writes a table (Markdown and CSV).",
        footer = {"", "Examples:",
            "  simpview compare mine.png --page 6 --simp-dir course/ --diff diff.png",
            "  simpview compare pageC.png --scene course-a3/pageC.simp",
            "  simpview compare a1-page2.png --assignment 1 --page 2",
            "  simpview compare --dir subs/ --pages 1-8 --simp-dir course/ --out-dir report/",
            "  simpview compare --dir subs/ --scene course-a3/ --out-dir report/",
            "  simpview compare --dir subs/ --assignment 1 --pages 1-5 --out-dir report/",
            "  simpview compare --dir subs/ --pages 1-8 --simp-dir course/ \\",
            "      --rubric compare.json --gradescope results.json --junit results.xml \\",
            "      --html report/",
            "",
            "A pixel matches with slack when the other picture has its colour within the tolerance at that pixel "
                + "or one of its 8 neighbours (--deviation 2: its 24), both ways round. Regions are panel rectangles: "
                + "origin bottom-left, y up.",
            "Grading (rubric, Gradescope, JUnit, the web report) and 'simpview check': docs/grading.md."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:every picture reaches --min; with --dir, every one that counts, and no submission lacks a "
                + "page asked for",
            "1:some picture is below --min, or cannot be read, or has no panel; with --dir, a page asked for has no "
                + "picture; a scene error; or an output file (a table, a report, a diff image) cannot be written",
            "2:usage error"})
public final class CompareCommand implements Callable<Integer>, NamedOutputs.OfCommand {

    @Spec
    private CommandSpec spec;

    /** The top command, which knows where the project's own scenes are. */
    @ParentCommand
    private SimpviewCommand parent;

    @Parameters(arity = "0..1", paramLabel = "IMAGE", description = "the picture to compare (PNG, JPEG, GIF or BMP)")
    private Path image;

    @Option(names = "--page", paramLabel = "N", description = "compare with page N, 1 to 8 (with --assignment 1: 1 to 5)")
    private Integer page;

    @Option(names = "--assignment", paramLabel = "A",
            description = "1: the first assignment's pages, panel by panel: a picture against its page --page N (1 to 5), "
                    + "or with --dir its pages --pages (default: 1-5), each asked for (not with --scene); 2: the eight "
                    + "pages (default)")
    private Integer assignment;

    @Option(names = "--scene", paramLabel = "F.simp|D",
            description = "compare with this scene drawn as a page; with --dir, a scene file for every picture "
                    + "or a folder whose scenes are matched to the pictures by name")
    private Path scene;

    @Option(names = "--dir", paramLabel = "D", description = "compare every picture in this folder and its subfolders")
    private Path dir;

    @Option(names = "--pages", paramLabel = "RANGE", converter = CompareOptions.PageRangeConverter.class,
            description = "with --dir: the pages pictures are matched to by name (page3.png is page 3), e.g. 1-8, "
                    + "each asked for; with --assignment 1, the first assignment's pages (a1-page3.png is its page 3), "
                    + "1 to 5")
    private PageRange pages;

    @Option(names = "--diff", paramLabel = "OUT.png",
            description = "write ours | theirs | heat map, at 1:1 (the panel; with --assignment 1, each the whole page)")
    private Path diff;

    @Option(names = "--out-dir", paramLabel = "D", description = "with --dir: where the table and the diff images go")
    private Path outDir;

    @Option(names = "--tolerance", paramLabel = "T", converter = CompareOptions.Tolerance.class,
            description = "per channel, in 1/255 steps, for the verdict (with slack) and the regions (default: "
                    + Comparison.DEFAULT_TOLERANCE + ")")
    private int tolerance = Comparison.DEFAULT_TOLERANCE;

    @Option(names = "--min", paramLabel = "P", converter = CompareOptions.Share.class,
            description = "the share in percent that passes (default: " + ComparisonReport.DEFAULT_MINIMUM + ")")
    private double min = ComparisonReport.DEFAULT_MINIMUM;

    @Option(names = "--deviation", paramLabel = "PX", converter = CompareOptions.Deviation.class,
            description = "position deviation, 0, 1 or 2 pixels: a pixel matches when the other picture has its colour "
                    + "within that distance, both ways round (default: 1)")
    private int deviation = Comparison.DEFAULT_DEVIATION;

    @Option(names = "--metric", paramLabel = "M", converter = CompareOptions.MetricConverter.class,
            description = "exact; blur: both panels blurred (3x3 binomial) first; or flip: a pixel matches when its "
                    + "perceptual difference (LDR-FLIP, 67 pixels per degree) is at most --flip-threshold, forgiving another "
                    + "antialiasing (default: exact)")
    private Comparison.Metric metric = Comparison.Metric.EXACT;

    @Option(names = "--flip-threshold", paramLabel = "F", converter = CompareOptions.FlipThreshold.class,
            description = "with --metric flip: the FLIP value, 0 to 1, at or below which a pixel matches (default: 0.13, "
                    + "just above a flat 8/255 difference on mid grey)")
    private Double flipThreshold;

    @Option(names = "--rubric", paramLabel = "F.json",
            description = "per page or pattern, the tolerance, deviation, minimum share, failing-pixel limit, points and "
                    + "accepted alternates (see docs/grading.md); one picture: judged by its page's or scene's rule "
                    + "and its alternates, or with --assignment 1 each panel by its panel's rule")
    private Path rubric;

    @Option(names = "--gradescope", paramLabel = "results.json", description = "with --dir: write Gradescope's results.json")
    private Path gradescope;

    @Option(names = "--junit", paramLabel = "F.xml", description = "with --dir: write JUnit XML, one testcase per picture")
    private Path junit;

    @Option(names = "--html", paramLabel = "D", description = "with --dir: write a web report, D/index.html "
            + "(the diff images go to --out-dir, or to D without it)")
    private Path html;

    @Option(names = "--diffs", paramLabel = "WHICH", converter = CompareOptions.DiffImagesConverter.class,
            description = "with --dir: which pictures get a diff image, all, failing (those that do not pass) or none "
                    + "(default: all)")
    private CompareBatch.DiffImages diffs = CompareBatch.DiffImages.ALL;

    @Option(names = "--partial", description = "with --gradescope: score a failing page in part, by how near it came "
            + "(default: all or nothing)")
    private boolean partial;

    @Mixin
    private OwnPicturesOptions pictures;

    @Mixin
    private ThreadsOption threads;

    /** The files the run reads and writes, once its options are checked; null before. */
    private OutputPaths files;

    @Override
    public List<String> outputFileOptions() {
        return List.of("--diff", "--gradescope", "--junit");
    }

    /**
     * The tables in --out-dir (or in --html's folder without it) and the web report's index.html, which a batch
     * writes whatever else its line says. Its diff images are not known: their names are those of the pictures
     * found in --dir, and which of them get one depends on --diffs and on how each fares.
     */
    @Override
    public List<Path> filesInOutputFolders(String[] args) {
        List<Path> files = new ArrayList<>();
        List<String> tables = List.of(CompareBatch.TABLE, CompareBatch.CSV, CompareBatch.TOTALS);
        files.addAll(NamedOutputs.inFolders("--out-dir", tables, args));
        if (!NamedOutputs.given("--out-dir", args)) {
            files.addAll(NamedOutputs.inFolders("--html", tables, args));
        }
        files.addAll(NamedOutputs.inFolders("--html", List.of(HtmlReport.INDEX), args));
        return files;
    }

    @Override
    public Integer call() {
        int code = ExitCode.SCENE_ERROR;
        try {
            code = compare();
            return code;
        } finally {
            NamedOutputs.releaseAtEnd(files, code, spec, this);
        }
    }

    private int compare() {
        checkOptions();
        if (firstAssignment() && dir == null) {
            return compareAssignment1();
        }
        try (DrawingThreads drawing = threads.open()) {
            OwnPictures own = pictures.ownPictures(parent.ownScenes(), monitor(), drawing);
            if (dir != null) {
                Rubric judged;
                try {
                    judged = rubricOf(rubric, RubricRule.defaults(tolerance, min, deviation, metric, flipThreshold()));
                } catch (CompareException e) {
                    err().println("simpview compare: " + e.getMessage());
                    return ExitCode.USAGE_ERROR;
                }
                CompareBatch batch = new CompareBatch("compare", own, judged, partial, spec.commandLine().getOut(), err());
                files = new OutputPaths().reads(rubric, "the rubric").reads(scene, "the scene");
                CompareBatch.Outputs outputs = new CompareBatch.Outputs(outDir != null ? outDir : html,
                        gradescope, junit, html, false, diffs, files);
                // with one scene for every picture, each picture is a submission of its own, in whatever folder
                boolean eachAlone = pages == null && !firstAssignment() && scene != null && Files.isRegularFile(scene);
                Path graded = eachAlone ? dir : batch.classFolder(dir, outputs, pages == null ? scene : null);
                if (firstAssignment()) {
                    return batch.firstAssignment(graded,
                            pages != null ? pages : CompareOptions.FIRST_ASSIGNMENT_PAGES, outputs);
                }
                return pages != null ? batch.pages(graded, pages, outputs) : batch.scenes(graded, scene, outputs);
            }
            Rubric judged;
            try {
                judged = rubricOf(rubric, verdictRule());
            } catch (CompareException e) {
                err().println("simpview compare: " + e.getMessage());
                return ExitCode.USAGE_ERROR;
            }
            // the other pages a failing picture may be of, drawn only if it fails, their scenes' warnings unsaid
            OtherPages others = new OtherPages(
                    () -> pictures.ownPictures(parent.ownScenes(), SceneMonitor.NONE, drawing), own.context());
            return compareOne(own, page != null ? CompareTarget.page(page) : CompareTarget.scene(scene), others, judged);
        }
    }

    /** Options that make no sense together are usage errors (exit 2), not silently ignored. */
    private void checkOptions() {
        usage(image == null ^ dir == null, image == null ? "give a picture to compare, or --dir D" : "give a picture or --dir D, not both");
        boolean batch = dir != null;
        boolean first = firstAssignment();
        if (batch && first) {
            usage(scene == null, "--assignment 1 grades the first assignment's pages, not scenes: give --pages RANGE "
                    + "(default: 1-5) or leave --scene out");
            usage(pages == null || pages.last() <= Assignment1.COUNT, "--pages " + pages + ": the first assignment has "
                    + "pages 1 to " + Assignment1.COUNT + " (without --assignment 1, --pages names the eight pages)");
        }
        if (batch) {
            usage(Files.isDirectory(dir), Files.exists(dir)
                    ? "--dir " + dir + " is a file, not a folder (one picture: simpview compare " + dir + " --page N)"
                    : "--dir " + dir + ": no such folder");
            usage(first || pages == null ^ scene == null,
                    "--dir needs either --pages RANGE or --scene F.simp|D (or --assignment 1: the first assignment's pages)");
            usage(page == null, "--page goes with one picture; with --dir use --pages RANGE");
            usage(diff == null, "with --dir the diff images go to --out-dir");
            usage(outDir != null || html != null || gradescope != null || junit != null,
                    "--dir needs --out-dir D (the tables and diff images), or --html, --gradescope or --junit");
            usage(outDir == null || !outDir.toString().isEmpty(), "--out-dir needs a folder name");
        } else {
            usage(page != null || scene != null, "say what to compare with: --page N or --scene F.simp");
            usage(page == null || scene == null, "give --page N or --scene F.simp, not both");
            usage(pages == null && outDir == null, "--pages and --out-dir go with --dir");
            usage(gradescope == null && junit == null && html == null && !partial
                    && diffs == CompareBatch.DiffImages.ALL,
                    "--gradescope, --junit, --html, --diffs and --partial go with --dir");
            usage(diff == null || !diff.toString().isEmpty(), "--diff needs a file name");
            usage(diff == null || PngFiles.isPngName(diff), "--diff " + diff + ": " + PngFiles.PNG_ONLY);
            files = new OutputPaths().reads(image, "the picture to compare").reads(scene, "the scene")
                    .reads(rubric, "the rubric").writes(diff, "--diff");
        }
        usage(assignment == null || assignment == 1 || assignment == 2, "--assignment must be 1 or 2, not " + assignment);
        usage(!first || batch || page != null,
                "--assignment 1 compares one picture with one page: give IMAGE --page N, or grade a folder with --dir D");
        int count = first ? Assignment1.COUNT : Assignment2.COUNT;
        usage(page == null || page >= 1 && page <= count,
                "--page must be 1 to " + count + (first ? " for the first assignment" : "") + ", not " + page);
        usage(first || batch || !pictures.a1RuleGiven(), "--a1-rule goes with --assignment 1: it is the rule the first "
                + "assignment's pages are drawn by (with --dir and in check, also for the first assignment's pages found "
                + "among the eight)");
        usage(flipThreshold == null || metric == Comparison.Metric.FLIP || rubric != null,
                "--flip-threshold goes with --metric flip (or a rubric whose rules use it)");
        pictures.check(scene);
        threads.count(); // a count out of range is a usage error whether or not anything is drawn in bands
        if (first) {
            pictures.checkFirstAssignment();
            usage(rubric != null || !spec.commandLine().getParseResult().hasMatchedOption("--deviation"),
                    "--deviation does not go with --assignment 1: the first assignment's panels are judged without "
                            + "slack (which pixels a line drawer lights is the point); a rubric rule may give them one "
                            + "(\"deviation\")");
        }
    }

    /** Whether the first assignment's pages are compared (--assignment 1), not the eight pages or scenes. */
    private boolean firstAssignment() {
        return assignment != null && assignment == 1;
    }

    /** The command line's verdict as a rule: its tolerance, minimum share, slack and metric. */
    private RubricRule verdictRule() {
        return RubricRule.defaults(tolerance, min, deviation, metric, flipThreshold());
    }

    private double flipThreshold() {
        return flipThreshold == null ? Comparison.FLIP_THRESHOLD : flipThreshold;
    }

    private void usage(boolean fine, String message) {
        if (!fine) {
            throw new ParameterException(spec.commandLine(), message);
        }
    }

    /**
     * One picture against its page or scene, judged by {@code rubricRead}'s rule for it (the command line's alone
     * without --rubric), as a batch judges it: against simpview's own picture, and when it fails that, against each
     * of the rule's accepted alternates in turn ({@link Alternates}).
     */
    private int compareOne(OwnPictures own, CompareTarget target, OtherPages others, Rubric rubricRead) {
        RubricRule rule = target.ruleIn(rubricRead);
        Picture theirs;
        Picture ours;
        try {
            ours = own.of(target); // first: a usage problem it finds (cue colours for a lit scene) comes first
            theirs = Picture.read(image);
        } catch (SceneException e) {
            err().println("simpview compare: " + e.getMessage());
            return ExitCode.SCENE_ERROR;
        } catch (CompareException e) {
            err().println("simpview compare: " + (PanelGridComparison.holds(image, FirstAssignmentGrading.panels())
                    ? firstAssignmentsPage(target) : e.getMessage()));
            return ExitCode.SCENE_ERROR;
        }
        // A page of four framed 300x300 panels also frames a 650x650 square (two panels and their gutter): the
        // first assignment's page is what it is.
        if (PanelGridComparison.holds(theirs, FirstAssignmentGrading.panels())) {
            err().println("simpview compare: " + firstAssignmentsPage(target));
            return ExitCode.SCENE_ERROR;
        }
        // The hint's search reads the two panels only, as the comparison does: it runs beside it, on the second
        // core, so that a wrong picture costs the command no more time than a right one (its 60 ms, cold).
        FutureTask<SystematicError> hint = new FutureTask<>(
                () -> SystematicError.find(ours.panel(), theirs.panel(), Comparison.N, rule.tolerance()));
        Thread hinting = new Thread(hint, "simpview-compare-hint");
        hinting.setDaemon(true);
        hinting.start();
        ComparisonReport againstOurs = ComparisonReport.of(theirs, own.describe(target),
                rule.compare(ours.panel(), theirs.panel(), Comparison.N), rule, awaitHint(hint));
        // as a batch judges it: a picture that fails against simpview's own, against each accepted alternate in turn
        List<Alternates.Accepted> alternates = againstOurs.passes() ? List.of() : Alternates.of(rule,
                target.key(), target.isPage() ? CompareBatch::pageNamed : CompareBatch.sceneNamed(scene),
                new HashMap<>(), err(), "simpview compare: ");
        Alternates.Judged judged = Alternates.judge(againstOurs, theirs, own.describe(target), rule, alternates);
        ComparisonReport report = judged.report();
        Comparison comparison = report.comparison();
        // a picture that fails and no mistake explains may be another page, its file named for the wrong one
        PanelHint other = report.passes() || report.systematic() != null || !target.isPage() ? null
                : others.ofEight(target.page(), theirs.panel(), rule);
        PrintWriter out = spec.commandLine().getOut();
        if (rubric != null) {
            out.println("rubric:  " + rubric + ", " + ("*".equals(rule.match()) ? "its defaults (no rule names "
                    + target.key() + ")" : "its rule \"match\": \"" + rule.match() + "\"")
                    + (rule.alternates() == null ? "" : "; its accepted alternates, in " + rule.alternates() + ", "
                            + "are tried when simpview's own fails it"));
        }
        out.print(report.text());
        if (!judged.alternate().isEmpty()) {
            out.println("note: matched the accepted alternate " + judged.alternate() + "; against simpview's own it "
                    + "fails: " + Percent.of(againstOurs.verdictShare()) + " " + againstOurs.verdictName() + " ("
                    + Percent.of(againstOurs.minimum() / 100) + " needed)");
        } else if (!alternates.isEmpty()) {
            out.println("note: it passes against none of the rule's " + Count.of(alternates.size(),
                    "accepted alternate") + " either (in " + rule.alternates() + ")");
        }
        String inspect = inspectCommand(target, report.lookAt());
        if (inspect != null) {
            nextStep(out, "how simpview made that pixel, term by term", inspect);
        }
        if (other != null) {
            out.println("hint: " + other.hint(Comparison.N));
        }
        sayFormat(out, image, report.passes(), theirs.format());
        if (diff != null) {
            try {
                PngFiles.writeEncoded(HeatMap.diffPng(comparison, rule.tolerance()), diff);
                files.wrote(diff);
                out.println("diff:    " + diff + " (" + (judged.alternate().isEmpty() ? "ours"
                        : "the accepted alternate " + judged.alternate()) + " | theirs | heat map: grey identical, blue within "
                        + rule.tolerance() + "/255, yellow one pixel off, red different)");
            } catch (IOException e) {
                err().println("simpview compare: " + e.getMessage());
                return ExitCode.SCENE_ERROR;
            }
        }
        return report.passes() ? ExitCode.OK : ExitCode.SCENE_ERROR;
    }

    /**
     * What a picture that fails, {@code image}, is told of its format, as check tells it ({@link
     * PictureFormat#failingAdvice(String, PictureFormat, boolean)}), by the format its bytes were {@code decoded} as:
     * a right page saved as JPEG fails, and without this the student would look for the fault in their renderer.
     */
    static void sayFormat(PrintWriter out, Path image, boolean passes, PictureFormat decoded) {
        String advice = passes ? "" : PictureFormat.failingAdvice(image.toString(), decoded, true);
        if (!advice.isEmpty()) {
            out.println("note: " + advice);
        }
    }

    /**
     * The command that shows how simpview made the pixel to look at first ({@code look}), with the options that drew
     * the target; null when there is no such pixel, or the target is a page {@code inspect} does not draw (the
     * random pages 1 to 3).
     */
    private String inspectCommand(CompareTarget target, WorstPixel look) {
        if (look == null || target.isPage() && !(Assignment2.page(target.page()) instanceof ScenePage)) {
            return null;
        }
        String what = target.isPage() ? "--page " + target.page()
                : "--scene " + ArgumentLine.shellWord(scene.toString());
        return "simpview inspect " + what + pictures.drawingOptions() + " --at " + look.at() + " --explain";
    }

    /** The hint the search found; an error of its own is the program's and is thrown as such. */
    private static SystematicError awaitHint(FutureTask<SystematicError> hint) {
        try {
            return hint.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null; // the command is being stopped: no hint
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
    }

    /** Why a picture of the first assignment's page is not compared with {@code target}, and what to give instead. */
    private String firstAssignmentsPage(CompareTarget target) {
        boolean samePage = target.isPage() && target.page() <= Assignment1.COUNT;
        return image + " is a page of the first assignment (four 300x300 panels), not a page with one 650x650 panel: "
                + "add --assignment 1 to compare it panel by panel, e.g. simpview compare " + image + " --assignment 1 "
                + "--page " + (samePage ? target.page() : "N (1 to " + Assignment1.COUNT + ")") + pictures.seedOption();
    }

    /**
     * The picture against the first assignment's page, panel by panel ({@link FirstAssignmentComparison}): each panel
     * by the rubric's rule for it with --rubric, as a batch judges it, else by the command line's, without slack.
     */
    private int compareAssignment1() {
        Rubric read;
        try {
            read = rubricOf(rubric, verdictRule());
        } catch (CompareException e) {
            err().println("simpview compare: " + e.getMessage());
            return ExitCode.USAGE_ERROR;
        }
        FirstAssignmentComparison comparison = new FirstAssignmentComparison(image, page, rubric, read,
                pictures.typedOptions("--seed", "--a1-rule"), spec.commandLine().getOut(), err());
        return comparison.compare(context(), diff, files);
    }

    /**
     * The command to run next, on a line of its own that ends with it ({@code next:    simpview inspect ...}), so that
     * all of the line after its label pastes into a shell whole; {@code why}, what it shows, on the line above it,
     * in the same column.
     */
    static void nextStep(PrintWriter out, String why, String command) {
        out.println("         " + why + ":");
        out.println("next:    " + command);
    }

    /** The rubric file read over the command line's rule, or the command line's rule alone. */
    static Rubric rubricOf(Path file, RubricRule base) throws CompareException {
        return file == null ? Rubric.of(base) : Rubric.read(file, base);
    }

    private PageContext context() {
        return pictures.context(parent.ownScenes(), monitor());
    }

    private SceneMonitor monitor() {
        return PageDrawing.warningsTo(err());
    }

    private PrintWriter err() {
        return spec.commandLine().getErr();
    }
}
