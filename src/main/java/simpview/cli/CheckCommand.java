package simpview.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;
import simpview.cli.CompareOptions.PageRange;
import simpview.compare.BatchRow;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.SubmissionNames;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.scene.PlainPath;
import simpview.surface.DrawingThreads;

/**
 * {@code simpview check DIR}: a student's self-check before handing in. Every
 * picture in DIR that names a page (or a scene of --scene) is compared with
 * simpview's, and one table says PASS or FAIL and the worst region of each.
 * The same batch as {@code compare --dir}, printed for one student.
 */
@Command(name = "check",
        mixinStandardHelpOptions = true,
        version = ExitCode.VERSION,
        description = "Checks a folder of your pictures (page1.png ... page8.png, or window captures named so) against "
                + "simpview's pages, a folder of scenes, or the first assignment's pages (--assignment 1), and prints "
                + "one table: pass or fail and the worst region of each. Exit 0 only when every picture found passes "
                + "and no page asked for is missing.",
        footer = {"", "Examples:",
            "  simpview check my-pages/ --simp-dir course/",
            "  simpview check my-a3/ --scene course-a3/",
            "  simpview check my-pages/ --pages 1-3 --seed 7 --out-dir check-report/",
            "  simpview check my-a1/ --assignment 1 --a1-rule course"},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:every picture found passes, and every page asked for has one",
            "1:some picture fails or cannot be read, a page asked for has no picture, no picture was found, a scene "
                + "error, or an output file cannot be written",
            "2:usage error"})
public final class CheckCommand implements Callable<Integer>, NamedOutputs.OfCommand {

    @Spec
    private CommandSpec spec;

    /** The top command, which knows where the project's own scenes are. */
    @ParentCommand
    private SimpviewCommand parent;

    @Parameters(index = "0", paramLabel = "DIR", description = "the folder of your pictures (subfolders too)")
    private Path dir;

    @Option(names = "--pages", paramLabel = "RANGE", converter = CompareOptions.PageRangeConverter.class,
            description = "the pages pictures are matched to by name, each asked for (default: 1-8, asked for only when "
                    + "something in DIR is named like one of them and is not a first-assignment page; a folder of "
                    + "first-assignment pages alone is asked for those, 1 to 5, as with --assignment 1; with "
                    + "--assignment 1, its pages 1 to 5, default 1-5, each asked for)")
    private PageRange pages;

    @Option(names = "--assignment", paramLabel = "A",
            description = "1: the first assignment's pages, panel by panel (a1-page3.png or page3.png is its page 3), "
                    + "those of --pages asked for; not with --scene. 2: the eight pages (default)")
    private Integer assignment;

    @Option(names = "--scene", paramLabel = "F.simp|D",
            description = "instead of the pages: one scene for every picture, or a folder of scenes matched by name")
    private Path scene;

    @Option(names = "--tolerance", paramLabel = "T", converter = CompareOptions.Tolerance.class,
            description = "per channel, in 1/255 steps (default: " + Comparison.DEFAULT_TOLERANCE + ")")
    private int tolerance = Comparison.DEFAULT_TOLERANCE;

    @Option(names = "--min", paramLabel = "P", converter = CompareOptions.Share.class,
            description = "the share in percent that passes (default: " + ComparisonReport.DEFAULT_MINIMUM + ")")
    private double min = ComparisonReport.DEFAULT_MINIMUM;

    @Option(names = "--deviation", paramLabel = "PX", converter = CompareOptions.Deviation.class,
            description = "position deviation, 0, 1 or 2 pixels (default: 1)")
    private int deviation = Comparison.DEFAULT_DEVIATION;

    @Option(names = "--metric", paramLabel = "M", converter = CompareOptions.MetricConverter.class,
            description = "exact, blur or flip (see compare --help; default: exact)")
    private Comparison.Metric metric = Comparison.Metric.EXACT;

    @Option(names = "--flip-threshold", paramLabel = "F", converter = CompareOptions.FlipThreshold.class,
            description = "with --metric flip: the FLIP value, 0 to 1, at or below which a pixel matches (default: 0.13, "
                    + "just above a flat 8/255 difference on mid grey)")
    private Double flipThreshold;

    @Option(names = "--rubric", paramLabel = "F.json", description = "the course's rubric, if it gives you one")
    private Path rubric;

    @Option(names = "--out-dir", paramLabel = "D", description = "also write the tables and diff images here")
    private Path outDir;

    @Mixin
    private OwnPicturesOptions pictures;

    @Mixin
    private ThreadsOption threads;

    /** The files the run reads and writes, once its options are checked; null before. */
    private OutputPaths files;

    /** The rubric a folder carries for itself, used when --rubric does not name one. */
    static final String FOLDER_RUBRIC = "compare.json";

    /** Check names no file of its own: what it writes goes to --out-dir. */
    @Override
    public List<String> outputFileOptions() {
        return List.of();
    }

    /** The tables check writes in --out-dir whatever else its line says (its diff images are named for the pictures). */
    @Override
    public List<Path> filesInOutputFolders(String[] args) {
        return NamedOutputs.inFolders("--out-dir", List.of(CompareBatch.TABLE, CompareBatch.CSV, CompareBatch.TOTALS), args);
    }

    @Override
    public Integer call() {
        int code = ExitCode.SCENE_ERROR;
        try {
            code = check();
            return code;
        } finally {
            // a FIFO in --out-dir the run did not write (a failure, a passing picture's diff, a usage error) would
            // leave its reader waiting
            NamedOutputs.releaseAtEnd(files, code, spec, this);
        }
    }

    private int check() {
        if (pages != null && scene != null) {
            throw new ParameterException(spec.commandLine(), "give --pages or --scene, not both");
        }
        checkAssignment();
        if (!Files.isDirectory(dir)) {
            throw new ParameterException(spec.commandLine(), Files.exists(dir)
                    ? dir + " is a file, not a folder (one picture: simpview compare " + dir + " --page N)"
                    : dir + ": no such folder");
        }
        pictures.check(scene);
        if (flipThreshold != null && metric != Comparison.Metric.FLIP && rubric == null) {
            throw new ParameterException(spec.commandLine(), "--flip-threshold goes with --metric flip (or a rubric whose "
                    + "rules use it)");
        }
        Path rules = rubric != null ? rubric : Files.isRegularFile(dir.resolve(FOLDER_RUBRIC)) ? dir.resolve(FOLDER_RUBRIC) : null;
        if (firstAssignment()) {
            pictures.checkFirstAssignment();
            if (rules == null && spec.commandLine().getParseResult().hasMatchedOption("--deviation")) {
                throw new ParameterException(spec.commandLine(), "--deviation does not go with --assignment 1: the "
                        + "first assignment's panels are judged without slack (which pixels a line drawer lights is "
                        + "the point); a rubric rule may give them one (\"deviation\")");
            }
        }
        Rubric judged;
        try {
            judged = CompareCommand.rubricOf(rules, RubricRule.defaults(tolerance, min, deviation, metric,
                    flipThreshold == null ? Comparison.FLIP_THRESHOLD : flipThreshold));
        } catch (CompareException e) {
            spec.commandLine().getErr().println("simpview check: " + e.getMessage());
            return ExitCode.USAGE_ERROR;
        }
        if (rubric == null && rules != null) {
            spec.commandLine().getErr().println("rubric: " + rules + " (the folder's own)");
        }
        try (DrawingThreads drawing = threads.open()) {
            OwnPictures own = pictures.ownPictures(parent.ownScenes(),
                    PageDrawing.warningsTo(spec.commandLine().getErr()), drawing);
            CompareBatch batch = new CompareBatch("check", own, judged, false, spec.commandLine().getOut(),
                    spec.commandLine().getErr(), pages == null && !firstAssignment()).nextSteps(this::compareCommand);
            files = new OutputPaths().reads(rules, "the rubric").reads(scene, "the scene");
            CompareBatch.Outputs outputs = new CompareBatch.Outputs(outDir, null, null, null, true,
                    CompareBatch.DiffImages.FAILING, files);
            if (scene != null) {
                return batch.scenes(dir, scene, outputs);
            }
            if (firstAssignment()) {
                return batch.firstAssignment(dir, pages != null ? pages : CompareOptions.FIRST_ASSIGNMENT_PAGES, outputs);
            }
            return batch.folder(dir, pages != null ? pages : ALL_PAGES, outputs);
        }
    }

    /**
     * The command that compares a failing row's picture alone, with this check's options, and writes its diff image
     * beside where it is run: its report names the pixel to look at first and the command that explains it. Null
     * when the picture or its scene is not where the row says (a picture named in another way).
     */
    private String compareCommand(BatchRow row) {
        Path rules = rubric != null ? rubric : Files.isRegularFile(dir.resolve(FOLDER_RUBRIC))
                ? dir.resolve(FOLDER_RUBRIC) : null;
        // the rubric is read over the options as typed, as here: the picture alone is judged by its page's rule
        String verdict = pictures.typedOptions("--tolerance", "--min", "--deviation", "--metric", "--flip-threshold")
                + rubricOption(rules);
        // the first assignment's pages are compared without slack: --deviation goes with them only with a rubric, whose
        // panel rules judge a page of them alone as they judged it here
        String firstVerdict = rules == null ? pictures.typedOptions("--tolerance", "--min", "--metric",
                "--flip-threshold") : verdict;
        return compareCommand(dir, scene, row, pictures.drawingOptions() + verdict,
                pictures.typedOptions("--seed", "--a1-rule") + firstVerdict);
    }

    /** " --rubric F.json" of the rubric a batch was judged by, as a shell reads it back; "" for none. */
    private static String rubricOption(Path rules) {
        return rules == null ? "" : " --rubric " + ArgumentLine.shellWord(rules.toString());
    }

    /**
     * The command that compares the picture of a failing row ({@code dir}'s {@code row.file()}) alone with what it
     * was compared with: a page of the eight pages, a scene of {@code scene} (a file, or a folder of them; null:
     * none), or a page of the first assignment ("A1 page 2 panel 4 (antialiased)": --assignment 1 --page 2). The
     * options as typed follow: {@code options} those that draw the eight pages and the scenes and judge them,
     * {@code firstOptions} those that draw the first assignment's pages and judge them (without slack). Null when
     * the picture or its scene is not where the row says.
     */
    static String compareCommand(Path dir, Path scene, BatchRow row, String options, String firstOptions) {
        Path picture = PlainPath.of(dir.resolve(row.file())); // of the folder ".": page1.png, not ./page1.png
        if (!Files.isRegularFile(picture)) {
            return null;
        }
        String what;
        Matcher first = FIRST_ASSIGNMENT_PAGE.matcher(row.target());
        if (first.lookingAt()) {
            what = "--assignment 1 --page " + first.group(1) + firstOptions;
        } else if (scene != null) {
            Path file = PlainPath.of(Files.isDirectory(scene) ? scene.resolve(row.target()) : scene);
            if (!Files.isRegularFile(file)) {
                return null;
            }
            what = "--scene " + ArgumentLine.shellWord(file.toString()) + options;
        } else {
            Matcher number = PAGE_NUMBER.matcher(row.target());
            if (!number.matches()) {
                return null; // a scene of the folder's own (3d.simp), not a page
            }
            what = "--page " + number.group(1) + options;
        }
        String diff = SubmissionNames.stem(picture.getFileName().toString()) + "-diff.png";
        return "simpview compare " + ArgumentLine.shellWord(picture.toString()) + " " + what + " --diff "
                + ArgumentLine.shellWord(diff);
    }

    /** The page of the first assignment a row's target names: "A1 page 2 panel 4 (antialiased)" is its page 2. */
    private static final Pattern FIRST_ASSIGNMENT_PAGE = Pattern.compile("A1 page ([0-9]+)");

    /** A row's target that is a page of the eight, and its number: "6", "2 (seed 361)". */
    private static final Pattern PAGE_NUMBER = Pattern.compile("([0-9]+)(?: \\(seed -?[0-9]+\\))?");

    /** Whether the first assignment's pages are checked (--assignment 1), not the eight pages or scenes. */
    private boolean firstAssignment() {
        return assignment != null && assignment == 1;
    }

    /** --assignment is 1 or 2; with 1, --pages names pages 1 to 5 of it, and there is no --scene. */
    private void checkAssignment() {
        if (assignment != null && assignment != 1 && assignment != 2) {
            throw new ParameterException(spec.commandLine(), "--assignment must be 1 or 2, not " + assignment);
        }
        if (firstAssignment() && scene != null) {
            throw new ParameterException(spec.commandLine(), "--assignment 1 checks the first assignment's pages, not "
                    + "scenes: give --pages RANGE (default: 1-5) or leave --scene out");
        }
        if (firstAssignment() && pages != null && pages.last() > Assignment1.COUNT) {
            throw new ParameterException(spec.commandLine(), "--pages " + pages + ": the first assignment has pages 1 "
                    + "to " + Assignment1.COUNT + " (without --assignment 1, --pages names the eight pages)");
        }
    }

    private static final CompareOptions.PageRange ALL_PAGES = new CompareOptions.PageRangeConverter().convert("1-8");

    /**
     * A folder dropped on the window: {@code simpview check FOLDER} with the window's seed and scene folder
     * and today's defaults, the folder's own compare.json as the rubric and its scenes with their pictures;
     * the table as check prints it (or, when there is none, what went wrong). Runs on the caller's thread.
     */
    public static String checkFolder(Path folder, PageContext context) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        PrintWriter errors = new PrintWriter(err, true);
        Path rules = Files.isRegularFile(folder.resolve(FOLDER_RUBRIC)) ? folder.resolve(FOLDER_RUBRIC) : null;
        Rubric judged;
        try {
            judged = CompareCommand.rubricOf(rules, RubricRule.defaults(Comparison.DEFAULT_TOLERANCE,
                    ComparisonReport.DEFAULT_MINIMUM, Comparison.DEFAULT_DEVIATION, Comparison.Metric.EXACT));
        } catch (CompareException e) {
            return e.getMessage() + "\n";
        }
        try (DrawingThreads drawing = DrawingThreads.one()) {
            OwnPictures own = new OwnPictures(context, null, null, false, PageDrawing.warningsTo(errors), drawing);
            // the command that compares a failing picture alone, drawn as the window draws it
            String seed = context.seed() == PageContext.DEFAULT_SEED ? "" : " --seed " + context.seed();
            String simpDir = context.simpDir() == null || context.simpDir().equals(context.ownSimpDir()) ? ""
                    : " --simp-dir " + ArgumentLine.shellWord(context.simpDir().toString());
            String rule = context.a1Rule() == A1Rule.SPEC ? "" : " --a1-rule " + context.a1Rule().key();
            CompareBatch batch = new CompareBatch("check", own, judged, false, new PrintWriter(out, true), errors,
                    true).nextSteps(row -> compareCommand(folder, null, row, simpDir + seed + rubricOption(rules),
                            seed + rule + rubricOption(rules)));
            batch.folder(folder, ALL_PAGES, new CompareBatch.Outputs(null, null, null, null, true,
                    CompareBatch.DiffImages.NONE, new OutputPaths()));
        }
        String table = out.toString();
        int none = err.toString().indexOf("no pictures (");
        if (none >= 0) {
            // and what it holds instead, when that tells (a zip: unzip it)
            String said = err.toString().substring(none).lines().findFirst().orElse("");
            int instead = said.indexOf(": it ");
            return "No pictures (.png, .jpg, .gif, .bmp) in " + folder + (instead < 0 ? "" : said.substring(instead))
                    + ".\n";
        }
        if (table.isEmpty()) {
            return err.toString(); // the batch stopped before comparing (a scene simpview cannot draw): why
        }
        return (rules == null ? "" : "rubric: " + rules.getFileName() + " (the folder's own)\n") + table;
    }
}
