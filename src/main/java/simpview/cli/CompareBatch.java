package simpview.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BiPredicate;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import simpview.cli.CompareOptions.PageRange;
import simpview.compare.BatchRow;
import simpview.compare.Count;
import simpview.compare.HtmlReport;
import simpview.compare.OutputFiles;
import simpview.compare.PanelGridComparison;
import simpview.compare.Picture;
import simpview.compare.Rubric;
import simpview.compare.SubmissionNames;
import simpview.compare.SubmissionTotals;
import simpview.compare.Wanted;
import simpview.compare.WithoutPictures;
import simpview.pages.A1Layout;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.PageContext;
import simpview.pages.SceneList;
import simpview.pages.ScenePage;
import simpview.scene.FileProblem;
import simpview.scene.SceneException;

/**
 * {@code simpview compare --dir ...}: every picture in a folder (and its
 * subfolders) against the page or scene its name names, one table row each.
 * A picture that cannot be read is a row saying why; the rest go on.
 *
 * A batch finds what was handed in ({@link HandedIn}), matches each picture to
 * a page or scene by its name, draws those, compares each picture with
 * simpview's ({@link PictureComparisons}; a page of the first assignment panel
 * by panel, {@link FirstAssignmentGrading}), works out what each submission was
 * asked for ({@link PagesAskedFor}) and writes the results ({@link BatchResults}).
 */
public final class CompareBatch {

    static final String TABLE = "compare.md";
    static final String CSV = "compare.csv";
    /** Each submission's total, for a gradebook to import ({@link SubmissionTotals}), beside the table. */
    static final String TOTALS = "totals.csv";
    static final String DIFFS = "diffs";

    /**
     * The order the pages and scenes simpview cannot draw are named in: pages by number, then scenes by name in
     * natural order (pageA ... pageJ), not the order the pictures that need them happen to come in.
     */
    private static final Comparator<CompareTarget> MENTIONED_IN_ORDER =
            Comparator.comparing((CompareTarget target) -> !target.isPage()).thenComparingInt(CompareTarget::page)
                    .thenComparing(target -> target.scene().getFileName().toString(), SceneList.NATURAL_ORDER);

    /**
     * What a picture's name matched: a target, a page of the first assignment (compared panel by
     * panel), or why it was skipped; {@code alone}: the picture is a submission of its own (one scene for
     * every picture: one picture a student), not one of its folder's.
     */
    record Match(CompareTarget target, String skipped, int firstAssignmentPage, boolean alone) {

        Match(CompareTarget target, String skipped) {
            this(target, skipped, 0, false);
        }

        Match(CompareTarget target, String skipped, int firstAssignmentPage) {
            this(target, skipped, firstAssignmentPage, false);
        }

        /** A picture of the one scene every picture is compared with: a student's, whatever folder it is in. */
        static Match alone(CompareTarget target) {
            return new Match(target, null, 0, true);
        }
    }

    /**
     * Where the results go. {@code outDir} (null: no files but the ones named) holds the
     * tables and diff images; the others are written when not null. {@code student}: print
     * the student's table ({@code simpview check}) instead of the teacher's. {@code files}:
     * the files the command reads besides the pictures (its rubric, its scene), which the
     * batch adds the pictures to and holds every file it writes against.
     */
    record Outputs(Path outDir, Path gradescope, Path junit, Path html, boolean student, DiffImages diffs,
            OutputPaths files) {

        /**
         * Why the results could not be written where they go, as far as can be known before anything is
         * written ("--out-dir r: /home/t/r is in the way: it is a file, not a folder"); null when nothing
         * is known to stop them.
         */
        String problem() {
            for (Report report : reports()) {
                String why = OutputFiles.fileProblem(report.file());
                if (why != null) {
                    return report.option() + " " + report.given() + ": " + why;
                }
            }
            return null;
        }

        /** Every table and report file the batch writes (not its diff images), in the order it writes them. */
        List<Report> reports() {
            List<Report> reports = new ArrayList<>();
            if (outDir != null) {
                reports.add(new Report(outDir.resolve(TABLE), outDirOption(), outDir));
                reports.add(new Report(outDir.resolve(CSV), outDirOption(), outDir));
                reports.add(new Report(outDir.resolve(TOTALS), outDirOption(), outDir));
            }
            if (gradescope != null) {
                reports.add(new Report(gradescope, "--gradescope", gradescope));
            }
            if (junit != null) {
                reports.add(new Report(junit, "--junit", junit));
            }
            if (html != null) {
                reports.add(new Report(html.resolve(HtmlReport.INDEX), "--html", html));
            }
            return reports;
        }

        /** The option that names the folder of the tables and diff images: --out-dir, or --html without it. */
        String outDirOption() {
            return outDir != null && outDir.equals(html) ? "--html" : "--out-dir";
        }
    }

    /** A file the batch writes, the option that names it and what was given with that option (a file or its folder). */
    record Report(Path file, String option, Path given) {
    }

    /** Which pictures get a diff image: every one compared, only those that do not pass, or none. */
    enum DiffImages { ALL, FAILING, NONE }

    private final OwnPictures own;
    private final Rubric rubric;
    /** How the first assignment's pages are graded, panel by panel. */
    private final FirstAssignmentGrading firstAssignmentGrading;
    /** What was handed in to the folder graded, and the class's folder in the one given. */
    private final HandedIn handedIn;
    /** The comparisons, picture by picture. */
    private final PictureComparisons comparisons;
    /** What each submission is asked for. */
    private final PagesAskedFor pagesAskedFor;
    /** The results, written and printed. */
    private final BatchResults results;
    private final PrintWriter err;
    /** What its messages start with: the command that runs it ("simpview compare: "). */
    private final String says;
    /**
     * Whether the pages of the range are asked for only when something handed in is named like one of them
     * ({@code check} without --pages): a folder of the first assignment's pages, or of its own scenes and
     * their pictures, is not asked for the eight pages.
     */
    private final boolean pagesIfHandedIn;
    /**
     * The pictures that are first-assignment pages where the eight pages were asked for by --pages (so not graded
     * as such: skipped by name, or scored 0 as the page of the eight their name names), by their paths under the
     * folder: the teacher who meant --assignment 1 is told so when every picture is one.
     */
    private final Set<String> firstAssignmentUnasked = ConcurrentHashMap.newKeySet();

    /** A batch of {@code command} ("compare", "check"), which its messages name; every page of the range asked for. */
    CompareBatch(String command, OwnPictures own, Rubric rubric, boolean partial, PrintWriter out, PrintWriter err) {
        this(command, own, rubric, partial, out, err, false);
    }

    /** The same, the pages of the range asked for only when something handed in is named like one of them. */
    CompareBatch(String command, OwnPictures own, Rubric rubric, boolean partial, PrintWriter out, PrintWriter err,
            boolean pagesIfHandedIn) {
        this.says = "simpview " + command + ": ";
        this.own = own;
        this.rubric = rubric;
        // the pages a failing picture may be of instead, drawn once, if ever
        OtherPages others = new OtherPages(own);
        this.firstAssignmentGrading = new FirstAssignmentGrading(own.context(), others, rubric, partial);
        this.handedIn = new HandedIn(rubric, err, says);
        this.err = err;
        this.pagesIfHandedIn = pagesIfHandedIn;
        this.comparisons = new PictureComparisons(own, others, rubric, partial, firstAssignmentGrading, handedIn, err,
                pagesIfHandedIn, firstAssignmentUnasked);
        this.pagesAskedFor = new PagesAskedFor(own.context(), rubric, firstAssignmentGrading, handedIn, pagesIfHandedIn,
                firstAssignmentUnasked, err, says);
        this.results = new BatchResults(rubric, out, err, says);
    }

    /**
     * This batch, its student's table ({@code check}) followed by {@code command} of each failing row for which it
     * gives one: the one picture's comparison, which says where and why it differs.
     */
    CompareBatch nextSteps(Function<BatchRow, String> command) {
        results.nextSteps(command);
        return this;
    }

    /**
     * The folder a teacher's batch of {@code dir} grades, whose first-level folders are the submissions: {@code dir}
     * itself or the class's folder inside it, as {@link HandedIn#classFolder} finds it. The batch names its pictures
     * in that folder from then on.
     */
    Path classFolder(Path dir, Outputs outputs, Path sceneFolder) {
        return handedIn.classFolder(dir, outputs, sceneFolder);
    }

    /** Pictures matched to pages by the number in their names: page3.png is page 3. */
    int pages(Path dir, PageRange pages, Outputs outputs) {
        List<CompareTarget> wanted = new ArrayList<>();
        for (int p = 1; p <= Assignment2.COUNT; p++) {
            if (pages.contains(p)) {
                wanted.add(CompareTarget.page(p));
            }
        }
        warnUnusedRules(pageSubjects(pages));
        return run(dir, outputs, wanted, Set.of(), CompareBatch::pageNamed, relative -> pageMatch(dir, relative, pages));
    }

    /** The rubric key of the page a file's name names ("page3" of page3.png), for the alternates; none: empty. */
    static Optional<String> pageNamed(String name) {
        OptionalInt n = SubmissionNames.pageNumber(name);
        return n.isPresent() ? Optional.of("page" + n.getAsInt()) : Optional.empty();
    }

    /**
     * The first assignment's pages ({@code --assignment 1}): a picture whose name has a page number (a1-page3.png,
     * page3.png) is that page of the first assignment, compared panel by panel, and every page of {@code pages}
     * (1 to 5) is asked for: a submission without a picture of one has a MISSING row for it, worth its four
     * panels' points.
     */
    int firstAssignment(Path dir, PageRange pages, Outputs outputs) {
        Set<Integer> asked = new TreeSet<>();
        for (int page = 1; page <= Assignment1.COUNT; page++) {
            if (pages.contains(page)) {
                asked.add(page);
            }
        }
        warnUnusedRules(FirstAssignmentGrading.subjects(asked));
        // nothing of the eight pages or of a scene is drawn, so no alternate is looked for by its name
        return run(dir, outputs, List.of(), asked, name -> Optional.empty(),
                relative -> FirstAssignmentGrading.match(HandedIn.fileName(relative), pages, "--pages " + pages));
    }

    /** The page a picture's name names: one of the eight (if among {@code pages}), or of the first assignment. */
    private Match pageMatch(Path dir, String relative, PageRange pages) {
        String name = HandedIn.fileName(relative);
        OptionalInt number = SubmissionNames.pageNumber(name);
        if (number.isPresent() && FirstAssignmentGrading.namesFirstAssignment(relative)) {
            if (pagesIfHandedIn) {
                return FirstAssignmentGrading.match(name, null, null); // check without --pages: compared as its own page
            }
            // --pages names the eight pages: only those are graded, and asked of everyone. A picture whose own name
            // says first assignment (a1-page5.png) is none of them, whatever it holds: one of the wrong size is no
            // page 5 of the eight (as check without --pages names it A1 page 5), so no ERROR row of page 5 nor a
            // candidate beside page5.png.
            if (SubmissionNames.namesFirstAssignment(name)) {
                int page = number.getAsInt();
                if (page > Assignment1.COUNT) {
                    return new Match(null, "the first assignment has pages 1 to " + Assignment1.COUNT + ", not " + page
                            + ", and --pages names the eight pages");
                }
                firstAssignmentUnasked.add(relative);
                return new Match(null, "a page of the first assignment by its name, and --pages names the eight "
                        + "pages (" + FirstAssignmentGrading.HOW_GRADED + ")");
            }
            // Only a folder on its way says so: one that holds no first-assignment page (A1-Smith/page1.png, a
            // student's folder) is the page its number names.
            if (PanelGridComparison.holds(handedIn.file(dir, relative), FirstAssignmentGrading.panels())) {
                firstAssignmentUnasked.add(relative);
                return new Match(null, "a page of the first assignment by its folder's name and its four panels, and "
                        + "--pages names the eight pages (" + FirstAssignmentGrading.HOW_GRADED + ")");
            }
        }
        if (number.isEmpty()) {
            return new Match(null, SubmissionNames.noPageNumber(name, "page", Assignment2.COUNT));
        }
        if (!pages.contains(number.getAsInt())) {
            return new Match(null, "page " + number.getAsInt() + " is not among --pages " + pages);
        }
        return new Match(CompareTarget.page(number.getAsInt()), null);
    }

    /**
     * A student's folder as {@code check DIR} (and a folder dropped on the window) takes it: a picture whose
     * name names a scene of the folder itself (house.png beside house.simp) is compared with that scene;
     * any other with the page its name names, as {@link #pages} does. Without scenes in the folder it is
     * {@link #pages} exactly. The pages asked for (reported missing) are {@code pages}; the folder's
     * scenes asked for are those a picture matched or the rubric names.
     */
    int folder(Path dir, PageRange pages, Outputs outputs) {
        Map<String, Path> scenes = Files.isDirectory(dir) ? scenesIn(dir) : Map.of();
        if (scenes.isEmpty()) {
            return pages(dir, pages, outputs);
        }
        List<CompareTarget> wanted = new ArrayList<>();
        for (int p = 1; p <= Assignment2.COUNT; p++) {
            if (pages.contains(p)) {
                wanted.add(CompareTarget.page(p));
            }
        }
        scenes.entrySet().stream()
                .filter(e -> rubric.rules().stream().anyMatch(r -> r.match().trim().equals(e.getKey())))
                .forEach(e -> wanted.add(CompareTarget.scene(e.getValue())));
        Map<String, Integer> subjects = pageSubjects(pages);
        scenes.keySet().forEach(name -> subjects.put(name, 0));
        warnUnusedRules(subjects);
        Function<String, Optional<String>> namer = name -> {
            Optional<String> scene = SubmissionNames.sceneName(name, scenes.keySet());
            return scene.isPresent() ? scene : pageNamed(name);
        };
        return run(dir, outputs, wanted, Set.of(), namer, relative -> {
            Optional<String> named = SubmissionNames.sceneName(HandedIn.fileName(relative), scenes.keySet());
            return named.map(name -> new Match(CompareTarget.scene(scenes.get(name)), null))
                    .orElseGet(() -> pageMatch(dir, relative, pages));
        });
    }

    /**
     * The rubric key of the scene a file's name names, among those of {@code scene}'s folder, for the alternates of
     * one scene file: an alternate named for another scene beside it (pageD_v2.png beside pageC.simp) is not pageC's,
     * as it is not when the folder is given; none: empty.
     */
    static Function<String, Optional<String>> sceneNamed(Path scene) {
        Path folder = scene.toAbsolutePath().getParent();
        Set<String> names = folder == null ? Set.of() : scenesIn(folder).keySet();
        return name -> SubmissionNames.sceneName(name, names);
    }

    /**
     * A scene's name for the example of a picture's name: the first named like a page (pageA), not a file the
     * pages include (cube), when there is one.
     */
    private static String exampleScene(Collection<String> names) {
        return names.stream().filter(n -> n.toLowerCase(Locale.ROOT).startsWith("page")).findFirst()
                .orElse(names.iterator().next());
    }

    /**
     * Every picture against one scene file, or against the scene of a folder that its name names. A scene file
     * may be named without .simp ({@link SceneList#scene}), as compare, render and inspect take it.
     */
    int scenes(Path dir, Path given, Outputs outputs) {
        Path scene = orWithExtension(given);
        if (Files.isRegularFile(scene)) {
            warnUnusedRules(Map.of(SubmissionNames.stem(scene.getFileName().toString()), 0));
            return run(dir, outputs, List.of(CompareTarget.scene(scene)), Set.of(), sceneNamed(scene),
                    relative -> Match.alone(CompareTarget.scene(scene)));
        }
        if (!Files.isDirectory(scene)) {
            err.println(says + "--scene " + scene + ": no such file or folder");
            return ExitCode.USAGE_ERROR;
        }
        Map<String, Path> scenes;
        try {
            scenes = scenesOf(scene);
        } catch (IllegalArgumentException e) {
            err.println(says + "--scene " + scene + ": " + e.getMessage());
            return ExitCode.USAGE_ERROR;
        }
        if (scenes.isEmpty()) {
            err.println(says + "--scene " + scene + ": no .simp files in that folder");
            return ExitCode.USAGE_ERROR;
        }
        // A folder also holds scenes the pages include (cube.simp): the ones asked for are those a rubric
        // rule names, and (in run) every one some picture of the batch was matched to.
        List<CompareTarget> wanted = scenes.entrySet().stream()
                .filter(e -> rubric.rules().stream().anyMatch(r -> r.match().trim().equals(e.getKey())))
                .map(e -> CompareTarget.scene(e.getValue())).toList();
        Map<String, Integer> subjects = new HashMap<>();
        scenes.keySet().forEach(name -> subjects.put(name, 0));
        warnUnusedRules(subjects);
        return run(dir, outputs, wanted, Set.of(), name -> SubmissionNames.sceneName(name, scenes.keySet()), relative -> {
            Optional<String> named = SubmissionNames.sceneName(HandedIn.fileName(relative), scenes.keySet());
            return named.map(s -> new Match(CompareTarget.scene(scenes.get(s)), null))
                    .orElseGet(() -> new Match(null, "its name names none of the scenes in " + scene
                            + " (expected a name like " + exampleScene(scenes.keySet()) + ".png)"));
        });
    }

    /** {@code named}, or it with .simp added when only that is a file ({@link SceneList#scene}). */
    private static Path orWithExtension(Path named) {
        if (Files.exists(named)) {
            return named;
        }
        try {
            return SceneList.scene(named);
        } catch (IllegalArgumentException e) {
            return named; // neither is there: the caller says so
        }
    }

    /**
     * The rubric keys of the pages of {@code pages} (with their numbers, for a rule's page range) and of every
     * panel of the first assignment's pages, which a picture so named brings whatever --pages says.
     */
    private static Map<String, Integer> pageSubjects(PageRange pages) {
        Map<String, Integer> subjects = new HashMap<>();
        for (int p = 1; p <= Assignment2.COUNT; p++) {
            if (pages.contains(p)) {
                subjects.put("page" + p, p);
            }
        }
        subjects.putAll(FirstAssignmentGrading.subjects(
                IntStream.rangeClosed(1, Assignment1.COUNT).boxed().collect(Collectors.toSet())));
        return subjects;
    }

    /**
     * Says on stderr which rubric rules fit none of the pages and scenes this run can compare, before it
     * starts: a mistyped "match" would otherwise leave its pages to the defaults without a word. A warning
     * only: one rubric may serve several assignments.
     */
    private void warnUnusedRules(Map<String, Integer> subjects) {
        rubric.unusedRules(subjects).forEach(unused -> err.println(says + "warning: " + unused));
    }

    /**
     * Compares the pictures under {@code dir} and writes the results. {@code wanted}: the pages and scenes asked
     * for; {@code firstAssignmentWanted}: the first assignment's pages asked for (besides those some picture is
     * of); {@code namer}: the rubric key a file name names, for the alternates; {@code matcher}: what a picture
     * (its path under {@code dir}) is compared with.
     */
    private int run(Path dir, Outputs outputs, List<CompareTarget> wanted, Set<Integer> firstAssignmentWanted,
            Function<String, Optional<String>> namer, Function<String, Match> matcher) {
        HandedIn.Found found;
        try {
            found = handedIn.find(dir, outputs);
        } catch (IOException e) {
            err.println(says + unlisted(dir, e));
            return ExitCode.USAGE_ERROR;
        } catch (UncheckedIOException e) {
            err.println(says + unlisted(dir, e.getCause()));
            return ExitCode.USAGE_ERROR;
        }
        handedIn.sayWhatWasFound(dir, found);
        List<Path> pictures = found.pictures();
        DiffNames diffNames = DiffNames.of(pictures.stream().map(p -> handedIn.name(dir, p)).toList());
        claimOutputs(dir, pictures, outputs, diffNames);
        String unwritable = outputs.problem();
        if (unwritable != null) {
            err.println(says + "cannot write the results: " + unwritable);
            return ExitCode.SCENE_ERROR;
        }
        long start = System.nanoTime();
        List<Match> matches = new ArrayList<>();
        for (Path picture : pictures) {
            matches.add(matcher.apply(handedIn.name(dir, picture)));
        }
        boolean oneStudent = handedIn.oneStudent(dir, outputs, pictures, matches.stream().anyMatch(Match::alone));
        Map<CompareTarget, Picture> drawn = new HashMap<>();
        Map<CompareTarget, SceneException> undrawable = drawAll(pictures, matches, drawn);
        if (!undrawable.isEmpty()) {
            err.print(stopped(undrawable, dir));
            return ExitCode.SCENE_ERROR;
        }
        Map<Integer, BufferedImage> firstAssignment = firstAssignmentGrading.draw(matches);
        Map<CompareTarget, List<Alternates.Accepted>> alternates = alternatesOf(drawn.keySet(), namer);
        DiffPlan diffPlan = new DiffPlan(outputs.outDir(), outputs.diffs(), diffNames, outputs.files());
        List<BatchRow> rows = comparisons.rows(dir, pictures, matches, drawn, firstAssignment, alternates, diffPlan,
                picture -> found.listing().linkOut(picture, dir));
        double seconds = (System.nanoTime() - start) / 1e9;
        err.printf(Locale.ROOT, "%s in %.2f s%n", Count.of(pictures.size(), "picture"), seconds);
        noteIfFirstAssignmentOnly(wanted, rows);
        List<Wanted> asked = pagesAskedFor.of(dir, found, matches, rows, oneStudent, wanted, firstAssignmentWanted,
                firstAssignment.keySet(), matcher);
        int written = writeResults(dir, found, matches, rows, asked, outputs, seconds, oneStudent);
        noteEarlierDiffs(outputs.outDir(), rows);
        return results.saidUnwrittenDiffs(rows, diffPlan) ? ExitCode.SCENE_ERROR : written;
    }

    /** How many of an earlier run's diff images the note names before "and N more". */
    private static final int EARLIER_DIFFS_NAMED = 3;

    /**
     * Names the diff images in the out folder's diffs that this run did not write: an earlier run's, of pictures
     * that pass now (under --diffs failing) or are gone, which no row of this run links. They are left where
     * they are (the folder may hold what a teacher keeps), and the note says what they are.
     */
    private void noteEarlierDiffs(Path outDir, List<BatchRow> rows) {
        if (outDir == null) {
            return;
        }
        Path folder = outDir.resolve(DIFFS);
        Set<Path> thisRun = new HashSet<>();
        rows.stream().map(BatchRow::diff).filter(diff -> !diff.isEmpty())
                .forEach(diff -> thisRun.add(outDir.resolve(diff).normalize()));
        List<String> earlier = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "*" + DiffNames.ENDING)) {
            for (Path file : files) {
                if (!thisRun.contains(file.normalize())) {
                    earlier.add(file.getFileName().toString());
                }
            }
        } catch (IOException | UncheckedIOException e) {
            return; // no such folder, or one that cannot be listed: nothing of an earlier run to name
        }
        if (earlier.isEmpty()) {
            return;
        }
        Collections.sort(earlier);
        int more = earlier.size() - EARLIER_DIFFS_NAMED;
        String named = String.join(", ", earlier.subList(0, Math.min(EARLIER_DIFFS_NAMED, earlier.size())))
                + (more > 0 ? " and " + more + " more" : "");
        err.println(says + "note: " + folder + " also holds " + Count.of(earlier.size(), "diff image")
                + " this run did not write (" + named + "): an earlier run's, which no row of this one links; they "
                + "are left as they are");
    }

    /**
     * Every file the batch will write, held against those it reads (the pictures, the accepted
     * alternates and the command's own) and against each other, before anything is compared.
     *
     * @throws UsageProblem when one would overwrite a file read, or two are one file
     */
    private void claimOutputs(Path dir, List<Path> pictures, Outputs outputs, DiffNames diffNames) {
        OutputPaths files = outputs.files();
        pictures.forEach(picture -> files.reads(picture, "a picture to compare"));
        Set<Path> alternates = new HashSet<>();
        rubric.rules().forEach(rule -> alternates.add(rule.alternates()));
        alternates.add(rubric.defaults().alternates());
        alternates.remove(null);
        for (Path folder : alternates) {
            try {
                Alternates.picturesIn(folder).forEach(picture -> files.reads(picture, "an accepted alternate picture"));
            } catch (IOException | UncheckedIOException e) {
                // said when the alternates are read
            }
        }
        for (Report report : outputs.reports()) {
            files.writes(report.file(), report.option());
        }
        Path outDir = outputs.outDir();
        String tables = outputs.outDirOption();
        if (outDir != null && outputs.diffs() != DiffImages.NONE) {
            for (Path picture : pictures) {
                String relative = handedIn.name(dir, picture);
                for (int panel = 0; panel <= A1Layout.PANELS; panel++) {
                    files.mayWrite(outDir.resolve(diffNames.of(relative, panel)), tables);
                }
            }
        }
    }

    /**
     * Why the pictures under {@code dir} could not be found, as {@code e} says: the folder, or the one below it
     * that could not be read (a student's, copied without read access), and why: "class/bob: cannot be listed
     * (permission denied), so nothing in class was graded"; "class: no such folder" when it is gone.
     */
    static String unlisted(Path dir, IOException e) {
        if (!Files.isDirectory(dir)) {
            return dir + ": no such folder";
        }
        Path folder = e instanceof FileSystemException system && system.getFile() != null
                ? Path.of(system.getFile()) : dir;
        return folder + ": cannot be listed (" + FileProblem.ofFolder(e) + "), so nothing in " + dir + " was graded";
    }

    /**
     * Draws each page or scene the pictures need into {@code drawn}, once, in order (the canvas is one); the
     * error of each that simpview cannot draw is returned, in order (none when all were drawn).
     */
    private Map<CompareTarget, SceneException> drawAll(List<Path> pictures, List<Match> matches,
            Map<CompareTarget, Picture> drawn) {
        Map<CompareTarget, SceneException> undrawable = new LinkedHashMap<>();
        for (Match match : matches) {
            CompareTarget target = match.target();
            if (target != null && !drawn.containsKey(target) && !undrawable.containsKey(target)) {
                try {
                    drawn.put(target, own.of(target));
                } catch (SceneException e) {
                    undrawable.put(target, e);
                }
            }
        }
        // page2.png holding a first-assignment page is compared as that (compareRead), never with page 2: that
        // page not drawn (simpview's own scenes not found) stops nothing when every picture so named holds one
        undrawable.keySet().removeIf(target -> target.isPage() && target.page() <= Assignment1.COUNT
                && allHoldFirstAssignmentPages(pictures, matches, target));
        return undrawable;
    }

    /** Whether every picture matched to {@code target} holds a first-assignment page (four framed panels). */
    private boolean allHoldFirstAssignmentPages(List<Path> pictures, List<Match> matches, CompareTarget target) {
        for (int i = 0; i < pictures.size(); i++) {
            if (target.equals(matches.get(i).target())
                    && !PanelGridComparison.holds(pictures.get(i), FirstAssignmentGrading.panels())) {
                return false;
            }
        }
        return true;
    }

    /**
     * Why the batch stopped before comparing anything: the pages or scenes simpview cannot draw, each with its
     * scene error (file:line:column), and the option that names their files. Grading on would score every
     * picture of them 0 for the teacher's setup, not for what the student drew.
     */
    private String stopped(Map<CompareTarget, SceneException> undrawable, Path dir) {
        List<CompareTarget> targets = undrawable.keySet().stream().sorted(MENTIONED_IN_ORDER).toList();
        List<String> names = targets.stream().map(CompareBatch::named).toList();
        String all = UsageWords.joined(names, "and");
        StringBuilder text = new StringBuilder(says + "nothing was graded: simpview cannot draw " + all
                + " itself, so every picture of " + (names.size() == 1 ? "it" : "them")
                + " would score 0 whatever it shows:\n");
        targets.forEach(target -> text.append("  ").append(named(target)).append(": ")
                .append(undrawable.get(target).getMessage().replace("\n", "\n  ")).append('\n'));
        Set<String> fixes = new LinkedHashSet<>();
        targets.forEach(target -> fixes.add(fixFor(target, dir)));
        fixes.forEach(fix -> text.append(fix).append('\n'));
        return text.append("No picture was compared and no result file written.\n").toString();
    }

    /** "page 6" or "pageC.simp", as the messages name a page or scene. */
    private static String named(CompareTarget target) {
        return target.isPage() ? "page " + target.page() : target.scene().getFileName().toString();
    }

    /** What to change so that simpview can draw {@code target}: the option (or folder) that names its file. */
    private String fixFor(CompareTarget target, Path dir) {
        PageContext context = own.context();
        if (target.isPage() && Assignment2.page(target.page()) instanceof ScenePage page && page.isCourses()) {
            Path folder = context.simpDir().toAbsolutePath().normalize();
            return context.simpDir().equals(context.ownSimpDir())
                    ? "Name the folder of the course's page6.simp to page8.simp with --simp-dir DIR: without it they "
                            + "are looked for in simpview's own scene folder, " + folder + "."
                    : "--simp-dir names the folder of the course's page6.simp to page8.simp, here " + folder
                            + ": correct the file, or name the right folder.";
        }
        if (target.isPage()) {
            return "Pages 4 and 5 are simpview's own scenes, in " + context.ownSimpDir().toAbsolutePath().normalize()
                    + ": that installation of simpview is incomplete.";
        }
        if (target.scene().toAbsolutePath().normalize().startsWith(dir.toAbsolutePath().normalize())) {
            return "It is a scene of the folder checked (a picture named like it is compared with it): correct it, "
                    + "or name the course's scenes with --scene.";
        }
        return "--scene names it: correct it, or name the right scene or folder with --scene.";
    }

    /**
     * Each target's accepted alternates from its rule's folder: a picture there that
     * names a page or scene (as submissions do) is for that one only; one that names
     * none is for every target of the rule. An unreadable alternate is said and left out.
     */
    private Map<CompareTarget, List<Alternates.Accepted>> alternatesOf(Iterable<CompareTarget> targets,
            Function<String, Optional<String>> namer) {
        Map<CompareTarget, List<Alternates.Accepted>> all = new HashMap<>();
        Map<Path, Object> read = new HashMap<>();
        for (CompareTarget target : targets) {
            all.put(target, Alternates.of(target.ruleIn(rubric), target.key(), namer, read, err, says));
        }
        return all;
    }

    /**
     * Says so when every picture is a page of the first assignment but the eight pages were asked for by --pages:
     * the teacher meant --assignment 1, and each of the eight pages is missing or scored 0.
     */
    private void noteIfFirstAssignmentOnly(List<CompareTarget> wanted, List<BatchRow> rows) {
        if (!pagesIfHandedIn && wanted.stream().anyMatch(CompareTarget::isPage)
                && pagesAskedFor.firstAssignmentOnly(rows)) {
            err.println(says + "note: every picture is a page of the first assignment, but --pages names the eight "
                    + "pages: none was graded as a page of the first assignment, and each of the eight pages asked for "
                    + "is missing or scored 0. To grade the first assignment, give --assignment 1: its --pages are its "
                    + "pages 1 to 5 (default: 1-5).");
        }
    }

    /**
     * Writes and prints the results of the pictures {@code found} in {@code dir}, compared as {@code matches} says,
     * against what each submission was {@code asked} for ({@link BatchResults#write}), and returns its exit code: of
     * several pictures of one page, the one named for it and nothing else counts; a picture of the scene every picture
     * is compared with is a submission of its own.
     */
    private int writeResults(Path dir, HandedIn.Found found, List<Match> matches, List<BatchRow> rows,
            List<Wanted> asked, Outputs outputs, double seconds, boolean oneStudent) {
        List<Path> pictures = found.pictures();
        Set<String> plainlyNamed = picturesWhere(dir, pictures, matches, CompareBatch::namesItsPageOnly);
        Set<String> alone = picturesWhere(dir, pictures, matches, (relative, match) -> match.alone());
        String instead = found.withoutPictures().stream().filter(w -> w.submission().isEmpty())
                .map(WithoutPictures::instead).findFirst().orElse("");
        return results.write(dir, rows, asked, outputs, seconds, plainlyNamed::contains, alone::contains, instead,
                oneStudent);
    }

    /** The pictures (by their paths under {@code dir}) whose path and match pass {@code test}. */
    private Set<String> picturesWhere(Path dir, List<Path> pictures, List<Match> matches,
            BiPredicate<String, Match> test) {
        Set<String> passing = new HashSet<>();
        for (int i = 0; i < pictures.size(); i++) {
            String relative = handedIn.name(dir, pictures.get(i));
            if (test.test(relative, matches.get(i))) {
                passing.add(relative);
            }
        }
        return passing;
    }

    /**
     * Whether a picture's file name is the name of the page or scene it was matched to and nothing else
     * (page3.png, pageC.png, a1-page2.png): of several pictures of one page, that one counts.
     */
    private static boolean namesItsPageOnly(String relative, Match match) {
        String name = HandedIn.fileName(relative);
        int firstAssignmentPage = match.firstAssignmentPage();
        if (firstAssignmentPage > 0) {
            return SubmissionNames.isFirstAssignmentPageName(name, firstAssignmentPage)
                    || SubmissionNames.isPageName(name, firstAssignmentPage); // a1/page2.png
        }
        CompareTarget target = match.target();
        if (target == null) {
            return false;
        }
        return target.isPage() ? SubmissionNames.isPageName(name, target.page())
                : SubmissionNames.isSceneName(name, target.key());
    }

    /** The scenes of a folder by their names (pageC of pageC.simp), in order; none when it cannot be read. */
    static Map<String, Path> scenesIn(Path folder) {
        try {
            return scenesOf(folder);
        } catch (IllegalArgumentException e) {
            return new TreeMap<>(); // an unreadable folder has no scenes; --scene's folder is told why (scenes)
        }
    }

    /**
     * The scenes of a folder by their names, in order.
     *
     * @throws IllegalArgumentException saying why, when the folder cannot be read
     */
    private static Map<String, Path> scenesOf(Path folder) {
        Map<String, Path> scenes = new TreeMap<>();
        SceneList.folder(folder).forEach(f -> scenes.put(SubmissionNames.stem(f.getFileName().toString()), f));
        return scenes;
    }
}
